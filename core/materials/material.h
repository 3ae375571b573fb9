// Compiled materials: the flat, texture-resolved form of MaterialDesc that the
// path loop reads. Each kind states what it yields at a hit (MaterialTraits): a
// BSDF, an emission, or neither; code that decides by kind handles every kind.
#pragma once

#include "core/geometry/ray.h"
#include "core/materials/bsdf.h"
#include "core/materials/texture.h"
#include "core/materials/toon.h"

#include <cstdint>
#include <optional>
#include <span>
#include <variant>

namespace inkray {

struct DiffuseMaterial {
  Texture albedo;
};
struct ConductorMaterial {
  Texture color;
  float alpha = 0.f;
};
struct DielectricMaterial {
  DielectricBsdf bsdf;
};
struct EmissiveMaterial {
  Texture color;
  float strength = 1.f;
  bool two_sided = false;
};
struct UnlitMaterial {
  Texture color;
};
struct TransparentMaterial {
  Color tint{1.f};
};
// Picks material a or b per sample with probability luminance(factor) of b, so
// the mix costs no more than either side and needs no BSDF of its own.
struct MixMaterial {
  uint32_t a = 0, b = 0;  // indices into RenderScene::materials; never a cycle
  Texture factor;
};

using Material = std::variant<DiffuseMaterial, ConductorMaterial, DielectricMaterial, EmissiveMaterial,
                              UnlitMaterial, TransparentMaterial, ToonMaterial, MixMaterial>;

// What a kind of material promises, decided once per alternative.
struct MaterialFlags {
  bool scatters;   // material_bsdf gives a BSDF
  bool emits;      // material_emission can be non-zero
  bool transmits;  // light passes through: the surface's orientation tells inside from outside
  bool is_mix;     // stands for other materials: resolve_mix before asking anything else
};
// No general definition: a new alternative does not compile until it states its flags here.
template <class T>
struct MaterialTraits;
template <>
struct MaterialTraits<DiffuseMaterial> {
  static constexpr MaterialFlags flags{.scatters = true, .emits = false, .transmits = false, .is_mix = false};
};
template <>
struct MaterialTraits<ConductorMaterial> {
  static constexpr MaterialFlags flags{.scatters = true, .emits = false, .transmits = false, .is_mix = false};
};
template <>
struct MaterialTraits<DielectricMaterial> {
  static constexpr MaterialFlags flags{.scatters = true, .emits = false, .transmits = true, .is_mix = false};
};
template <>
struct MaterialTraits<EmissiveMaterial> {
  static constexpr MaterialFlags flags{.scatters = false, .emits = true, .transmits = false, .is_mix = false};
};
// Shows its colour to every ray, lit by nothing: it neither scatters nor lights the scene.
template <>
struct MaterialTraits<UnlitMaterial> {
  static constexpr MaterialFlags flags{
      .scatters = false, .emits = false, .transmits = false, .is_mix = false};
};
template <>
struct MaterialTraits<TransparentMaterial> {
  static constexpr MaterialFlags flags{.scatters = true, .emits = false, .transmits = true, .is_mix = false};
};
// Scatters as a Lambertian of its lit colour where the path does not show its cel look.
template <>
struct MaterialTraits<ToonMaterial> {
  static constexpr MaterialFlags flags{.scatters = true, .emits = false, .transmits = false, .is_mix = false};
};
template <>
struct MaterialTraits<MixMaterial> {
  static constexpr MaterialFlags flags{.scatters = false, .emits = false, .transmits = false, .is_mix = true};
};

// The flags of the kind `m` holds.
inline MaterialFlags material_flags(const Material& m) {
  return std::visit([]<class T>(const T&) { return MaterialTraits<T>::flags; }, m);
}

inline constexpr uint32_t kNoMaterial = UINT32_MAX;
// Follows mixes from `index` to a material that is not a mix, choosing b with
// probability luminance(factor) clamped to [0, 1]. u in [0, 1) is reused for
// nested mixes by rescaling, so one stratified number decides the whole chain.
// Returns kNoMaterial if the chain is longer than the material list (a cycle,
// which compilation rejects).
uint32_t resolve_mix(std::span<const Material> materials, uint32_t index, const SurfaceInteraction& si,
                     float u);

// Materials read the hit's uv and vertex colour (si.color multiplies base colours).
// The functions below see a mix as neither scattering nor emitting: resolve it first.
// The BSDF at a hit, or nullopt when the material does not scatter (emissive, unlit);
// a toon surface scatters as a Lambertian of its lit colour when light bounces off it.
std::optional<Bsdf> material_bsdf(const Material& material, const SurfaceInteraction& si);
// Radiance leaving the surface towards a viewer on the side given by cos_ng
// (dot of the outgoing direction and the geometric normal).
Color material_emission(const Material& material, const SurfaceInteraction& si, float cos_ng);
// False for a mix even over an emitter: such emission is found by BSDF sampling only.
bool material_is_emissive(const Material& material);
// Mean emitted radiance over the surface, for weighting light selection.
Color material_average_emission(const Material& material);
// Colour for the albedo AOV.
Color material_albedo(const Material& material, const SurfaceInteraction& si);
// Surfaces a path passes through: their orientation decides inside and outside.
inline bool material_has_transmission(const Material& m) { return material_flags(m).transmits; }

}  // namespace inkray
