// Toon (cel) shading at a path vertex: gathers the light level from every light
// in the scene with shadow rays, then turns it into bands, a ramp, a specular
// band and a rim through the curves in materials/toon.h.
#pragma once

#include "core/lights/light.h"
#include "core/materials/toon.h"
#include "core/sampling/sampler.h"
#include "core/world/render_scene.h"

namespace inkray {

// Toon lighting draws one 2D sample per light that needs one (area lights, and
// the environment when the material shadows it). Those pairs live in a block of their own, far above the
// path's per-bounce pairs, so the number of lights never shifts another
// decision's dimension.
inline constexpr uint32_t kToonPairBlock = 1u << 24;
inline constexpr uint32_t kToonPairsPerDepth = 4096;
inline uint32_t toon_light_pair(int depth, size_t light) {
  return kToonPairBlock + uint32_t(depth) * kToonPairsPerDepth + uint32_t(light % kToonPairsPerDepth);
}

// The hit as the toon shader needs it.
struct ToonHit {
  const SurfaceInteraction* si = nullptr;
  Vec3 wo{0.f};            // towards the viewer, normalised
  Normal3 ns{0.f};         // shading normal, on the viewer's side
  LightReference ref;      // shadow rays start here (geometric normal on the viewer's side)
  float view_depth = 0.f;  // distance travelled from the camera, for ramp_axis depth
  int depth = 0;           // bounce index, for sample dimensions
};

struct ToonShade {
  Color radiance{0.f};    // towards hit.wo
  float reference = 0.f;  // irradiance (luminance) the light level is relative to; 0 without lights
  float band = 0.f;       // FirstHit::band: where the look changes hard (bands, specular, rim)
};

// The toon look at a hit for one sample; *rays counts the shadow rays.
ToonShade toon_shade(const RenderScene& scene, const ToonMaterial& m, const ToonHit& hit,
                     const Sampler& sampler, uint32_t* rays);

}  // namespace inkray
