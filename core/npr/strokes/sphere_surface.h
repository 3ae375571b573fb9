// An analytic sphere (possibly an ellipsoid under its transform) as a surface to
// grow strokes on: exact area-uniform sampling and exact projection.
#pragma once

#include "core/geometry/sphere.h"
#include "core/npr/strokes/surface_point.h"

namespace inkray {

class SphereSurface {
 public:
  explicit SphereSurface(const Sphere& sphere);

  double area() const { return area_; }
  // Area-uniform point; every random number derives from (seed, index).
  SurfacePoint sample(uint32_t seed, uint32_t index) const;
  // The position of sample(seed, index) alone (no normal or uv): cheaper.
  Point3 sample_position(uint32_t seed, uint32_t index) const;
  // The surface point on the ray from the centre (in object space) through p:
  // exactly on the surface, and the closest point when the sphere is round.
  // near is ignored: the projection is direct. Its uv is left at 0 (growth
  // needs none; sample() gives roots theirs).
  SurfacePoint project(const Point3& p, float near = kInfinity) const;
  const Sphere& sphere() const { return sphere_; }

 private:
  SurfacePoint at(const glm::dvec3& n_object) const;
  Point3 position(const glm::dvec3& n_object) const;
  glm::dvec3 sample_direction(uint32_t seed, uint32_t index) const;
  // World area per unit object-space area at the object normal n (r = 1).
  double area_scale(const glm::dvec3& n_object) const;

  Sphere sphere_;
  glm::dmat3 m_{1.0};         // object -> world, linear part
  glm::dmat3 normal_m_{1.0};  // inverse transpose, for normals
  double det_ = 1.0;
  double max_area_scale_ = 1.0;  // bound on area_scale, for rejection sampling
  bool round_ = false;           // the same area scale everywhere: no rejection needed
  double area_ = 0.0;
};

}  // namespace inkray
