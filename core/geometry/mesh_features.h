// Feature edges of a triangle mesh, the dihedral angle at every edge two triangles
// share, and the smooth patches those edges bound, which crease lines compare
// (docs/architecture.md, "Mesh normals and feature edges").
#pragma once

#include "core/math/types.h"

#include <cstdint>
#include <span>
#include <vector>

namespace inkray {

// The patch of a surface that has none: spheres, strokes.
inline constexpr uint32_t kNoPatch = UINT32_MAX;

// Two triangles meeting at an edge. Half-edge h is the edge of triangle h / 3 from
// its corner h % 3 to the next corner.
struct FeatureEdge {
  uint32_t a = 0, b = 0;  // the two half-edges
  float dihedral = 0.f;   // degrees between the facet normals; infinite when either triangle is degenerate
};

struct MeshFeatures {
  uint32_t triangles = 0;
  std::vector<FeatureEdge> edges;
};

// The unit normal of a triangle, by its winding; zero for a degenerate one (no area,
// or too thin for its normal to mean anything in float).
Normal3 facet_normal(const Point3& a, const Point3& b, const Point3& c);

// Vertex -> welded position id, counting from 0: vertices whose positions are exactly
// equal share one.
std::vector<uint32_t> weld_positions(std::span<const Point3> positions);

// Edges are found by position, welded where exactly equal, so vertices split for
// normals or uvs still join. Boundary edges are not listed. An edge of three or more
// triangles (non-manifold) lists every pair, or for more than kMaxPairedFan
// triangles each with the next, so a degenerate fan costs linear time.
inline constexpr size_t kMaxPairedFan = 8;
MeshFeatures find_feature_edges(std::span<const Point3> positions, std::span<const uint32_t> indices);

// Patch id per triangle: connected components of triangles joined through edges
// whose dihedral angle is at most threshold_degrees. Ids count from 0 in the order of
// each patch's first triangle. A degenerate triangle is a patch of its own.
std::vector<uint32_t> smooth_patches(const MeshFeatures& features, float threshold_degrees);

}  // namespace inkray
