// Floating-point error bounds and ray origin offsets (pbrt-v4, section 6.8):
// a spawned ray starts just outside the box that surely contains the true hit
// point, so it can never re-hit the surface it leaves.
#pragma once

#include "core/math/types.h"

#include <bit>
#include <cmath>

namespace inkray {

inline constexpr float kMachineEpsilon = std::numeric_limits<float>::epsilon() * 0.5f;
inline constexpr float gamma_bound(int n) { return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon); }

inline float next_float_up(float v) {
  if (std::isinf(v) && v > 0.f) return v;
  if (v == -0.f) v = 0.f;
  uint32_t bits = std::bit_cast<uint32_t>(v);
  bits = v >= 0 ? bits + 1 : bits - 1;
  return std::bit_cast<float>(bits);
}
inline float next_float_down(float v) {
  if (std::isinf(v) && v < 0.f) return v;
  if (v == 0.f) v = -0.f;
  uint32_t bits = std::bit_cast<uint32_t>(v);
  bits = v > 0 ? bits - 1 : bits + 1;
  return std::bit_cast<float>(bits);
}

// p_error bounds |computed p - true p| per axis; w is the new ray direction.
inline Point3 offset_ray_origin(const Point3& p, const Vec3& p_error, const Normal3& n, const Vec3& w) {
  const float d = glm::dot(glm::abs(n), p_error);
  Vec3 offset = d * n;
  if (glm::dot(w, n) < 0.f) offset = -offset;
  Point3 po = p + offset;
  // Round away from p so the offset is not lost to rounding.
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0.f)
      po[i] = next_float_up(po[i]);
    else if (offset[i] < 0.f)
      po[i] = next_float_down(po[i]);
  }
  return po;
}

}  // namespace inkray
