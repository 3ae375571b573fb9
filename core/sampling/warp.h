// Warps from the unit square to directions and shapes, each with its pdf.
#pragma once

#include "core/math/types.h"

#include <cmath>

namespace inkray {

// Shirley-Chiu concentric map: low distortion keeps stratification.
inline Vec2 sample_uniform_disk_concentric(Vec2 u) {
  const Vec2 o = 2.f * u - Vec2(1.f);
  if (o.x == 0.f && o.y == 0.f) return Vec2(0.f);
  float r, theta;
  if (std::abs(o.x) > std::abs(o.y)) {
    r = o.x;
    theta = (kPi / 4.f) * (o.y / o.x);
  } else {
    r = o.y;
    theta = kPi / 2.f - (kPi / 4.f) * (o.x / o.y);
  }
  return r * Vec2(std::cos(theta), std::sin(theta));
}

inline Vec3 sample_cosine_hemisphere(Vec2 u) {
  const Vec2 d = sample_uniform_disk_concentric(u);
  const float z = safe_sqrt(1.f - d.x * d.x - d.y * d.y);
  return {d.x, d.y, z};
}
inline float cosine_hemisphere_pdf(float cos_theta) { return cos_theta * kInvPi; }

inline Vec3 sample_uniform_sphere(Vec2 u) {
  const float z = 1.f - 2.f * u.x;
  const float r = safe_sqrt(1.f - z * z);
  const float phi = 2.f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
inline constexpr float uniform_sphere_pdf() { return kInv4Pi; }

inline Vec3 sample_uniform_hemisphere(Vec2 u) {
  const float z = u.x;
  const float r = safe_sqrt(1.f - z * z);
  const float phi = 2.f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
inline constexpr float uniform_hemisphere_pdf() { return kInv2Pi; }

// Uniform over the cone of directions within acos(cos_max) of +z.
inline Vec3 sample_uniform_cone(Vec2 u, float cos_max) {
  const float cos_t = (1.f - u.x) + u.x * cos_max;
  const float sin_t = safe_sqrt(1.f - cos_t * cos_t);
  const float phi = u.y * 2.f * kPi;
  return {std::cos(phi) * sin_t, std::sin(phi) * sin_t, cos_t};
}
inline float uniform_cone_pdf(float cos_max) { return 1.f / (2.f * kPi * (1.f - cos_max)); }

// Barycentrics (b0, b1) of a uniform point on a triangle (Heitz 2019, low distortion).
inline Vec2 sample_uniform_triangle(Vec2 u) {
  float b0, b1;
  if (u.x < u.y) {
    b0 = u.x / 2.f;
    b1 = u.y - b0;
  } else {
    b1 = u.y / 2.f;
    b0 = u.x - b1;
  }
  return {b0, b1};
}

// Power heuristic with beta = 2 (Veach 1997) for multiple importance sampling.
inline float power_heuristic(float pdf_a, float pdf_b) {
  const float a = pdf_a * pdf_a;
  const float b = pdf_b * pdf_b;
  if (std::isinf(a)) return 1.f;
  return a + b > 0.f ? a / (a + b) : 0.f;
}

}  // namespace inkray
