// LineSetup: what a scene's outline settings mean for every camera sample, worked
// out once per view by the compiler (RenderScene::lines; docs/architecture.md,
// "World and view"), with the stencil a sample of the nominal width draws.
#pragma once

#include "core/world/line_types.h"

#include <array>
#include <cstdint>

namespace inkray {

// How far lines are followed through mirrors and glass, as the compiled line setup
// has it (LineSetup::follow).
struct FollowLimits {
  bool specular = true;  // outlines.in_reflections: follow mirrors and glass at all
  float max_blur = 0.f;  // roughness blur, radians, beyond which mirrors and glass are not followed
};

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

}  // namespace inkray
