// Fresnel reflectance and the reflect/refract direction helpers shared by the
// BSDFs (pbrt-v4 util/scattering.h). Directions point away from the surface.
#pragma once

#include "core/math/types.h"

#include <optional>

namespace inkray {

// Mirror of wo about n; valid for either orientation of n.
inline Vec3 reflect(const Vec3& wo, const Vec3& n) { return -wo + 2.f * glm::dot(wo, n) * n; }

struct Refraction {
  Vec3 wt;     // transmitted direction, on the other side of n from wo
  float etap;  // relative IOR that was crossed (n_transmitted / n_incident)
};

// Snell's law through a surface with normal n, eta = n_inside / n_outside
// with n pointing outside. Empty on total internal reflection.
inline std::optional<Refraction> refract(const Vec3& wo, Vec3 n, float eta) {
  float cos_i = glm::dot(n, wo);
  if (cos_i < 0.f) {  // wo is inside: the interface is seen the other way round
    eta = 1.f / eta;
    cos_i = -cos_i;
    n = -n;
  }
  const float sin2_t = glm::max(0.f, 1.f - sqr(cos_i)) / sqr(eta);
  if (sin2_t >= 1.f) return std::nullopt;
  const float cos_t = safe_sqrt(1.f - sin2_t);
  return Refraction{-wo / eta + (cos_i / eta - cos_t) * n, eta};
}

// Unpolarised Fresnel reflectance of a dielectric interface; cos_i < 0 means
// the incident direction is inside. Returns 1 on total internal reflection.
inline float fresnel_dielectric(float cos_i, float eta) {
  cos_i = glm::clamp(cos_i, -1.f, 1.f);
  if (cos_i < 0.f) {
    eta = 1.f / eta;
    cos_i = -cos_i;
  }
  const float sin2_t = (1.f - sqr(cos_i)) / sqr(eta);
  if (sin2_t >= 1.f) return 1.f;
  const float cos_t = safe_sqrt(1.f - sin2_t);
  const float r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const float r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5f * (sqr(r_parl) + sqr(r_perp));
}

// Schlick's approximation with a coloured normal-incidence reflectance: cheap,
// artist-friendly, and exactly F0 = 1 gives F = 1 at every angle.
inline Color fresnel_schlick(const Color& f0, float cos_i) {
  const float m = glm::clamp(1.f - std::abs(cos_i), 0.f, 1.f);
  const float m5 = sqr(sqr(m)) * m;
  return f0 + (Color(1.f) - f0) * m5;
}

}  // namespace inkray
