// Robust intersection: a ray spawned from a hit never re-hits the surface it
// leaves, rays from inside closed shapes never escape (pbrt-v4 style tests).
#include "core/geometry/embree_scene.h"
#include "core/math/hash.h"
#include "core/sampling/warp.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inkray {
namespace {

float log_uniform(Pcg32& rng, float lo, float hi) {
  return std::exp(std::log(lo) + rng.next_float() * (std::log(hi) - std::log(lo)));
}
Vec3 random_dir(Pcg32& rng) { return sample_uniform_sphere({rng.next_float(), rng.next_float()}); }
Vec3 random_in_hemisphere(Pcg32& rng, const Vec3& n) {
  Vec3 d = random_dir(rng);
  return glm::dot(d, n) < 0.f ? -d : d;
}

// Shoots a ray at the shape from outside, then checks the spawned rays.
struct ReintersectionStats {
  int hits = 0;
  int rehits = 0;
  int escapes = 0;
};

void check_spawned_rays(const EmbreeScene& scene, const Ray& ray, bool closed, ReintersectionStats* st,
                        Pcg32& rng) {
  Hit hit;
  if (!scene.intersect(ray, kInfinity, &hit)) return;
  ++st->hits;
  const SurfaceInteraction si = scene.interaction(ray, hit);
  // Leaving on the outside (the side the normal faces for closed shapes; any side for open ones).
  const Vec3 out = random_in_hemisphere(rng, si.ng);
  Hit again;
  if (scene.intersect(spawn_ray(si.p, si.p_error, si.ng, out), kInfinity, &again)) ++st->rehits;
  const Vec3 in = -random_in_hemisphere(rng, si.ng);
  const bool hit_inside = scene.intersect(spawn_ray(si.p, si.p_error, si.ng, in), kInfinity, &again);
  if (closed && !hit_inside) ++st->escapes;
  if (!closed && hit_inside) ++st->rehits;
}

Ray ray_towards(Pcg32& rng, const Point3& target, float distance) {
  const Point3 o = target + random_dir(rng) * distance;
  return {o, glm::normalize(target - o)};
}

// `trials` scenes of one shape each, from `place` (seeded `seed`): it adds the shape to
// the scene and returns a ray shot at it from outside; the spawned rays of every hit checked.
template <class Place>
ReintersectionStats spawn_trials(uint64_t seed, int trials, bool closed, Place place) {
  Pcg32 rng(seed);
  ReintersectionStats st;
  for (int i = 0; i < trials; ++i) {
    EmbreeScene scene;
    const Ray ray = place(rng, scene, i);
    check_spawned_rays(scene, ray, closed, &st, rng);
  }
  return st;
}

TEST(GeometryReintersection, RandomSpheres) {
  const ReintersectionStats st = spawn_trials(1, 2000, true, [](Pcg32& rng, EmbreeScene& scene, int) {
    const float radius = log_uniform(rng, 1e-4f, 1e5f);
    // Positions up to 1e4 radii from the origin: beyond that a float cannot
    // place a ray near the sphere, let alone inside it.
    const Point3 center = random_dir(rng) * std::min(log_uniform(rng, 1e-4f, 1e5f), 1e4f * radius);
    scene.add(Sphere{center, radius, Transform{}});
    scene.commit();
    const Point3 target = center + random_dir(rng) * radius * 0.99f;
    return ray_towards(rng, target, radius * log_uniform(rng, 1.1f, 100.f));
  });
  EXPECT_GT(st.hits, 1900);
  EXPECT_EQ(st.rehits, 0);
  EXPECT_EQ(st.escapes, 0);
}

TEST(GeometryReintersection, RandomTransformedSpheres) {
  const ReintersectionStats st = spawn_trials(2, 1000, true, [](Pcg32& rng, EmbreeScene& scene, int) {
    const float s = log_uniform(rng, 1e-3f, 1e3f);
    const Transform t =
        Transform::translate(random_dir(rng) * std::min(log_uniform(rng, 1e-3f, 1e4f), 1e4f * s)) *
        Transform::rotate(360.f * rng.next_float(), random_dir(rng)) *
        Transform::scale(Vec3(s, s * (0.5f + rng.next_float()), s * (0.5f + rng.next_float())));
    scene.add(Sphere{Point3(0.f), 1.f, t});
    scene.commit();
    const Point3 target = t.point(random_dir(rng) * 0.5f);
    return ray_towards(rng, target, s * 50.f);
  });
  EXPECT_GT(st.hits, 950);
  EXPECT_EQ(st.rehits, 0);
  EXPECT_EQ(st.escapes, 0);
}

TEST(GeometryReintersection, RandomTrianglesAndQuads) {
  const ReintersectionStats st = spawn_trials(3, 4000, false, [](Pcg32& rng, EmbreeScene& scene, int i) {
    const float size = log_uniform(rng, 1e-4f, 1e5f);
    const Point3 base = random_dir(rng) * std::min(log_uniform(rng, 1e-4f, 1e5f), 1e4f * size);
    const Vec3 e0 = random_dir(rng) * size, e1 = random_dir(rng) * size;
    if (i % 2) {
      scene.add(make_quad(base, e0, e1, Transform{}));
    } else {
      scene.add(make_mesh({base, base + e0, base + e1}, {}, {}, {0, 1, 2}, Transform{}));
    }
    scene.commit();
    const float b0 = rng.next_float() * 0.5f, b1 = rng.next_float() * 0.5f;
    const Point3 target = base + b0 * e0 + b1 * e1;
    return ray_towards(rng, target, size * log_uniform(rng, 0.1f, 100.f));
  });
  EXPECT_GT(st.hits, 3500);
  EXPECT_EQ(st.rehits, 0);
}

// Embree's own watertightness test: a tessellated sphere far from the origin.
TEST(GeometryReintersection, FarTessellatedSphereKeepsRaysInside) {
  const Point3 center(148376.f, 1234.f, -223423.f);
  EmbreeScene scene;
  scene.add(make_uv_sphere(center, 2.f, 64, 128, Transform{}));
  scene.commit();
  Pcg32 rng(4);
  int escapes = 0, rehits = 0, misses = 0;
  for (int i = 0; i < 20000; ++i) {
    Ray ray{center, random_dir(rng)};
    Hit hit;
    if (!scene.intersect(ray, kInfinity, &hit)) {
      ++misses;
      continue;
    }
    SurfaceInteraction si = scene.interaction(ray, hit);
    // Bounce around inside a few times: every inward ray must hit the shell again.
    for (int bounce = 0; bounce < 4; ++bounce) {
      const Vec3 in = -random_in_hemisphere(rng, si.ng);
      ray = spawn_ray(si.p, si.p_error, si.ng, in);
      if (!scene.intersect(ray, kInfinity, &hit)) {
        ++escapes;
        break;
      }
      si = scene.interaction(ray, hit);
    }
    Hit out_hit;
    if (scene.intersect(spawn_ray(si.p, si.p_error, si.ng, random_in_hemisphere(rng, si.ng)), kInfinity,
                        &out_hit))
      ++rehits;
  }
  EXPECT_EQ(misses, 0);
  EXPECT_EQ(escapes, 0);
  EXPECT_EQ(rehits, 0);
}

// Rays aimed exactly at the vertices and edge midpoints of a closed mesh.
TEST(GeometryReintersection, ClosedMeshHasNoCracksAtEdges) {
  const TriangleMesh mesh = make_uv_sphere(Point3(3.f, -2.f, 5.f), 1.5f, 12, 24, Transform{});
  std::vector<Point3> targets;
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Point3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                 c = mesh.positions[mesh.indices[3 * t + 2]];
    targets.insert(targets.end(), {a, b, c, 0.5f * (a + b), 0.5f * (b + c), 0.5f * (c + a)});
  }
  EmbreeScene scene;
  scene.add(make_mesh({mesh.positions.begin(), mesh.positions.end() - 1}, mesh.normals, mesh.uvs,
                      mesh.indices, Transform{}));
  scene.commit();
  int escapes = 0;
  for (const Point3& target : targets) {
    for (const Point3& origin : {Point3(3.f, -2.f, 5.f), Point3(3.3f, -1.9f, 5.2f)}) {
      Hit hit;
      if (!scene.intersect({origin, target - origin}, kInfinity, &hit)) ++escapes;
    }
  }
  EXPECT_EQ(escapes, 0) << "of " << 2 * targets.size() << " rays";
}

