// Ribbon meshes: laid out stroke by stroke, bit-identical for a seed at any
// thread count, and every vertex above the surface it lies on by no more than
// max_lift.
#include "core/base/parallel.h"
#include "core/npr/strokes/stroke_mesh.h"
#include "core/npr/strokes/stroke_placement.h"
#include "npr/strokes/stroke_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace inkray {
namespace {

using namespace inkray::testing;

bool same_mesh(const TriangleMesh& a, const TriangleMesh& b) {
  return a.positions == b.positions && a.normals == b.normals && a.uvs == b.uvs && a.colors == b.colors &&
         a.indices == b.indices;
}

bool same_alpha(const StrokeGeometry& a, const StrokeGeometry& b) {
  if (a.alpha.size() != b.alpha.size() || a.first_vertex != b.first_vertex) return false;
  for (size_t t = 0; t < a.alpha.size(); ++t)
    if (std::memcmp(&a.alpha[t], &b.alpha[t], sizeof(AlphaTriangle)) != 0) return false;
  return true;
}

// Ribbons keep only the stations and columns they need to follow the surface
// (stroke_mesh.h), so a stroke's vertex count varies: each stroke owns a
// contiguous range of rows of 2, 3 or 5 vertices, and its triangles pair up
// into cells of that range.
TEST(StrokeMesh, EachStrokeOwnsRowsOfVerticesAndPairedTriangles) {
  const StrokeSurface surface = surface_of(testing::test_sphere());
  StrokeEmitterDesc e = test_emitter(300);
  e.segments = 5;
  const StrokeGeometry g = build_test_strokes(surface, e);
  ASSERT_EQ(g.first_vertex.size(), 301u);
  EXPECT_EQ(g.first_vertex.back(), g.mesh.vertex_count());
  EXPECT_EQ(g.mesh.uvs.size(), g.mesh.vertex_count());
  EXPECT_EQ(g.mesh.colors.size(), g.mesh.vertex_count());
  EXPECT_EQ(g.mesh.normals.size(), g.mesh.vertex_count());
  EXPECT_EQ(g.alpha.size(), g.mesh.triangle_count());
  EXPECT_EQ(g.mesh.triangle_count() % 2, 0u);
  size_t stroke = 0;
  for (size_t t = 0; t < g.mesh.triangle_count(); ++t) {
    const uint32_t* idx = &g.mesh.indices[3 * t];
    while (g.first_vertex[stroke + 1] <= idx[0]) ++stroke;
    for (int k = 0; k < 3; ++k) {
      ASSERT_GE(idx[k], g.first_vertex[stroke]) << t;
      ASSERT_LT(idx[k], g.first_vertex[stroke + 1]) << t;
    }
  }
  for (size_t i = 0; i < 300; ++i) {
    const uint32_t n = g.first_vertex[i + 1] - g.first_vertex[i];
    // At least two rows; at most segments + 1 rows of kMaxColumns + 1.
    EXPECT_TRUE(n % 2 == 0 || n % 3 == 0 || n % 5 == 0) << n;
    EXPECT_GE(n, 4u);
    EXPECT_LE(n, 6u * (kMaxColumns + 1));
  }
}

TEST(StrokeMesh, SameSeedGivesBitIdenticalMeshAtAnyThreadCount) {
  const StrokeSurface sphere = surface_of(testing::test_sphere());
  const StrokeSurface box = surface_of(testing::test_box());
  // Enough strokes for several parallel blocks (placement, growth and meshing).
  const StrokeEmitterDesc e = test_emitter(5000, 21);
  // Placement and meshing run in the caller's arena: a budget's run() caps their threads.
  const auto build_on = [&](const StrokeSurface& s, const StrokeEmitterDesc& d, int threads) {
    return ThreadBudget(threads).run([&] { return build_test_strokes(s, d); });
  };
  for (const StrokeSurface* surface : {&sphere, &box}) {
    const StrokeGeometry one = build_on(*surface, e, 1), two = build_on(*surface, e, 2),
                         four = build_on(*surface, e, 4);
    EXPECT_TRUE(same_mesh(one.mesh, two.mesh));
    EXPECT_TRUE(same_mesh(one.mesh, four.mesh));
    EXPECT_TRUE(same_alpha(one, two));
    EXPECT_TRUE(same_alpha(one, four));
    EXPECT_EQ(one.max_lift, four.max_lift);
  }
  EXPECT_FALSE(same_mesh(build_test_strokes(sphere, test_emitter(800, 3)).mesh,
                         build_test_strokes(sphere, test_emitter(800, 4)).mesh));
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
  const StrokeGeometry g = build_test_strokes(surface_of(s), e);
  ASSERT_GT(g.offset, 0.f);
  for (size_t v = 0; v < g.mesh.vertex_count(); ++v) {
    const double height =
        glm::length(glm::dvec3(g.mesh.positions[v]) - glm::dvec3(center)) - double(s.radius);
    ASSERT_GT(height, 0.0) << v;
    ASSERT_LE(height, double(g.max_lift) * 1.001) << v;
  }
  // Every triangle's centroid too: the lift covers the chords, not just the vertices.
  const auto& m = g.mesh;
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const glm::dvec3 c =
        (glm::dvec3(m.positions[m.indices[3 * t]]) + glm::dvec3(m.positions[m.indices[3 * t + 1]]) +
         glm::dvec3(m.positions[m.indices[3 * t + 2]])) /
        3.0;
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
  const StrokeGeometry g = build_test_strokes(surface_of(testing::test_box()), e);
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
  const StrokeGeometry g = build_test_strokes(surface_of(testing::test_sphere()), e);
  for (size_t i = 0; i < 50; ++i) {
    const uint32_t first = g.first_vertex[i], n = g.first_vertex[i + 1] - first;
    // The row width is where v first changes.
    uint32_t per = 1;
    while (per < n && g.mesh.uvs[first + per].y == g.mesh.uvs[first].y) ++per;
    ASSERT_EQ(n % per, 0u);
    // A whole stroke on a sphere: v from 0 at the tail to 1 at the tip, rising;
    // u from 0 to 1 across every row in equal steps.
    EXPECT_EQ(g.mesh.uvs[first].y, 0.f);
    EXPECT_EQ(g.mesh.uvs[first + n - 1].y, 1.f);
    for (uint32_t k = 0; k < n; ++k) {
      const Vec2 uv = g.mesh.uvs[first + k];
      EXPECT_FLOAT_EQ(uv.x, float(k % per) / float(per - 1));
      if (k >= per) {
        EXPECT_GT(uv.y, g.mesh.uvs[first + k - per].y);
      }
    }
  }
}

}  // namespace
}  // namespace inkray
