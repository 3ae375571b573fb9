// The surface an emitter's strokes grow on: its object's shape, seen through
// sampling (placement) and projection (growth). Spheres stay analytic.
#pragma once

#include "core/geometry/embree_scene.h"
#include "core/npr/strokes/mesh_surface.h"
#include "core/npr/strokes/sphere_surface.h"

#include <optional>
#include <string>
#include <variant>

namespace inkray {

class StrokeSurface {
 public:
  // A mesh surface refers to the shape's mesh, which must outlive it. Returns
  // nullopt and sets *error when the shape has no area to grow strokes on.
  static std::optional<StrokeSurface> from_shape(const Shape& shape, std::string* error);

  double area() const;
  SurfacePoint sample(uint32_t seed, uint32_t index) const;
  Point3 sample_position(uint32_t seed, uint32_t index) const;  // = sample(seed, index).p, cheaper
  // near: a distance within which a surface point is known to lie (a hint for
  // meshes; the answer does not depend on it).
  SurfacePoint project(const Point3& p, float near = kInfinity) const;

  float size() const { return size_; }  // bounding box diagonal
  // Largest coordinate magnitude: float rounding of positions scales with it.
  float magnitude() const { return magnitude_; }
  // How much deeper than a circular arc's sagitta a chord between two surface
  // points may dip, for the same angle between their normals: a sphere is an
  // arc; a mesh may fold its whole angle at one sharp edge (twice the dip).
  float chord_dip_factor() const { return std::holds_alternative<SphereSurface>(surface_) ? 1.25f : 2.5f; }

 private:
  explicit StrokeSurface(std::variant<SphereSurface, MeshSurface> surface, float size, float magnitude)
      : surface_(std::move(surface)), size_(size), magnitude_(magnitude) {}

  std::variant<SphereSurface, MeshSurface> surface_;
  float size_ = 0.f;
  float magnitude_ = 0.f;
};

}  // namespace inkray