// A radius-1000 ground sphere seen from just above it at grazing angles.
TEST(GeometryReintersection, GrazingRaysOnLargeSphere) {
  EmbreeScene scene;
  const Point3 center(0.f, -1000.f, 0.f);
  scene.add(Sphere{center, 1000.f, Transform{}});
  scene.commit();
  const Point3 eye(0.f, 1.f, 0.f);
  int hits = 0, rehits = 0, bad_distance = 0;
  for (int i = 0; i < 20000; ++i) {
    // The horizon lies acos(1000/1001) = 2.5623 degrees below horizontal; rays
    // from just below it (extremely grazing) to 5.5 degrees down.
    const float elevation = glm::radians(-2.5626f - 3.f * float(i) / 20000.f);
    const float azimuth = 0.7f * float(i);
    const Vec3 d(std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                 std::cos(elevation) * std::sin(azimuth));
    Hit hit;
    if (!scene.intersect({eye, d}, kInfinity, &hit)) continue;
    ++hits;
    // Distance against a double-precision reference.
    const glm::dvec3 f = glm::dvec3(eye - center), dd = glm::normalize(glm::dvec3(d));
    const double b = glm::dot(f, dd), c = glm::dot(f, f) - 1e6;
    const double t_ref = -b - std::sqrt(b * b - c);
    if (std::abs(hit.t - t_ref) > 1e-4 * t_ref + 1e-3) ++bad_distance;
    const SurfaceInteraction si = scene.interaction({eye, d}, hit);
    const Vec3 reflected = glm::reflect(d, si.ng);
    Hit again;
    if (scene.intersect(spawn_ray(si.p, si.p_error, si.ng, reflected), kInfinity, &again)) ++rehits;
  }
  EXPECT_EQ(hits, 20000);
  EXPECT_EQ(bad_distance, 0);
  EXPECT_EQ(rehits, 0);
}

}  // namespace
}  // namespace inkray

