// Analytic spheres under an affine transform (so ellipsoids too), intersected
// in double precision in object space: robust for a radius-1000 ground sphere
// seen at grazing angles, with hit points reprojected onto the surface.
#pragma once

#include "core/geometry/ray.h"
#include "core/math/transform.h"

#include <optional>

namespace inkray {

struct Sphere {
  Point3 center{0.f};  // object space
  float radius = 1.f;
  Transform to_world;

  // Nearest hit distance in (t_min, t_max), in units of ray.d's length.
  std::optional<float> intersect(const Ray& ray, float t_min, float t_max) const;
  // Point, error bound, outward normal and uv of the hit at distance t.
  SurfaceInteraction interaction(const Ray& ray, float t) const;
  // The outward normal, not normalised, at a point on the surface.
  Normal3 normal_at(const Point3& p) const;
  // World-space bounds.
  void bounds(Point3* lo, Point3* hi) const;
  // Uniform scale (and rotation) keeps it a sphere: then world centre and radius exist.
  bool is_round(Point3* world_center, float* world_radius) const;

 private:
  glm::dvec3 to_object_point(const Point3& p) const;
  glm::dvec3 to_object_vector(const Vec3& v) const;
};

}  // namespace inkray
