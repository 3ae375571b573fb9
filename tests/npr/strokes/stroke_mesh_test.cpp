// Ribbon meshes: the right size, bit-identical for a seed at any thread count,
// and every vertex above the surface it lies on by no more than max_lift.
#include "core/base/parallel.h"
#include "core/npr/strokes/stroke_mesh.h"
#include "core/npr/strokes/stroke_placement.h"
#include "npr/strokes/stroke_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inkray {
namespace {

using testing::surface_of;
using testing::test_emitter;

StrokeGeometry build(const StrokeSurface& surface, const StrokeEmitterDesc& e) {
  const auto roots = place_roots(surface, size_t(e.count), uint32_t(e.seed));
  const std::vector<Color> colors(roots.size(), Color(0.5f));
  return build_stroke_mesh(surface, roots, colors, e);
}

bool same_mesh(const TriangleMesh& a, const TriangleMesh& b) {
  return a.positions == b.positions && a.normals == b.normals && a.uvs == b.uvs && a.colors == b.colors &&
         a.indices == b.indices;
}

TEST(StrokeMesh, TwoVerticesPerStationTwoTrianglesPerSegment) {
  const StrokeSurface surface = surface_of(testing::test_sphere());
  StrokeEmitterDesc e = test_emitter(300);
  e.segments = 5;
  const StrokeGeometry g = build(surface, e);
  EXPECT_EQ(g.mesh.vertex_count(), 300u * 2u * 6u);
  EXPECT_EQ(g.mesh.triangle_count(), 300u * 2u * 5u);
  EXPECT_EQ(g.mesh.uvs.size(), g.mesh.vertex_count());
  EXPECT_EQ(g.mesh.colors.size(), g.mesh.vertex_count());
  for (uint32_t i : g.mesh.indices) ASSERT_LT(i, g.mesh.vertex_count());
}

TEST(StrokeMesh, SameSeedGivesBitIdenticalMeshAtAnyThreadCount) {
  const StrokeSurface sphere = surface_of(testing::test_sphere());
  const StrokeSurface box = surface_of(testing::test_box());
  // Enough strokes for several parallel chunks.
  const StrokeEmitterDesc e = test_emitter(5000, 21);
  // Placement and meshing run in the caller's arena: a budget's run() caps their threads.
  const auto build_on = [&](int threads) { return ThreadBudget(threads).run([&] { return build(sphere, e); }); };
  const StrokeGeometry one = build_on(1), two = build_on(2), four = build_on(4);
  EXPECT_TRUE(same_mesh(one.mesh, two.mesh));
  EXPECT_TRUE(same_mesh(one.mesh, four.mesh));
  EXPECT_EQ(one.max_lift, four.max_lift);
  EXPECT_TRUE(same_mesh(build(box, test_emitter(800, 3)).mesh, build(box, test_emitter(800, 3)).mesh));
  EXPECT_FALSE(same_mesh(build(sphere, test_emitter(800, 3)).mesh, build(sphere, test_emitter(800, 4)).mesh));
}

TEST(StrokeMesh, EveryVertexIsAboveTheSphereWithinMaxLift) {
  const Sphere s = testing::test_sphere();
  const Point3 center = s.to_world.point(s.center);
  // Long, wide strokes bend over the sphere: the chords between vertices dip most.
  StrokeEmitterDesc e = test_emitter(400, 6);
  e.width_min = 0.3f;
  e.width_max = 0.6f;
  e.length_min = 1.f;
  e.length_max = 2.f;
  e.segments = 4;
  const StrokeGeometry g = build(surface_of(s), e);
  ASSERT_GT(g.offset, 0.f);
  for (size_t v = 0; v < g.mesh.vertex_count(); ++v) {
    const double height = glm::length(glm::dvec3(g.mesh.positions[v]) - glm::dvec3(center)) - double(s.radius);
    ASSERT_GT(height, 0.0) << v;
    ASSERT_LE(height, double(g.max_lift) * 1.001) << v;
  }
  // Every triangle's centroid too: the lift covers the chords, not just the vertices.
  const auto& m = g.mesh;
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const glm::dvec3 c = (glm::dvec3(m.positions[m.indices[3 * t]]) + glm::dvec3(m.positions[m.indices[3 * t + 1]]) +
                          glm::dvec3(m.positions[m.indices[3 * t + 2]])) / 3.0;
    ASSERT_GT(glm::length(c - glm::dvec3(center)), double(s.radius)) << t;
  }
}

TEST(StrokeMesh, EveryVertexIsOutsideTheBoxWithinMaxLift) {
  // Strokes wrap around the box's sharp edges; the signed distance to a box is exact.
  const Point3 lo(-1.f, -0.5f, -0.75f), hi(1.f, 0.5f, 0.75f);
  const Point3 center = 0.5f * (lo + hi), half = 0.5f * (hi - lo);
  StrokeEmitterDesc e = test_emitter(1500, 8);
  e.width_min = 0.1f;
  e.width_max = 0.2f;
  e.length_min = 0.4f;
  e.length_max = 0.8f;
  const StrokeGeometry g = build(surface_of(testing::test_box()), e);
  for (size_t v = 0; v < g.mesh.vertex_count(); ++v) {
    const Vec3 q = glm::abs(g.mesh.positions[v] - center) - half;
    const float outside = glm::length(glm::max(q, Vec3(0.f)));
    const float inside = std::min(max_component(q), 0.f);
    const float distance = outside + inside;
    ASSERT_GT(distance, 0.f) << v;
    ASSERT_LE(distance, g.max_lift * 1.001f) << v;
  }
}

TEST(StrokeMesh, UvRunsAcrossAndAlongEachStroke) {
  StrokeEmitterDesc e = test_emitter(50);
  e.segments = 4;
  const StrokeGeometry g = build(surface_of(testing::test_sphere()), e);
  for (size_t v = 0; v < g.mesh.vertex_count(); ++v) {
    const size_t k = v % 10;  // vertex within its stroke
    EXPECT_EQ(g.mesh.uvs[v].x, float(k % 2));
    EXPECT_EQ(g.mesh.uvs[v].y, float(k / 2) / 4.f);
  }
}

}  // namespace
}  // namespace inkray
