// Compiled materials: the flat, texture-resolved form of MaterialDesc that the
// path loop reads. A material yields a BSDF at a hit, an emission, or both.
#pragma once

#include "core/geometry/ray.h"
#include "core/materials/bsdf.h"
#include "core/materials/texture.h"

#include <optional>
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

using Material = std::variant<DiffuseMaterial, ConductorMaterial, DielectricMaterial, EmissiveMaterial,
                              UnlitMaterial, TransparentMaterial>;

// Materials read the hit's uv and vertex colour (si.color multiplies base colours).
// The BSDF at a hit, or nullopt when the material does not scatter (emissive, unlit).
std::optional<Bsdf> material_bsdf(const Material& material, const SurfaceInteraction& si);
// Radiance leaving the surface towards a viewer on the side given by cos_ng
// (dot of the outgoing direction and the geometric normal).
Color material_emission(const Material& material, const SurfaceInteraction& si, float cos_ng);
bool material_is_emissive(const Material& material);
// Mean emitted radiance over the surface, for weighting light selection.
Color material_average_emission(const Material& material);
// Colour for the albedo AOV.
Color material_albedo(const Material& material, const SurfaceInteraction& si);
// Surfaces a path passes through: their orientation decides inside and outside.
inline bool material_has_transmission(const Material& m) {
  return std::holds_alternative<DielectricMaterial>(m) || std::holds_alternative<TransparentMaterial>(m);
}

}  // namespace inkray
