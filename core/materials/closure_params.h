// The settings of the conductor, dielectric, emissive and transparent closures as one
// block each (docs/architecture.md, "Parameter tables"): the document's description
// and the compiled material both derive from it, so a setting is declared once, with
// one default, and compiling copies the block whole. Colour inputs are not here: the
// document holds them as colour inputs, the compiled material as textures. Diffuse and
// unlit have nothing but their colour, so they have no block.
#pragma once

#include "core/math/types.h"

namespace inkray {

// GGX alpha from the perceptual roughness the document states: 0 is a mirror.
inline float ggx_alpha(float roughness) { return roughness * roughness; }

struct ConductorParams {
  float roughness = 0.f;  // perceptual: alpha = roughness^2
  bool operator==(const ConductorParams&) const = default;
};

struct DielectricParams {
  float ior = 1.5f;       // index of refraction of the inside
  float roughness = 0.f;  // perceptual: alpha = roughness^2; 0 is smooth glass
  Color tint{1.f};        // multiplies transmitted light
  bool operator==(const DielectricParams&) const = default;
};

struct EmissiveParams {
  float strength = 1.f;  // radiance = color * strength
  bool two_sided = false;
  bool operator==(const EmissiveParams&) const = default;
};

struct TransparentParams {
  Color tint{1.f};  // multiplies light passing straight through
  bool operator==(const TransparentParams&) const = default;
};

}  // namespace inkray
