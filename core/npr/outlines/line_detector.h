// Outline detection per camera sample (after Choudhury and Parker 2009): a
// stencil of extra camera rays spread over a disc around the sample compares
// the perceived surface at the centre with the surface each stencil ray sees.
// The disc's radius comes from the line width, so widths hold at any
// resolution, and coverage converges with the render like any other sample.
#pragma once

#include "core/npr/outlines/line_types.h"
#include "core/integrator/path_tracer.h"
#include "core/sampling/sampler.h"
#include "core/world/render_scene.h"

namespace inkray {

// What a scene's outline settings mean for every sample, worked out once per scene.
struct LineSetup {
  bool active = false;                      // any line type enabled
  uint32_t enabled = 0;                     // bit per LineType
  std::array<float, kLineTypeCount> width{};  // per-type width multipliers
  float max_width = 0.f;                      // the largest of them: the stencil's radius
  std::array<float, kLineTypeCount> ray_weight{};  // coverage one stencil ray adds to each type
  int rays = 1;                               // stencil rays per sample
  float width_px = 0.f;        // base width in pixels of this image (pixels and percent units)
  bool world_width = false;    // width in world units: depends on the centre's distance
  float miss_distance = 1.f;   // distance used for world widths and falloff where the centre sees nothing
  float crease_cos = 0.f, intersection_cos = 0.f;
  float depth_jump = 0.f;  // relative distance jump of depth lines
};

LineSetup make_line_setup(const RenderScene& scene);

// Sample dimensions of the stencil (see path_tracer.cpp for the others).
inline constexpr uint32_t kOutlinePairBlock = 1u << 25;

// The stencil rays come from `camera` (the one the sample's own ray came
// from), through film positions around film_pos with the sample's own lens
// point, so lines follow depth of field. `centre` is the camera ray through
// film_pos and `primary` what it hit.
LineSample detect_lines(const RenderScene& scene, const LineSetup& setup, const Camera& camera, Vec2 film_pos,
                        Vec2 lens, const Ray& centre, const PrimaryHit& primary, float u_mix,
                        const Sampler& sampler, uint32_t* rays);

}  // namespace inkray
