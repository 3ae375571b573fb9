// The outline line types, in the order they are composited (later ones on top),
// and what a camera sample contributes to the film's outline buffers.
#pragma once

#include "core/math/types.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>

namespace inkray {

enum class LineType { depth, crease, intersection, material, object, silhouette };
inline constexpr int kLineTypeCount = 6;
inline constexpr std::array<std::string_view, kLineTypeCount> kLineTypeNames = {
    "depth", "crease", "intersection", "material", "object", "silhouette"};

// How a line reached the camera: seen directly, in a mirror, or through glass.
enum class LinePath : uint8_t { direct, reflected, refracted };
inline constexpr int kLinePathCount = 3;
inline constexpr std::array<std::string_view, kLinePathCount> kLinePathNames = {"direct", "reflected",
                                                                                "refracted"};

// Coverage is the fraction of stencil rays that see a break; a pixel's line
// opacity is kLineGain times its mean, clamped to 1. With stencil points
// spread uniformly over a disc of radius r, a straight edge at distance x*r
// from the centre is seen by the fraction (acos x - x sqrt(1 - x^2)) / pi of
// the disc: the line is solid within 0.40 r of the edge and half-transparent
// at 0.635 r, so a radius of width / 1.27 draws a line `width` wide at half
// opacity, fading out at 1.57 width.
inline constexpr float kLineGain = 4.f;
inline constexpr float kStencilRadiusPerWidth = 1.f / 1.27f;

inline float line_opacity(float mean_coverage) { return std::clamp(kLineGain * mean_coverage, 0.f, 1.f); }

// What one camera sample's stencil rays saw, summed over its rays: the film
// adds these up and divides by the rays, so samples may trace different numbers
// of stencil rays (adaptive line sampling, line_sampling.h).
struct LineSample {
  std::array<float, kLineTypeCount> coverage{};  // summed weights of the rays that saw a break, per type
  float weight = 0.f;                            // ... of any enabled type
  float override_weight = 0.f;                   // ... where the nearer surface overrides the line colour
  Color override_color{0.f};                     // sum of those override colours, weighted alike
  float rays = 0.f;                              // stencil rays drawn (the denominator)
  float hit_rays = 0.f;                          // rays that saw a break of any type, unweighted
};

}  // namespace inkray
