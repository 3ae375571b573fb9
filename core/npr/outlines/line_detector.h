// Outline detection per camera sample (after Choudhury and Parker 2009): a
// stencil of extra camera rays spread over a disc around the sample compares
// the perceived surface at the centre with the surface each stencil ray sees.
// The disc's radius comes from the line width, so widths hold at any
// resolution, and coverage converges with the render like any other sample.
// How many stencil rays a sample traces is line_sampling.h's decision.
#pragma once

#include "core/document/npr_desc.h"
#include "core/world/line_types.h"
#include "core/npr/outlines/perceived_surface.h"
#include "core/integrator/path_tracer.h"
#include "core/sampling/sampler.h"
#include "core/world/render_scene.h"

namespace inkray {

// Lines narrower than this many pixels are drawn this wide at proportionally
// lower opacity: a stencil much smaller than a pixel finds an edge in a few
// samples only, which shows as isolated dots rather than a faint line.
inline constexpr float kMinLineWidthPx = 1.f;

// What `outlines` mean for the samples of `scene`'s view at its full resolution: the
// compiler's, stored as RenderScene::lines. Reads the view's camera and sample settings
// and the world's bounds.
LineSetup make_line_setup(const OutlineDesc& outlines, const RenderScene& scene);
// The same setup for a film of one pixel per divisor x divisor image pixels (an editor
// preview): wider film pixels, so another stencil at the nominal width.
LineSetup line_setup_for_film(const LineSetup& setup, int divisor);

// Sample dimensions of the stencil (see path_tracer.cpp for the others).
inline constexpr uint32_t kOutlinePairBlock = 1u << 25;

// Which stencil points a sample draws: ray k is point first + k of the pixel's
// own Owen-scrambled Sobol sequence, so however the rays are spread over the
// samples, a pixel's stencil points stay one stratified sequence.
struct StencilDraw {
  uint32_t x = 0, y = 0;  // the film pixel
  uint32_t first = 0;     // stencil rays the pixel has traced before
  uint32_t seed = 0;
  int count = 1;  // rays to trace for this sample
};

// The stencil rays come from `camera` (the one the sample's own ray came
// from), through film positions around film_pos with the sample's own lens
// point, so lines follow depth of field. `centre` is the camera ray through
// film_pos and `primary` what it hit.
LineSample detect_lines(const RenderScene& scene, const LineSetup& setup, const Camera& camera, Vec2 film_pos,
                        Vec2 lens, const Ray& centre, const PrimaryHit& primary, float u_mix,
                        const StencilDraw& draw, uint32_t* rays);

// How much a break seen through a specular chain counts, from 1 (coherent) to 0
// (the chain scatters the stencil too much to resolve a line): `spread` is how
// many times wider the stencil's footprint has grown along the chain.
float chain_coherence(float spread);

}  // namespace inkray
