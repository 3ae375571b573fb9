// Camera rays: the image centre looks at look_at, projection inverts ray
// generation, and thin-lens rays through one pixel meet on the focus plane.
#include "core/camera/camera.h"
#include "core/math/hash.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

CameraParams params() {
  CameraParams d;
  d.look_from = {1.f, 2.f, 3.f};
  d.look_at = {-2.f, 0.5f, -4.f};
  d.vfov = 50.f;
  return d;
}

TEST(Camera, CentreRayLooksAtTarget) {
  const Camera cam(params(), 200, 100);
  const Ray r = cam.generate_ray({100.f, 50.f}, {0.5f, 0.5f});
  const Vec3 expected = glm::normalize(params().look_at - params().look_from);
  EXPECT_NEAR(glm::dot(r.d, expected), 1.f, 1e-6f);
}

TEST(Camera, VerticalFieldOfViewSpansTheImageHeight) {
  const Camera cam(params(), 200, 100);
  const Ray top = cam.generate_ray({100.f, 0.f}, {0.5f, 0.5f});
  const Ray bottom = cam.generate_ray({100.f, 100.f}, {0.5f, 0.5f});
  EXPECT_NEAR(glm::degrees(std::acos(glm::dot(top.d, bottom.d))), 50.f, 1e-3f);
  // +y of the image is up in the world.
  EXPECT_GT(top.d.y, bottom.d.y);
}

TEST(Camera, ProjectInvertsGenerateRay) {
  const Camera cam(params(), 320, 240);
  Pcg32 rng(9);
  for (int i = 0; i < 100; ++i) {
    const Vec2 film(320.f * rng.next_float(), 240.f * rng.next_float());
    const Ray r = cam.generate_ray(film, {0.5f, 0.5f});
    Vec2 back;
    ASSERT_TRUE(cam.project(r.o + 7.f * r.d, &back));
    EXPECT_NEAR(back.x, film.x, 1e-2f);
    EXPECT_NEAR(back.y, film.y, 1e-2f);
  }
  Vec2 unused;
  EXPECT_FALSE(cam.project(params().look_from - (params().look_at - params().look_from), &unused));
}

TEST(Camera, ThinLensRaysMeetOnTheFocusPlane) {
  CameraParams d = params();
  d.aperture = 0.5f;
  d.focus_distance = 6.f;
  const Camera cam(d, 100, 100);
  const Vec3 forward = glm::normalize(d.look_at - d.look_from);
  Pcg32 rng(3);
  Point3 first(0.f);
  for (int i = 0; i < 50; ++i) {
    const Ray r = cam.generate_ray({30.f, 70.f}, {rng.next_float(), rng.next_float()});
    // Distance along the ray to the plane at focus_distance in front of the eye.
    const float t =
        glm::dot(d.look_from + forward * d.focus_distance - r.o, forward) / glm::dot(r.d, forward);
    const Point3 p = r.o + t * r.d;
    if (i == 0) first = p;
    EXPECT_LT(glm::length(p - first), 1e-4f);
    EXPECT_LE(glm::length(r.o - d.look_from), 0.25f + 1e-6f);
  }
}

}  // namespace
}  // namespace inkray
