// Brushes: the coverage of a stroke over its uv (u across, v along from where
// the brush lands to where it lifts), baked once per emitter into an AlphaMask
// that the renderer's alpha test reads.
#pragma once

#include "core/geometry/alpha_mask.h"
#include "core/document/npr_desc.h"

#include <filesystem>
#include <memory>
#include <string>

namespace inkray {

// Procedural bristle brush: `bristles` streaks across the stroke, each with its
// own paint load and length; a rounded head where the brush lands; soft, slightly
// wavy sides; and, as `pressure` rises, paint that runs out along the stroke so
// the gaps between bristles open into dry-brush streaks. variant picks the
// random bristle pattern.
float bristle_alpha(float u, float v, float bristles, float pressure, uint32_t variant);
// Procedural flat brush: soft sides, rounded ends, thinning by `pressure` along v.
float flat_alpha(float u, float v, float pressure);

// The emitter's brush as a mask: procedural brushes in kBrushVariants patterns;
// an image brush from brush_image (relative to base_dir; its alpha channel, or
// its luminance when it has none), with the stroke running along the image's x
// axis (left to right) and across its y axis, plus a mirrored variant. Returns
// null and sets *error when the image cannot be read.
inline constexpr int kBrushVariants = 8;
std::shared_ptr<AlphaMask> make_brush_mask(const StrokeEmitterDesc& emitter,
                                           const std::filesystem::path& base_dir, std::string* error);

}  // namespace inkray
