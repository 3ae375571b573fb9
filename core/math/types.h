// Basic vector types. Points, directions and colours share glm storage;
// the aliases keep their meaning visible in signatures.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <limits>

namespace inkray {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;  // a direction or offset
using Point3 = glm::vec3;
using Normal3 = glm::vec3;
using Color = glm::vec3;  // linear RGB radiance or reflectance
using Mat4 = glm::mat4;
using Mat3 = glm::mat3;

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 0.31830988618379067154f;
inline constexpr float kInv2Pi = 0.15915494309189533577f;
inline constexpr float kInv4Pi = 0.07957747154594766788f;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Largest float strictly below 1: keeps [0,1) samples in range after scaling.
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

inline float luminance(const Color& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }
inline float max_component(const Vec3& v) { return glm::max(v.x, glm::max(v.y, v.z)); }
inline bool is_black(const Color& c) { return c.r == 0.f && c.g == 0.f && c.b == 0.f; }
inline bool is_finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline float sqr(float x) { return x * x; }
inline float safe_sqrt(float x) { return std::sqrt(glm::max(0.f, x)); }

}  // namespace inkray
