// Moving instances (EmbreeScene::add_moving): a shape placed at the shutter's
// opening and closing is hit where it stands at each ray's instant, its hit point,
// normal and uv computed there, and a turning shape keeps its size in between.
#include "core/geometry/embree_scene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inkray {
namespace {

// The motion under test: across the shutter the shape slides from x = -2 to x = 2
// while turning a quarter turn about y. Interpolating the rotation (not the matrix)
// gives the angle 90 t at time t.
Transform expected_placement(float t) {
  return Transform::translate(Vec3(glm::mix(-2.f, 2.f, t), 0.f, 0.f)) *
         Transform::rotate(90.f * t, Vec3(0.f, 1.f, 0.f));
}

std::shared_ptr<const ShapeBvh> unit_box() {
  return std::make_shared<const ShapeBvh>(
      std::make_shared<const Shape>(make_box(Point3(-0.5f), Point3(0.5f), Transform{})));
}

// The unit box moving as expected_placement says, alone in a committed scene.
struct MovingBox {
  EmbreeScene scene;
  uint32_t id = 0;
  MovingBox() {
    const auto box = unit_box();
    id =
        scene.add_moving(box, expected_placement(0.f), expected_placement(1.f), nullptr, box->shared_shape());
    scene.commit();
  }
};

TEST(MovingInstance, PlacementInterpolatesTranslationAndRotation) {
  const MovingBox moving;
  const EmbreeScene& scene = moving.scene;
  const uint32_t id = moving.id;
  EXPECT_TRUE(scene.moving(id));
  EXPECT_TRUE(scene.any_moving());
  for (const float t : {0.f, 0.2f, 0.5f, 0.8f, 1.f}) {
    const Transform at = scene.placement(id, t);
    const Transform want = expected_placement(t);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 3; ++r)
        EXPECT_NEAR(at.m[c][r], want.m[c][r], 2e-5f) << "t " << t << " m[" << c << "][" << r << "]";
  }
  // The bounds hold the box over the whole shutter.
  Point3 lo, hi;
  scene.bounds(&lo, &hi);
  EXPECT_LE(lo.x, -2.5f);
  EXPECT_GE(hi.x, 2.5f);
}

// Rays straight down -z through a grid of points, at several instants: where the
// box stands at the ray's instant decides hit or miss, and the hit lies on its surface
// there with the normal of the face it is on.
TEST(MovingInstance, HitsLieOnTheSurfaceWhereItStandsAtTheRaysInstant) {
  const MovingBox moving;
  const EmbreeScene& scene = moving.scene;
  const uint32_t id = moving.id;
  int hits = 0;
  for (const float t : {0.f, 0.3f, 0.5f, 0.7f, 1.f}) {
    const Transform at = expected_placement(t);
    for (float x = -2.99f; x <= 3.f; x += 0.0625f) {
      for (const float y : {-0.3f, 0.f, 0.45f}) {
        const Ray ray{Point3(x, y, 5.f), Vec3(0.f, 0.f, -1.f), t};
        // The box's top and bottom are horizontal at every instant, so the ray meets
        // it where its outline at height y covers x: found in the box's own space.
        const Point3 o = Point3(at.inv * glm::vec4(ray.o, 1.f));
        const Vec3 d = Vec3(at.inv * glm::vec4(ray.d, 0.f));
        float t0 = -kInfinity, t1 = kInfinity;
        for (int a : {0, 2}) {
          if (std::abs(d[a]) < 1e-6f) {  // along the slab: inside it or not at all
            if (std::abs(o[a]) > 0.5f) t0 = kInfinity;
            continue;
          }
          const float near = (-0.5f - o[a]) / d[a], far = (0.5f - o[a]) / d[a];
          t0 = std::max(t0, std::min(near, far));
          t1 = std::min(t1, std::max(near, far));
        }
        const bool inside = t1 - t0 > 1e-3f;  // clear of the grazing edges
        const bool outside = t0 - t1 > 1e-3f;
        Hit hit;
        const bool found = scene.intersect(ray, kInfinity, &hit);
        if (inside) {
          ASSERT_TRUE(found) << "t " << t << " x " << x << " y " << y;
        }
        if (outside) {
          ASSERT_FALSE(found) << "t " << t << " x " << x << " y " << y;
        }
        if (!found) continue;
        ++hits;
        ASSERT_EQ(hit.geometry, id);
        const SurfaceInteraction si = scene.interaction(ray, hit);
        EXPECT_EQ(si.time, t);
        EXPECT_NEAR(hit.t, t0, 1e-4f);
        const Point3 local = Point3(at.inv * glm::vec4(si.p, 1.f));
        EXPECT_NEAR(std::max({std::abs(local.x), std::abs(local.z)}), 0.5f, 1e-4f) << "t " << t << " x " << x;
        EXPECT_LE(std::abs(local.y), 0.5f + 1e-4f);
        // The normal of the face the hit is on, turned with the box.
        const Vec3 face = std::abs(local.x) > std::abs(local.z) ? Vec3(std::copysign(1.f, local.x), 0.f, 0.f)
                                                                : Vec3(0.f, 0.f, std::copysign(1.f, local.z));
        EXPECT_GT(glm::dot(si.ng, glm::normalize(at.normal(face))), 0.9999f) << "t " << t << " x " << x;
      }
    }
  }
  EXPECT_GT(hits, 100);
}

