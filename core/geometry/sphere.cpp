#include "core/geometry/sphere.h"

#include "core/math/float_error.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace inkray {

glm::dvec3 Sphere::to_object_point(const Point3& p) const {
  return glm::dvec3(glm::dmat4(to_world.inv) * glm::dvec4(glm::dvec3(p), 1.0));
}
glm::dvec3 Sphere::to_object_vector(const Vec3& v) const {
  return glm::dvec3(glm::dmat4(to_world.inv) * glm::dvec4(glm::dvec3(v), 0.0));
}

std::optional<float> Sphere::intersect(const Ray& ray, float t_min, float t_max) const {
  const glm::dvec3 o = to_object_point(ray.o);
  const glm::dvec3 d = to_object_vector(ray.d);
  const double d_len = glm::length(d);
  if (!(d_len > 0.0)) return std::nullopt;
  const glm::dvec3 dn = d / d_len;
  const glm::dvec3 f = o - glm::dvec3(center);
  const double r = radius;
  // Ray Tracing Gems ch. 7: the discriminant from the perpendicular distance
  // avoids the cancellation of b^2 - 4ac for distant or grazing rays.
  const double proj = glm::dot(f, dn);
  const glm::dvec3 perp = f - proj * dn;
  const double disc = r * r - glm::dot(perp, perp);
  if (disc < 0.0) return std::nullopt;
  const double c = glm::dot(f, f) - r * r;
  const double q = -proj - std::copysign(std::sqrt(disc), proj);
  double s0 = q != 0.0 ? c / q : 0.0;
  double s1 = q;
  if (s0 > s1) std::swap(s0, s1);
  // Parameters along the normalised object-space direction -> along ray.d.
  const double t0 = s0 / d_len, t1 = s1 / d_len;
  if (t0 > t_min && t0 < t_max) return float(t0);
  if (t1 > t_min && t1 < t_max) return float(t1);
  return std::nullopt;
}

SurfaceInteraction Sphere::interaction(const Ray& ray, float t) const {
  const glm::dvec3 o = to_object_point(ray.o);
  const glm::dvec3 d = to_object_vector(ray.d);
  glm::dvec3 rel = o + double(t) * d - glm::dvec3(center);
  const double len = glm::length(rel);
  rel = len > 0.0 ? rel * (double(radius) / len) : glm::dvec3(0.0, double(radius), 0.0);
  const Point3 p_obj = Point3(glm::dvec3(center) + rel);
  // Reprojection leaves a few ulps of error in c + rel: bound it by the
  // magnitudes involved on every axis, so it is never zero along the normal.
  const Vec3 obj_error = Vec3(gamma_bound(5) * (max_component(glm::abs(center)) + radius));

  SurfaceInteraction si;
  si.t = t;
  si.p = to_world.point_with_error(p_obj, obj_error, &si.p_error);
  const Vec3 n_obj = Vec3(rel / double(radius));
  si.ng = glm::normalize(to_world.normal(n_obj));
  si.ns = si.ng;
  const float phi = std::atan2(n_obj.z, n_obj.x);
  si.uv = {(phi < 0.f ? phi + 2.f * kPi : phi) * kInv2Pi, std::acos(glm::clamp(n_obj.y, -1.f, 1.f)) * kInvPi};
  return si;
}

Normal3 Sphere::normal_at(const Point3& p) const {
  return to_world.normal(Vec3(to_object_point(p) - glm::dvec3(center)));
}

void Sphere::bounds(Point3* lo, Point3* hi) const {
  // Exact bounds of a transformed sphere: per axis, r * |row of M|.
  const Point3 c = to_world.point(center);
  Vec3 ext;
  for (int row = 0; row < 3; ++row) {
    const Vec3 m_row(to_world.m[0][row], to_world.m[1][row], to_world.m[2][row]);
    ext[row] = radius * glm::length(m_row);
  }
  // Pad by a relative ulp margin so Embree never culls a grazing hit.
  ext = ext * (1.f + 1e-5f) + 1e-5f * glm::abs(c);
  *lo = c - ext;
  *hi = c + ext;
}

bool Sphere::is_round(Point3* world_center, float* world_radius) const {
  const Mat3 m3(to_world.m);
  const float sx = glm::length(m3[0]), sy = glm::length(m3[1]), sz = glm::length(m3[2]);
  const bool orthogonal = std::abs(glm::dot(m3[0], m3[1])) <= 1e-5f * sx * sy &&
                          std::abs(glm::dot(m3[0], m3[2])) <= 1e-5f * sx * sz &&
                          std::abs(glm::dot(m3[1], m3[2])) <= 1e-5f * sy * sz;
  if (!orthogonal || std::abs(sx - sy) > 1e-5f * sx || std::abs(sx - sz) > 1e-5f * sx) return false;
  *world_center = to_world.point(center);
  *world_radius = radius * sx;
  return true;
}

}  // namespace inkray
