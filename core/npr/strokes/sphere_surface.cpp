// Sphere surfaces in double precision: points land on the analytic surface to
// within float rounding, however far the sphere sits from the origin.
#include "core/npr/strokes/sphere_surface.h"

#include "core/math/hash.h"

#include <cmath>
#include <numbers>

namespace inkray {
namespace {

double frobenius(const glm::dmat3& m) {
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) sum += glm::dot(m[c], m[c]);
  return std::sqrt(sum);
}

float unit_random(uint32_t seed, uint32_t index, uint32_t dimension) {
  return u32_to_unit_float(hash_combine(seed, index, dimension));
}

}  // namespace

SphereSurface::SphereSurface(const Sphere& sphere) : sphere_(sphere) {
  m_ = glm::dmat3(glm::dmat4(sphere.to_world.m));
  normal_m_ = glm::transpose(glm::dmat3(glm::dmat4(sphere.to_world.inv)));
  det_ = std::abs(glm::determinant(m_));
  // |normal_m n| <= ||normal_m||_2 <= ||normal_m||_F for unit n: a valid bound, and
  // at most sqrt(3) too large, so rejection keeps over half of its tries.
  max_area_scale_ = det_ * frobenius(normal_m_);
  // Round under its transform (a rotation and a uniform scale) when the normal
  // matrix's columns are orthogonal and equally long.
  const glm::dmat3 mtm = glm::transpose(normal_m_) * normal_m_;
  const double scale = mtm[0][0];
  round_ = std::abs(mtm[0][1]) + std::abs(mtm[0][2]) + std::abs(mtm[1][2]) <= 1e-9 * scale &&
           std::abs(mtm[1][1] - scale) <= 1e-9 * scale && std::abs(mtm[2][2] - scale) <= 1e-9 * scale;
  // Midpoint quadrature over z = cos(theta) and phi; exact for round spheres, and
  // the integrand of an ellipsoid is smooth, so 256 x 512 points are plenty.
  constexpr int kZ = 256, kPhi = 512;
  double sum = 0.0;
  for (int i = 0; i < kZ; ++i) {
    const double z = -1.0 + 2.0 * (i + 0.5) / kZ, s = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int j = 0; j < kPhi; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / kPhi;
      sum += area_scale({s * std::cos(phi), z, s * std::sin(phi)});
    }
  }
  const double r = sphere.radius;
  area_ = sum * (2.0 / kZ) * (2.0 * std::numbers::pi / kPhi) * r * r;
}

double SphereSurface::area_scale(const glm::dvec3& n_object) const {
  return det_ * glm::length(normal_m_ * n_object);
}

Point3 SphereSurface::position(const glm::dvec3& n_object) const {
  const glm::dvec3 p_object = glm::dvec3(sphere_.center) + double(sphere_.radius) * n_object;
  const glm::dvec3 translation = glm::dvec3(glm::dvec4(glm::dmat4(sphere_.to_world.m)[3]));
  return Point3(m_ * p_object + translation);
}

SurfacePoint SphereSurface::at(const glm::dvec3& n_object) const {
  SurfacePoint sp;
  sp.p = position(n_object);
  sp.n = Normal3(glm::normalize(normal_m_ * n_object));
  sp.ng = sp.n;
  const Vec3 n = Vec3(n_object);
  const float phi = std::atan2(n.z, n.x);
  sp.uv = {(phi < 0.f ? phi + 2.f * kPi : phi) * kInv2Pi, std::acos(glm::clamp(n.y, -1.f, 1.f)) * kInvPi};
  return sp;
}

glm::dvec3 SphereSurface::sample_direction(uint32_t seed, uint32_t index) const {
  // Uniform on the unit sphere, then rejection by the transform's local area scale.
  glm::dvec3 n(0.0, 1.0, 0.0);
  for (uint32_t attempt = 0; attempt < 64; ++attempt) {
    const double z = 1.0 - 2.0 * unit_random(seed, index, 3 * attempt);
    const double phi = 2.0 * std::numbers::pi * unit_random(seed, index, 3 * attempt + 1);
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    n = {s * std::cos(phi), z, s * std::sin(phi)};
    // A round sphere needs no rejection: every direction has the same scale.
    if (round_ || unit_random(seed, index, 3 * attempt + 2) * max_area_scale_ < area_scale(n)) break;
  }
  return n;
}

SurfacePoint SphereSurface::sample(uint32_t seed, uint32_t index) const {
  return at(sample_direction(seed, index));
}

Point3 SphereSurface::sample_position(uint32_t seed, uint32_t index) const {
  return position(sample_direction(seed, index));
}

SurfacePoint SphereSurface::project(const Point3& p, float /*near*/) const {
  const glm::dvec3 p_object = glm::dvec3(glm::dmat4(sphere_.to_world.inv) * glm::dvec4(glm::dvec3(p), 1.0));
  const glm::dvec3 rel = p_object - glm::dvec3(sphere_.center);
  const double len = glm::length(rel);
  const glm::dvec3 n_object = len > 0.0 ? rel / len : glm::dvec3(0.0, 1.0, 0.0);
  SurfacePoint sp;  // growth reads no uv: spare the inverse trigonometry
  sp.p = position(n_object);
  sp.n = Normal3(glm::normalize(normal_m_ * n_object));
  sp.ng = sp.n;
  return sp;
}

}  // namespace inkray
