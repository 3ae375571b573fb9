// Compiled materials: the flat, texture-resolved form of MaterialDesc that the
// path loop reads. Each kind states what it yields at a hit (MaterialTraits): a
// BSDF, an emission, or neither; code that decides by kind handles every kind.
#pragma once

#include "core/geometry/ray.h"
#include "core/materials/bsdf.h"
#include "core/materials/closure_params.h"
#include "core/materials/shader_program.h"
#include "core/materials/shading_point.h"
#include "core/materials/texture.h"
#include "core/materials/toon.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace inkray {

// A closure's settings are the document's block (closure_params.h, toon_params.h),
// copied whole; its colour inputs are compiled to textures.
struct DiffuseMaterial {
  Texture albedo;
};
struct ConductorMaterial : ConductorParams {
  Texture color;  // reflectance at normal incidence (F0)
};
struct DielectricMaterial : DielectricParams {};
struct EmissiveMaterial : EmissiveParams {
  Texture color;
};
struct UnlitMaterial {
  Texture color;
};
struct TransparentMaterial : TransparentParams {};
// Picks material a or b per sample with probability luminance(factor) of b, so
// the mix costs no more than either side and needs no BSDF of its own.
struct MixMaterial {
  uint32_t a = 0, b = 0;  // indices into RenderScene::materials; never a cycle
  Texture factor;
  bool uses_light = false;  // a side is a graph that reads the light inputs
};

// A material graph: its program decides per shading point which surface the
// sample sees (shader_program.h).
struct GraphMaterial {
  std::shared_ptr<const ShaderProgram> program;
};

using Material = std::variant<DiffuseMaterial, ConductorMaterial, DielectricMaterial, EmissiveMaterial,
                              UnlitMaterial, TransparentMaterial, ToonMaterial, MixMaterial, GraphMaterial>;

// Writes one valued input of a closure into its material (the alternative the leaf's
// template holds): bound by the input's socket name when the graph is compiled
// (core/compiler/closure_inputs.h), so no list restates the order of the sockets.
using ClosureSetter = void (*)(Material& material, const Vec3& value);

// One valued input of a closure: the register holding it, what it accepts, and
// where it goes in the material.
struct ClosureInput {
  uint16_t reg = 0;
  ClosureInputBounds bounds;  // shader_program.h
  ClosureSetter set = nullptr;
};

// One way a graph's surface can be at a hit (shader_program.h): the template
// compiled from the closure node's settings, and its valued inputs.
struct ClosureLeaf {
  Material tmpl;
  std::vector<ClosureInput> inputs;
  bool constant = false;  // every input is a constant: tmpl already holds them and is used as it is
};

// What a kind of material promises, decided once per alternative.
struct MaterialFlags {
  bool scatters;   // material_bsdf gives a BSDF
  bool emits;      // material_emission can be non-zero
  bool transmits;  // light passes through: the surface's orientation tells inside from outside
  bool resolves;   // stands for other surfaces per sample: resolve_material before asking anything else
};
// No general definition: a new alternative does not compile until it states its flags here.
template <class T>
struct MaterialTraits;
template <>
struct MaterialTraits<DiffuseMaterial> {
  static constexpr MaterialFlags flags{
      .scatters = true, .emits = false, .transmits = false, .resolves = false};
};
template <>
struct MaterialTraits<ConductorMaterial> {
  static constexpr MaterialFlags flags{
      .scatters = true, .emits = false, .transmits = false, .resolves = false};
};
template <>
struct MaterialTraits<DielectricMaterial> {
  static constexpr MaterialFlags flags{
      .scatters = true, .emits = false, .transmits = true, .resolves = false};
};
template <>
struct MaterialTraits<EmissiveMaterial> {
  static constexpr MaterialFlags flags{
      .scatters = false, .emits = true, .transmits = false, .resolves = false};
};
// Shows its colour to every ray, lit by nothing: it neither scatters nor lights the scene.
template <>
struct MaterialTraits<UnlitMaterial> {
  static constexpr MaterialFlags flags{
      .scatters = false, .emits = false, .transmits = false, .resolves = false};
};
template <>
struct MaterialTraits<TransparentMaterial> {
  static constexpr MaterialFlags flags{
      .scatters = true, .emits = false, .transmits = true, .resolves = false};
};
// Scatters as a Lambertian of its lit colour where the path does not show its cel look.
template <>
struct MaterialTraits<ToonMaterial> {
  static constexpr MaterialFlags flags{
      .scatters = true, .emits = false, .transmits = false, .resolves = false};
};
template <>
struct MaterialTraits<MixMaterial> {
  static constexpr MaterialFlags flags{
      .scatters = false, .emits = false, .transmits = false, .resolves = true};
};
template <>
struct MaterialTraits<GraphMaterial> {
  static constexpr MaterialFlags flags{
      .scatters = false, .emits = false, .transmits = false, .resolves = true};
};

// The flags of the kind `m` holds.
inline MaterialFlags material_flags(const Material& m) {
  return std::visit([]<class T>(const T&) { return MaterialTraits<T>::flags; }, m);
}

inline constexpr uint32_t kNoMaterial = UINT32_MAX;

// The surface a sample sees at a hit: never a mix or a graph. `material` points
// into the table or at the caller's scratch; the sample's throughput is multiplied
// by `weight` (2 where an add closure picked one of its two sides).
struct ResolvedMaterial {
  const Material* material = nullptr;  // null: none (a cycle, which compilation rejects)
  float weight = 1.f;
};
// Follows mixes and runs graphs from `index`. A mix picks b with probability
// luminance(factor) clamped to [0, 1]; u in [0, 1) is reused for nested choices by
// rescaling, so one stratified number decides the whole chain. A graph's chosen
// closure is written to `scratch`. sp carries the hit and, when a graph needs
// them (material_uses_light), the light inputs.
ResolvedMaterial resolve_material(std::span<const Material> materials, uint32_t index, const ShadingPoint& sp,
                                  float u, Material& scratch);
// Whether resolving `index` may run a graph that reads the light inputs.
bool material_uses_light(std::span<const Material> materials, uint32_t index);

// A graph's outline and stroke outputs at a hit (mixes followed with u like resolve_material);
// each is empty when the graph leaves it unlinked or the material is not a graph.
struct SurfaceOverrides {
  std::optional<Color> line_color;
  std::optional<float> line_width;
  std::optional<Color> stroke_color;
};
SurfaceOverrides material_overrides(std::span<const Material> materials, uint32_t index,
                                    const ShadingPoint& sp, float u);

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