// Halfway through its quarter turn the box stands at 45 degrees: a ray through a
// point its corner reaches then (0.68 from its centre, beyond the half-width 0.5 of
// the box square on, within the half-diagonal 0.707) hits it. Interpolating the
// matrices instead would shrink the box there by cos 45 and miss.
TEST(MovingInstance, ATurningShapeKeepsItsSize) {
  const MovingBox moving;
  const EmbreeScene& scene = moving.scene;
  Hit hit;
  EXPECT_TRUE(scene.intersect(Ray{Point3(0.68f, 0.f, 5.f), Vec3(0.f, 0.f, -1.f), 0.5f}, kInfinity, &hit));
  EXPECT_TRUE(scene.intersect(Ray{Point3(-0.68f, 0.f, 5.f), Vec3(0.f, 0.f, -1.f), 0.5f}, kInfinity, &hit));
  EXPECT_FALSE(scene.intersect(Ray{Point3(0.72f, 0.f, 5.f), Vec3(0.f, 0.f, -1.f), 0.5f}, kInfinity, &hit));
}

// An analytic sphere moving along x: its hits lie on the sphere about where its
// centre is at the ray's instant, with the outward normal there.
TEST(MovingInstance, MovingSphereIsHitWhereItIs) {
  EmbreeScene scene;
  const auto sphere =
      std::make_shared<const ShapeBvh>(std::make_shared<const Shape>(Sphere{Point3(0.f), 0.75f, {}}));
  const Transform open = Transform::translate(Vec3(-1.f, 0.f, 0.f)),
                  close = Transform::translate(Vec3(3.f, 0.f, 0.f));
  scene.add_moving(sphere, open, close, nullptr, sphere->shared_shape());
  scene.commit();
  for (const float t : {0.f, 0.25f, 0.5f, 1.f}) {
    const Point3 centre(glm::mix(-1.f, 3.f, t), 0.f, 0.f);
    for (float dx = -0.7f; dx <= 0.7f; dx += 0.1f) {
      const Ray ray{Point3(centre.x + dx, 0.2f, 4.f), Vec3(0.f, 0.f, -1.f), t};
      Hit hit;
      ASSERT_TRUE(scene.intersect(ray, kInfinity, &hit)) << "t " << t << " dx " << dx;
      const SurfaceInteraction si = scene.interaction(ray, hit);
      EXPECT_NEAR(glm::length(si.p - centre), 0.75f, 1e-4f);
      EXPECT_GT(glm::dot(si.ng, glm::normalize(si.p - centre)), 0.9999f);
      EXPECT_NEAR(si.p.z, std::sqrt(0.75f * 0.75f - dx * dx - 0.04f), 1e-3f);
    }
    Hit hit;
    EXPECT_FALSE(
        scene.intersect(Ray{Point3(centre.x + 0.8f, 0.f, 4.f), Vec3(0.f, 0.f, -1.f), t}, kInfinity, &hit));
  }
}

// What does not move keeps one time step: rays at any instant find it alike.
TEST(MovingInstance, StillShapesIgnoreTheRaysInstant) {
  EmbreeScene scene;
  const auto box = unit_box();
  scene.add(box, Transform::translate(Vec3(1.f, 0.f, 0.f)),
            std::make_shared<const Shape>(transformed(std::get<TriangleMesh>(box->shape()),
                                                      Transform::translate(Vec3(1.f, 0.f, 0.f)))));
  scene.commit();
  EXPECT_FALSE(scene.any_moving());
  Hit a, b;
  ASSERT_TRUE(scene.intersect(Ray{Point3(1.2f, 0.1f, 5.f), Vec3(0.f, 0.f, -1.f), 0.f}, kInfinity, &a));
  ASSERT_TRUE(scene.intersect(Ray{Point3(1.2f, 0.1f, 5.f), Vec3(0.f, 0.f, -1.f), 0.9f}, kInfinity, &b));
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.prim, b.prim);
  EXPECT_EQ(a.barycentric, b.barycentric);
}

}  // namespace
}  // namespace inkray
