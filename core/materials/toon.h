// The toon (cel) material's compiled form and its pure shading curves: light
// level -> band colour or ramp colour, the specular band and the rim. Gathering
// the light level from the scene is the integrator's job (toon_shading.h).
#pragma once

#include "core/image/rgb_image.h"
#include "core/materials/texture.h"
#include "core/materials/toon_params.h"

#include <memory>
#include <vector>

namespace inkray {

// The settings are the document's (ToonParams); the colour and the ramps compiled.
struct ToonMaterial : ToonParams {
  Texture color;  // lit colour; multiplied by the hit's vertex colour
  // Evenly spaced stops over the light level; null or empty for bands. Shared so a
  // graph copies the material per hit without allocating.
  std::shared_ptr<const std::vector<Color>> ramp;
  std::shared_ptr<const RgbImage> ramp_image;  // null when unset; replaces ramp and bands
};

// 0 below edge - width/2, 1 above edge + width/2, smooth in between; a hard
// step (x >= edge) when width is 0.
float toon_soft_step(float x, float edge, float width);

// Quantised level in [0, 1]: 0 in the darkest band, 1 in the top band, k/(bands-1)
// in band k. Band edges are at threshold and then evenly spaced from threshold up
// to 1, so threshold is where light starts to count and the lit bands are equal.
float toon_band_level(const ToonMaterial& m, float light_level);

// Colour ramp with evenly spaced stops, linearly interpolated; x clamped to [0, 1].
Color toon_ramp_eval(const std::vector<Color>& stops, float x);
// Bilinear lookup in a ramp image, clamped at the edges: u left to right, v bottom to top.
Color toon_ramp_image_eval(const RgbImage& image, float u, float v);

// Everything the base colour depends on at one shading sample.
struct ToonLightInput {
  float level = 0.f;    // normalised light level, [0, 1]
  Color tint{1.f};      // mean colour of the lights received (each light's brightest channel 1)
  float ramp_v = 0.5f;  // second axis of a ramp image
};
// base: the material colour at the hit (texture times vertex colour).
Color toon_base_color(const ToonMaterial& m, const Color& base, const ToonLightInput& in);

// Specular band coverage in [0, 1] for one light: the Blinn-Phong lobe
// (n.h)^shininess scaled by the light's relative strength, cut at 1 - specular_size.
float toon_specular_coverage(const ToonMaterial& m, float cos_nh, float relative_strength);

// Rim coverage in [0, 1] from the facing ratio n.wo: a band of 1 - n.wo from
// rim_threshold to rim_threshold + rim_width (open at the silhouette when that reaches 1).
float toon_rim_coverage(const ToonMaterial& m, float facing);

}  // namespace inkray
