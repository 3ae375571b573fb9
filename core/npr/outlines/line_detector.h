// Outline detection per camera sample (after Choudhury and Parker 2009): a
// stencil of extra camera rays spread over a disc around the sample compares
// the perceived surface at the centre with the surface each stencil ray sees.
// The disc's radius comes from the line width, so widths hold at any
// resolution, and coverage converges with the render like any other sample.
// How many stencil rays a sample traces is line_sampling.h's decision.
#pragma once

#include "core/npr/outlines/line_types.h"
#include "core/npr/outlines/perceived_surface.h"
#include "core/integrator/path_tracer.h"
#include "core/sampling/sampler.h"
#include "core/world/render_scene.h"

namespace inkray {

// Lines narrower than this many pixels are drawn this wide at proportionally
// lower opacity: a stencil much smaller than a pixel finds an edge in a few
// samples only, which shows as isolated dots rather than a faint line.
inline constexpr float kMinLineWidthPx = 1.f;

// One sample's stencil: its radius, and what a ray at each reach adds per type.
// Types of different widths share one stencil: it spans the widest, and a point
// that falls inside a narrower type's disc is a uniform point of that disc, so
// counting it with weight (R / r)^2 keeps every type's coverage unbiased.
struct Stencil {
  float radius = 0.f;                         // pixels
  std::array<float, kLineTypeCount> reach{};  // a type's disc radius, pixels (0: not drawn here)
  std::array<float, kLineTypeCount> weight{};
};

// What a scene's outline settings mean for every sample, worked out once per scene.
struct LineSetup {
  bool active = false;                        // any line type enabled with a width above 0
  uint32_t enabled = 0;                       // bit per LineType
  std::array<float, kLineTypeCount> width{};  // per-type width multipliers
  float max_width = 0.f;                      // the largest of them: the stencil's radius
  int quality = 1;                            // stencil rays per sample where lines are being found
  bool adaptive = true;                       // line_sampling.h may trace fewer or more
  float width_px = 0.f;                       // base width in pixels of this image (pixels and percent units)
  bool world_width = false;                   // width in world units: depends on the centre's distance
  float world_width_units = 0.f;              // that width, in world units, when world_width
  float distance_falloff = 0.f;               // width *= (falloff_start / distance)^this beyond falloff_start
  float falloff_start = 0.f;                  // 0: no falloff
  float nominal_radius_px = 1.f;              // the widest type's stencil radius for a typical sample
  float miss_distance = 1.f;  // distance used for world widths and falloff where the centre sees nothing
  float crease_cos = 0.f, intersection_cos = 0.f;
  float depth_jump = 0.f;   // relative distance jump of depth lines
  float pixel_angle = 0.f;  // radians per pixel of the full image at its centre
  float film_pixel = 1.f;   // width of a film pixel's sample footprint, in full-image pixels
  FollowLimits follow;      // how far lines are followed through mirrors and glass
  // The stencil of samples at width_px, the usual case: only world widths,
  // falloff and width overrides make their own.
  Stencil at_width;
};

// `divisor`: the film has one pixel per divisor x divisor image pixels (an
// editor preview).
LineSetup make_line_setup(const RenderScene& scene, int divisor = 1);

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