namespace inkray {
namespace {

// A mesh built in object space and placed by an instance transform (how compiled
// scenes place meshes): Embree intersects in object space, the hit point comes
// from the world-space vertices, and spawned rays must still neither re-hit the
// surface nor escape the closed mesh, at scales far from 1.
TEST(GeometryReintersection, InstancedClosedMeshesUnderRandomTransforms) {
  Pcg32 rng(7);
  ReintersectionStats st;
  const TriangleMesh object = make_uv_sphere(Point3(0.f), 1.f, 16, 32, Transform{});
  auto shape = std::make_shared<const Shape>(object);
  const auto bvh = std::make_shared<const ShapeBvh>(shape);
  for (int i = 0; i < 200; ++i) {
    const float scale = log_uniform(rng, 1e-3f, 1e4f);
    const Vec3 stretch(scale * (0.5f + rng.next_float()), scale * (0.5f + rng.next_float()), scale);
    const Transform to_world = Transform::translate(random_dir(rng) * log_uniform(rng, 1e-3f, 1e2f) * scale) *
                               Transform::rotate(360.f * rng.next_float(), random_dir(rng)) *
                               Transform::scale(stretch);
    EmbreeScene scene;
    scene.add(bvh, to_world, std::make_shared<const Shape>(transformed(object, to_world)));
    scene.commit();
    const Point3 center = to_world.point(Point3(0.f));
    for (int r = 0; r < 20; ++r)
      check_spawned_rays(scene, ray_towards(rng, center, 10.f * scale * 3.f), true, &st, rng);
  }
  EXPECT_GT(st.hits, 3000);
  EXPECT_EQ(st.rehits, 0);
  EXPECT_EQ(st.escapes, 0);
}

}  // namespace
}  // namespace inkray
