// Lights: a closed set sampled for next-event estimation. Emissive shapes are
// area lights whose radiance comes from their material; point, spot and
// directional lights are deltas; the environment is an infinite light.
#pragma once

#include "core/geometry/ray.h"
#include "core/math/frame.h"
#include "core/sampling/distribution.h"

#include <optional>
#include <variant>

namespace inkray {

struct PointLight {
  Point3 position{0.f};
  Color intensity{1.f};  // W/sr
};
struct SpotLight {
  Point3 position{0.f};
  Frame frame;  // z is the spot axis
  Color intensity{1.f};
  float cos_total = 0.8f;    // cosine of the cone half-angle
  float cos_falloff = 0.9f;  // cosine where the falloff starts
};
struct DirectionalLight {
  Vec3 to_light{0.f, 1.f, 0.f};
  Color irradiance{1.f};
  float scene_radius = 1.f;  // for its power
};
// Emissive triangle mesh: triangles picked by area.
struct MeshAreaLight {
  uint32_t object = 0;
  DiscreteDistribution triangles;
  float area = 0.f;
};
// Emissive rectangle (a quad whose edges meet at right angles, after its transform):
// sampled uniformly in the solid angle it subtends (core/sampling/spherical_rectangle.h).
struct RectAreaLight {
  uint32_t object = 0;
  Point3 corner{0.f};
  Vec3 x{1.f, 0.f, 0.f}, y{0.f, 0.f, 1.f};  // unit edge directions
  float width = 1.f, height = 1.f;          // edge lengths
};
// Emissive sphere without shear or non-uniform scale: sampled by solid angle.
struct SphereAreaLight {
  uint32_t object = 0;
  Point3 center{0.f};
  float radius = 1.f;
};
// Constant or gradient sky: zenith at +y, nadir at -y.
struct EnvironmentLight {
  Color zenith{0.f}, horizon{0.f}, nadir{0.f};
  float scene_radius = 1.f;
  Color radiance(const Vec3& dir) const {
    const float y = glm::clamp(dir.y / glm::length(dir), -1.f, 1.f);
    return y >= 0.f ? glm::mix(horizon, zenith, y) : glm::mix(horizon, nadir, -y);
  }
};

using Light = std::variant<PointLight, SpotLight, DirectionalLight, MeshAreaLight, RectAreaLight,
                           SphereAreaLight, EnvironmentLight>;

// What kind of light each alternative is. There is no primary template: a light added
// to `Light` does not compile until it says what it is here, and every dispatch over
// lights (light sampling, light_pdf, light_power, toon shading) visits every kind with
// no catch-all, so it does not compile until each handles it.
template <class L>
struct LightTraits;
// A delta light (a point, spot or directional light) is reached only by sampling it:
// no BSDF sample hits it, so its solid-angle density is never asked for.
template <>
struct LightTraits<PointLight> {
  static constexpr bool delta = true;
};
template <>
struct LightTraits<SpotLight> {
  static constexpr bool delta = true;
};
template <>
struct LightTraits<DirectionalLight> {
  static constexpr bool delta = true;
};
template <>
struct LightTraits<MeshAreaLight> {
  static constexpr bool delta = false;
};
template <>
struct LightTraits<RectAreaLight> {
  static constexpr bool delta = false;
};
template <>
struct LightTraits<SphereAreaLight> {
  static constexpr bool delta = false;
};
template <>
struct LightTraits<EnvironmentLight> {
  static constexpr bool delta = false;
};

namespace light_detail {
template <class V>
struct EveryLightHasTraits;
template <class... Ls>
struct EveryLightHasTraits<std::variant<Ls...>> {
  static constexpr bool value = ((LightTraits<Ls>::delta || !LightTraits<Ls>::delta) && ...);
};
}  // namespace light_detail
static_assert(light_detail::EveryLightHasTraits<Light>::value);

// The receiving point: where the shadow ray starts.
struct LightReference {
  Point3 p{0.f};
  Vec3 p_error{0.f};
  Normal3 n{0.f};  // zero for points in a medium; used only to offset the origin
};

struct LightSample {
  Color radiance{0.f};  // arriving at the reference point, before visibility
  Vec3 wi{0.f};         // towards the light, normalised
  float pdf = 0.f;      // solid angle (1 for delta lights), not including the light's selection pmf
  bool is_delta = false;
  Ray shadow_ray;  // from the reference point to the light
  float shadow_t_max = 0.f;
};

}  // namespace inkray
