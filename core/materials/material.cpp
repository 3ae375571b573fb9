// Material evaluation at a hit: BSDF, emission, albedo, and resolving mixes.
#include "core/materials/material.h"

#include <algorithm>

namespace inkray {

uint32_t resolve_mix(std::span<const Material> materials, uint32_t index, const SurfaceInteraction& si,
                     float u) {
  // Acyclic mixes reach a non-mix in fewer steps than there are materials.
  for (size_t steps = 0; steps <= materials.size() && index < materials.size(); ++steps) {
    const auto* mix = std::get_if<MixMaterial>(&materials[index]);
    if (!mix) return index;
    float p = glm::clamp(luminance(texture_eval(mix->factor, si.uv)), 0.f, 1.f);
    if (p > 1.f - 1e-6f) p = 1.f;  // white's luminance rounds just below 1; factor 1 must be all b
    if (u < p) {
      index = mix->b;
      u = std::min(u / p, kOneMinusEpsilon);
    } else {
      index = mix->a;
      u = std::min((u - p) / (1.f - p), kOneMinusEpsilon);
    }
  }
  return kNoMaterial;
}

std::optional<Bsdf> material_bsdf(const Material& material, const SurfaceInteraction& si) {
  if (const auto* m = std::get_if<DiffuseMaterial>(&material))
    return LambertBsdf{si.color * texture_eval(m->albedo, si.uv)};
  if (const auto* m = std::get_if<ConductorMaterial>(&material))
    return ConductorBsdf{si.color * texture_eval(m->color, si.uv), m->alpha};
  if (const auto* m = std::get_if<DielectricMaterial>(&material)) return m->bsdf;
  if (const auto* m = std::get_if<TransparentMaterial>(&material)) return TransparentBsdf{m->tint};
  if (const auto* m = std::get_if<ToonMaterial>(&material))
    return LambertBsdf{si.color * texture_eval(m->color, si.uv)};
  return std::nullopt;
}

Color material_emission(const Material& material, const SurfaceInteraction& si, float cos_ng) {
  const auto* m = std::get_if<EmissiveMaterial>(&material);
  if (!m || (!m->two_sided && cos_ng <= 0.f)) return Color(0.f);
  return m->strength * si.color * texture_eval(m->color, si.uv);
}

bool material_is_emissive(const Material& material) {
  const auto* m = std::get_if<EmissiveMaterial>(&material);
  return m && m->strength > 0.f && max_component(texture_average(m->color)) > 0.f;
}

Color material_average_emission(const Material& material) {
  const auto* m = std::get_if<EmissiveMaterial>(&material);
  return m ? m->strength * texture_average(m->color) : Color(0.f);
}

Color material_albedo(const Material& material, const SurfaceInteraction& si) {
  const Vec2 uv = si.uv;
  return std::visit(
      [&](const auto& m) -> Color {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, DiffuseMaterial>)
          return si.color * texture_eval(m.albedo, uv);
        else if constexpr (std::is_same_v<T, ConductorMaterial>)
          return si.color * texture_eval(m.color, uv);
        else if constexpr (std::is_same_v<T, DielectricMaterial>)
          return m.bsdf.tint;
        else if constexpr (std::is_same_v<T, EmissiveMaterial>)
          return texture_eval(m.color, uv);
        else if constexpr (std::is_same_v<T, UnlitMaterial>)
          return texture_eval(m.color, uv);
        else if constexpr (std::is_same_v<T, ToonMaterial>)
          return si.color * texture_eval(m.color, uv);
        else if constexpr (std::is_same_v<T, MixMaterial>)
          return Color(0.f);  // resolved before this is asked
        else
          return m.tint;
      },
      material);
}

}  // namespace inkray
