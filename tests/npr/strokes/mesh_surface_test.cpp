// Mesh surfaces: projections past an open edge are marked as off the surface
// and keep the facet's normal; a closed mesh whose faces have vertices of
// their own (a box) has no such edge; past a flat-shaded edge the normal
// points out, whichever facet the closest point was found on.
#include "core/npr/strokes/mesh_surface.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

TEST(StrokeMeshSurface, PastAnOpenEdgeIsOffTheSurface) {
  const TriangleMesh sheet = make_quad(Point3(0.f), {2.f, 0.f, 0.f}, {0.f, 2.f, 0.f}, Transform{});
  const MeshSurface surface(sheet);
  const SurfacePoint inside = surface.project({1.f, 1.f, 0.1f});
  EXPECT_FALSE(inside.boundary);
  const SurfacePoint past = surface.project({2.3f, 1.f, 0.f});
  EXPECT_TRUE(past.boundary);
  EXPECT_NEAR(past.p.x, 2.f, 1e-6f);
  EXPECT_NEAR(std::abs(past.n.z), 1.f, 1e-6f) << "no sideways normal past the edge";
  EXPECT_TRUE(surface.project({-0.5f, -0.5f, 0.f}).boundary);  // past a corner
  EXPECT_FALSE(surface.project({2.f, 1.f, 0.f}).boundary);     // on the edge itself
}

TEST(StrokeMeshSurface, ABoxHasNoOpenEdgesAndRoundsItsEdgesOutward) {
  const TriangleMesh box = make_box(Point3(-1.f), Point3(1.f), Transform{});
  const MeshSurface surface(box);
  for (const Point3 p : {Point3(1.3f, 1.2f, 0.f), Point3(1.5f, 1.5f, 1.5f), Point3(0.f, -1.4f, 1.1f),
                         Point3(1.f, 1.3f, 0.2f), Point3(1.3f, 1.f, -0.4f)}) {
    const SurfacePoint sp = surface.project(p);
    EXPECT_FALSE(sp.boundary) << p.x << " " << p.y << " " << p.z;
    // Outward: towards the point asked about.
    EXPECT_GT(glm::dot(sp.n, p - sp.p), 0.f) << p.x << " " << p.y << " " << p.z;
  }
}

}  // namespace
}  // namespace inkray
