#include "core/materials/material.h"

namespace inkray {

std::optional<Bsdf> material_bsdf(const Material& material, const SurfaceInteraction& si) {
  if (const auto* m = std::get_if<DiffuseMaterial>(&material))
    return LambertBsdf{si.color * texture_eval(m->albedo, si.uv)};
  if (const auto* m = std::get_if<ConductorMaterial>(&material))
    return ConductorBsdf{si.color * texture_eval(m->color, si.uv), m->alpha};
  if (const auto* m = std::get_if<DielectricMaterial>(&material)) return m->bsdf;
  if (const auto* m = std::get_if<TransparentMaterial>(&material)) return TransparentBsdf{m->tint};
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
        if constexpr (std::is_same_v<T, DiffuseMaterial>) return si.color * texture_eval(m.albedo, uv);
        else if constexpr (std::is_same_v<T, ConductorMaterial>) return si.color * texture_eval(m.color, uv);
        else if constexpr (std::is_same_v<T, DielectricMaterial>) return m.bsdf.tint;
        else if constexpr (std::is_same_v<T, EmissiveMaterial>) return texture_eval(m.color, uv);
        else if constexpr (std::is_same_v<T, UnlitMaterial>) return texture_eval(m.color, uv);
        else return m.tint;
      },
      material);
}

}  // namespace inkray
