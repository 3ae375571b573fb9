// A triangle mesh as a surface to grow strokes on: area-weighted sampling and
// closest-point projection through an Embree point-query BVH of the mesh.
#pragma once

#include "core/geometry/triangle_mesh.h"
#include "core/npr/strokes/surface_point.h"
#include "core/sampling/distribution.h"

#include <memory>

namespace inkray {

class MeshSurface {
 public:
  // Keeps a reference to mesh, which must outlive the surface.
  explicit MeshSurface(const TriangleMesh& mesh);
  ~MeshSurface();
  MeshSurface(MeshSurface&&) noexcept;
  MeshSurface& operator=(MeshSurface&&) noexcept;

  double area() const { return triangles_.total(); }
  // Area-uniform point; every random number derives from (seed, index).
  SurfacePoint sample(uint32_t seed, uint32_t index) const;
  // The position of sample(seed, index) alone: cheaper.
  Point3 sample_position(uint32_t seed, uint32_t index) const;
  // The closest point of the mesh to p. Off a facet's interior (past an edge of
  // a flat-shaded mesh) the normal bisects the facets there: it points from the
  // surface to p, which lets strokes walk around convex edges. Past an open
  // boundary (an edge with one triangle) the point keeps its facet's normal and
  // is marked `boundary`. near: a distance within which the caller knows a
  // surface point lies, which narrows the search (the answer is the same).
  SurfacePoint project(const Point3& p, float near = kInfinity) const;

 private:
  SurfacePoint at(uint32_t tri, float b1, float b2) const;
  // The triangle and barycentrics of sample(seed, index).
  void sample_triangle(uint32_t seed, uint32_t index, uint32_t* tri, float* b1, float* b2) const;

  const TriangleMesh* mesh_ = nullptr;
  DiscreteDistribution triangles_;  // by area
  std::vector<uint8_t> boundary_;   // per triangle: open edges and corners on them
  struct Bvh;
  std::unique_ptr<Bvh> bvh_;
};

}  // namespace inkray
