// Stroke roots: exactly `count` of them, on the surface, area-weighted, evenly
// spaced (blue noise), and the same for the same seed.
#include "core/math/hash.h"
#include "core/npr/strokes/stroke_placement.h"
#include "npr/strokes/stroke_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace inkray {
namespace {

using testing::surface_of;

bool same_points(const std::vector<SurfacePoint>& a, const std::vector<SurfacePoint>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].p != b[i].p || a[i].n != b[i].n || a[i].uv != b[i].uv || a[i].prim != b[i].prim) return false;
  return true;
}

// Smallest distance between any two points (brute force: the tests use a few thousand).
double min_distance(const std::vector<Point3>& p) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = i + 1; j < p.size(); ++j) best = std::min(best, double(glm::length(p[i] - p[j])));
  return best;
}

std::vector<Point3> positions(const std::vector<SurfacePoint>& roots) {
  std::vector<Point3> p;
  for (const SurfacePoint& r : roots) p.push_back(r.p);
  return p;
}

TEST(StrokePlacement, CountIsExactlyTheRequestedCount) {
  const StrokeSurface sphere = surface_of(testing::test_sphere());
  const StrokeSurface box = surface_of(testing::test_box());
  for (size_t count : {size_t(0), size_t(1), size_t(7), size_t(500), size_t(3001)}) {
    EXPECT_EQ(place_roots(sphere, count, 3).size(), count);
    EXPECT_EQ(place_roots(box, count, 3).size(), count);
  }
}

TEST(StrokePlacement, SameSeedSameRootsOtherSeedOtherRoots) {
  const StrokeSurface sphere = surface_of(testing::test_sphere());
  const StrokeSurface box = surface_of(testing::test_box());
  EXPECT_TRUE(same_points(place_roots(sphere, 2000, 5), place_roots(sphere, 2000, 5)));
  EXPECT_TRUE(same_points(place_roots(box, 2000, 5), place_roots(box, 2000, 5)));
  EXPECT_FALSE(same_points(place_roots(sphere, 2000, 5), place_roots(sphere, 2000, 6)));
  EXPECT_FALSE(same_points(place_roots(box, 2000, 5), place_roots(box, 2000, 6)));
}

TEST(StrokePlacement, RootsLieOnTheSphere) {
  const Sphere s = testing::test_sphere();
  const Point3 center = s.to_world.point(s.center);
  for (const SurfacePoint& r : place_roots(surface_of(s), 5000, 9)) {
    EXPECT_NEAR(glm::length(r.p - center) / s.radius, 1.0, 1e-4);
    EXPECT_NEAR(glm::dot(r.n, glm::normalize(r.p - center)), 1.0, 1e-4);
  }
}

TEST(StrokePlacement, RootsLieOnTheirMeshTriangle) {
  const Shape ellipsoid =
      make_uv_sphere(Point3(1.f, 2.f, -1.f), 0.8f, 24, 48, Transform::scale({1.f, 0.6f, 1.3f}));
  const auto& mesh = std::get<TriangleMesh>(ellipsoid);
  const StrokeSurface surface = surface_of(ellipsoid);
  for (const SurfacePoint& r : place_roots(surface, 4000, 2)) {
    ASSERT_LT(r.prim, mesh.triangle_count());
    const Point3 a = mesh.positions[mesh.indices[3 * r.prim]],
                 b = mesh.positions[mesh.indices[3 * r.prim + 1]],
                 c = mesh.positions[mesh.indices[3 * r.prim + 2]];
    const Vec3 n = glm::normalize(glm::cross(b - a, c - a));
    const float size = std::max({glm::length(b - a), glm::length(c - a), glm::length(c - b)});
    EXPECT_NEAR(glm::dot(r.p - a, n), 0.f, 1e-5f * size);
    // Inside: the point is on the inner side of each edge (within rounding).
    const Point3 corners[3] = {a, b, c};
    for (int e = 0; e < 3; ++e) {
      const Vec3 edge = corners[(e + 1) % 3] - corners[e];
      EXPECT_GE(glm::dot(glm::cross(edge, r.p - corners[e]), n), -1e-5f * size * size);
    }
  }
}

TEST(StrokePlacement, RootsDoNotClump) {
  const StrokeSurface surface = surface_of(testing::test_sphere());
  const size_t count = 2000;
  PlacementStats stats;
  const std::vector<SurfacePoint> roots = place_roots(surface, count, 4, &stats);
  std::vector<SurfacePoint> random(count);
  for (uint32_t i = 0; i < count; ++i) random[i] = surface.sample(77, i);
  const double spacing = std::sqrt(surface.area() / double(count));
  const double blue = min_distance(positions(roots)), white = min_distance(positions(random));
  // Dart throwing keeps every pair at least the final radius apart, which stays
  // a good fraction of the mean spacing; uniform random points come far closer.
  EXPECT_GE(blue, 0.5 * spacing);
  EXPECT_GE(blue, double(stats.final_radius) * (1.0 - 1e-4));
  EXPECT_GT(blue, 10.0 * white);
}

TEST(StrokePlacement, EqualAreasGetEqualCounts) {
  // Slabs of equal height cut a sphere into equal areas (Archimedes).
  const Sphere s = testing::test_sphere();
  const Point3 center = s.to_world.point(s.center);
  const StrokeSurface surface = surface_of(s);
  constexpr int kSlabs = 8;
  constexpr int kSeeds = 8;
  const size_t count = 4000;
  const double expected = double(count) / kSlabs;
  double chi_square = 0.0;
  for (uint32_t seed = 1; seed <= kSeeds; ++seed) {
    int per_slab[kSlabs] = {};
    for (const SurfacePoint& r : place_roots(surface, count, seed)) {
      const float y = (r.p.y - center.y) / s.radius;  // in [-1, 1]
      ++per_slab[std::clamp(int((y + 1.f) * 0.5f * kSlabs), 0, kSlabs - 1)];
    }
    for (int slab = 0; slab < kSlabs; ++slab) {
      EXPECT_NEAR(per_slab[slab], expected, 0.1 * expected) << "seed " << seed << " slab " << slab;
      chi_square += (per_slab[slab] - expected) * (per_slab[slab] - expected) / expected;
    }
  }
  // Independent uniform points would give a mean chi-square of kSlabs - 1 = 7
  // per seed; evenly spread roots give far less.
  EXPECT_LT(chi_square / kSeeds, 3.5);
}

TEST(StrokePlacement, TrianglesGetCountsByArea) {
  // Two separate triangles, one with three times the other's area.
  std::vector<Point3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {8, 0, 0}, {5, 1, 0}};
  const Shape mesh = make_mesh(std::move(p), {}, {}, {0, 1, 2, 3, 4, 5}, Transform{});
  const size_t count = 2000;
  size_t small = 0;
  for (const SurfacePoint& r : place_roots(surface_of(mesh), count, 8)) small += r.prim == 0 ? 1 : 0;
  EXPECT_NEAR(double(small), 0.25 * double(count), 0.03 * double(count));
}

}  // namespace
}  // namespace inkray
