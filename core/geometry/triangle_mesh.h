// Triangle meshes in world space, and the builders that turn quads, boxes and
// tessellated spheres into them.
#pragma once

#include "core/math/transform.h"
#include "core/math/types.h"

#include <cstdint>
#include <vector>

namespace inkray {

struct TriangleMesh {
  // One trailing padding element: Embree reads vertex buffers 16 bytes at a time.
  std::vector<Point3> positions;
  std::vector<Normal3> normals;  // per vertex, or empty for flat shading
  std::vector<Vec2> uvs;         // per vertex, or empty
  std::vector<Color> colors;     // per vertex, or empty (white)
  std::vector<uint32_t> indices;

  size_t vertex_count() const { return positions.empty() ? 0 : positions.size() - 1; }
  size_t triangle_count() const { return indices.size() / 3; }
  float triangle_area(size_t tri) const;
};

// A mesh's shading attributes at a point of one of its triangles.
struct MeshShading {
  Normal3 ng{0.f, 0.f, 1.f};  // the facet normal given, turned to the shading normal's side
  Normal3 ns{0.f, 0.f, 1.f};  // unit interpolated normal, or ng where the mesh has none
  Vec2 uv{0.f};               // interpolated, or (b1, b2) where the mesh has none
  Color color{1.f};           // interpolated vertex colour, or white
};

// Interpolates at barycentrics (b1, b2) of triangle tri. ng is the facet's unit
// normal, which the caller chooses where the triangle is degenerate.
MeshShading interpolate_shading(const TriangleMesh& mesh, uint32_t tri, float b1, float b2,
                                const Normal3& ng);

// Builds a mesh from unpadded arrays, transformed to world space.
TriangleMesh make_mesh(std::vector<Point3> positions, std::vector<Normal3> normals, std::vector<Vec2> uvs,
                       std::vector<uint32_t> indices, const Transform& to_world);
// The mesh moved by to_world, exactly as make_mesh would have built it there.
TriangleMesh transformed(const TriangleMesh& mesh, const Transform& to_world);
TriangleMesh make_quad(const Point3& corner, const Vec3& edge_u, const Vec3& edge_v,
                       const Transform& to_world);
// Six outward-facing quads.
TriangleMesh make_box(const Point3& lo, const Point3& hi, const Transform& to_world);
// UV sphere with smooth normals, for tests and emitters that need a mesh.
TriangleMesh make_uv_sphere(const Point3& center, float radius, int rings, int segments,
                            const Transform& to_world);

}  // namespace inkray
