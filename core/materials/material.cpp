// Material evaluation at a hit: BSDF, emission, albedo, and resolving mixes.
// Each function visits with one case per kind of material and no catch-all, so
// a new kind does not compile until every function says what it does for it.
#include "core/materials/material.h"

#include "core/base/overloaded.h"
#include "core/materials/shader_eval.h"

#include <algorithm>

namespace inkray {
namespace {

// The emitter a material is, or null for a kind that sends out no light of its own.
const EmissiveMaterial* emitter_of(const Material& material) {
  using Emitter = const EmissiveMaterial*;
  return std::visit(Overloaded{
                        [](const DiffuseMaterial&) -> Emitter { return nullptr; },
                        [](const ConductorMaterial&) -> Emitter { return nullptr; },
                        [](const DielectricMaterial&) -> Emitter { return nullptr; },
                        [](const EmissiveMaterial& m) -> Emitter { return &m; },
                        // Its colour is what a ray sees, not light that reaches anything else.
                        [](const UnlitMaterial&) -> Emitter { return nullptr; },
                        [](const TransparentMaterial&) -> Emitter { return nullptr; },
                        [](const ToonMaterial&) -> Emitter { return nullptr; },
                        // Even over an emitter: resolve it first.
                        [](const MixMaterial&) -> Emitter { return nullptr; },
                        [](const GraphMaterial&) -> Emitter { return nullptr; },
                    },
                    material);
}

// The side of a mix this sample takes: b with probability luminance(factor). u is
// rescaled to [0, 1) within the side taken, for the choices after this one.
uint32_t mix_side(const MixMaterial& mix, const ShadingPoint& sp, float& u) {
  float p = glm::clamp(luminance(texture_eval(mix.factor, sp.si->uv)), 0.f, 1.f);
  if (p > 1.f - 1e-6f) p = 1.f;  // white's luminance rounds just below 1; factor 1 must be all b
  if (u < p) {
    u = std::min(u / p, kOneMinusEpsilon);
    return mix.b;
  }
  u = std::min((u - p) / (1.f - p), kOneMinusEpsilon);
  return mix.a;
}

}  // namespace

ResolvedMaterial resolve_material(std::span<const Material> materials, uint32_t index, const ShadingPoint& sp,
                                  float u, Material& scratch) {
  // Acyclic mixes reach a non-mix in fewer steps than there are materials.
  for (size_t steps = 0; steps <= materials.size() && index < materials.size(); ++steps) {
    const Material& m = materials[index];
    if (const auto* graph = std::get_if<GraphMaterial>(&m)) return run_graph(*graph->program, sp, u, scratch);
    if (!material_flags(m).resolves) return {&m, 1.f};
    index = mix_side(std::get<MixMaterial>(m), sp, u);
  }
  return {};
}

bool material_uses_light(std::span<const Material> materials, uint32_t index) {
  if (index >= materials.size()) return false;
  if (const auto* graph = std::get_if<GraphMaterial>(&materials[index])) return graph->program->uses_light;
  if (const auto* mix = std::get_if<MixMaterial>(&materials[index])) return mix->uses_light;
  return false;
}

SurfaceOverrides material_overrides(std::span<const Material> materials, uint32_t index,
                                    const ShadingPoint& sp, float u) {
  for (size_t steps = 0; steps <= materials.size() && index < materials.size(); ++steps) {
    const Material& m = materials[index];
    if (const auto* graph = std::get_if<GraphMaterial>(&m)) return shader_overrides(*graph->program, sp);
    const auto* mix = std::get_if<MixMaterial>(&m);
    if (!mix) return {};
    index = mix_side(*mix, sp, u);
  }
  return {};
}

std::optional<Bsdf> material_bsdf(const Material& material, const SurfaceInteraction& si) {
  using Result = std::optional<Bsdf>;
  return std::visit(
      Overloaded{
          [&](const DiffuseMaterial& m) -> Result {
            return LambertBsdf{si.color * texture_eval(m.albedo, si.uv)};
          },
          [&](const ConductorMaterial& m) -> Result {
            return ConductorBsdf{si.color * texture_eval(m.color, si.uv), ggx_alpha(m.roughness)};
          },
          [](const DielectricMaterial& m) -> Result {
            return DielectricBsdf{m.ior, ggx_alpha(m.roughness), m.tint};
          },
          // Paths end on an emitter: light leaves it, none bounces off it.
          [](const EmissiveMaterial&) -> Result { return std::nullopt; },
          // Shows its colour whatever the light: nothing to scatter.
          [](const UnlitMaterial&) -> Result { return std::nullopt; },
          [](const TransparentMaterial& m) -> Result { return TransparentBsdf{m.tint}; },
          // Light bouncing off a toon surface sees a Lambertian of its lit colour.
          [&](const ToonMaterial& m) -> Result {
            return LambertBsdf{si.color * texture_eval(m.color, si.uv)};
          },
          // A mix or graph scatters as the surface resolve_material picks.
          [](const MixMaterial&) -> Result { return std::nullopt; },
          [](const GraphMaterial&) -> Result { return std::nullopt; },
      },
      material);
}

Color material_emission(const Material& material, const SurfaceInteraction& si, float cos_ng) {
  const EmissiveMaterial* m = emitter_of(material);
  if (!m || (!m->two_sided && cos_ng <= 0.f)) return Color(0.f);
  return m->strength * si.color * texture_eval(m->color, si.uv);
}

bool material_is_emissive(const Material& material) {
  const EmissiveMaterial* m = emitter_of(material);
  return m && m->strength > 0.f && max_component(texture_average(m->color)) > 0.f;
}

Color material_average_emission(const Material& material) {
  const EmissiveMaterial* m = emitter_of(material);
  return m ? m->strength * texture_average(m->color) : Color(0.f);
}

Color material_albedo(const Material& material, const SurfaceInteraction& si) {
  const Vec2 uv = si.uv;
  return std::visit(
      Overloaded{
          [&](const DiffuseMaterial& m) -> Color { return si.color * texture_eval(m.albedo, uv); },
          [&](const ConductorMaterial& m) -> Color { return si.color * texture_eval(m.color, uv); },
          [](const DielectricMaterial& m) -> Color { return m.tint; },
          [&](const EmissiveMaterial& m) -> Color { return texture_eval(m.color, uv); },
          [&](const UnlitMaterial& m) -> Color { return texture_eval(m.color, uv); },
          [](const TransparentMaterial& m) -> Color { return m.tint; },
          [&](const ToonMaterial& m) -> Color { return si.color * texture_eval(m.color, uv); },
          [](const MixMaterial&) -> Color { return Color(0.f); },  // resolved before this is asked
          [](const GraphMaterial&) -> Color { return Color(0.f); },
      },
      material);
}

}  // namespace inkray
