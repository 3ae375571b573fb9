// Strokes: chains drawn in the style of the line sets that select them
// (docs/architecture.md, "Lines as strokes"). A stroke is a polyline of samples,
// each with its own width, colour and opacity, ready to be rasterised
// (stroke_raster.h) or written as vector outlines (vector_lines.h). Styling knows
// nothing of how chains were found, and drawing nothing of styles.
#pragma once

#include "core/geometry/alpha_mask.h"
#include "core/math/types.h"
#include "core/world/chain.h"
#include "core/world/line_sets.h"

#include <memory>
#include <vector>

namespace inkray {

struct StrokeSample {
  Vec2 p{0.f};             // image position, pixels (y down)
  float half_width = 0.f;  // pixels
  Color color{0.f};        // a display colour, as line colours are (core/film/resolve.h)
  float opacity = 1.f;     // in [0, 1]
  float v = 0.f;           // distance along the stroke from its piece's start, pixels
};

struct LineStroke {
  // About a pixel apart (1.5 at most), so width and colour vary smoothly between them.
  std::vector<StrokeSample> samples;
  bool closed = false;  // the last sample joins the first (a loop: no ends, no taper)
  int set = 0;          // index of the line set that drew it
  // The set's brush, u across (0 at the left of the direction of travel), v along;
  // null: a solid stroke.
  std::shared_ptr<const AlphaTexture> brush;
  float brush_repeat_px = 0.f;  // v per brush image, pixels; 0: one image over the stroke
  int brush_variant = 0;        // in [0, brush->variants)
};

// How far a stroke runs, pixels: its samples' v span, with a loop's closing segment.
float stroke_length(const LineStroke& stroke);

// The strokes of every line set, in set order, then the chains' order, then the
// passes: what each selects of `chains`, styled for an image `image_height` pixels
// tall (the style's lengths are pixels at 1080 lines). For each selected chain:
//   - split at corners (chain_corners.h) and pieces shorter than min_length dropped;
//   - resampled so samples lie about a pixel apart (1.5 at most);
//   - open pieces extended by `overshoot` along their end tangents;
//   - per pass, displaced across itself by smooth value noise (`jitter`, wavelength
//     `jitter_scale`). The noise's seed is the style's seed, the pass and a key of the
//     piece that holds from frame to frame (its type, path and bounding box to 4 px),
//     and it runs from the piece's end that comes first in a fixed order (a loop's
//     topmost point, in its own orientation), so a chain traced the other way round or
//     listed elsewhere next frame jitters the same;
//   - tapered over taper_start and taper_end fractions of the (extended) length, the
//     width easing to zero at the tip; loops, and ends that stop in a crossing
//     (Chain::ends_at_crossing), are not tapered;
//   - widened or thinned by the pressure curve at the fraction of the stroke's length;
//   - width, colour and opacity modulated (LineModulation): a multiplier 1 where the
//     value reads 0 and width_min / opacity_min where it reads 1, a colour from
//     `color` to `color_end`. Values: along = fraction of the stroke's length; depth
//     = over the nearest to the farthest depth of all `chains` (the background, depth
//     0, reads as farthest); curvature = |curvature| over a radian per 10 pixels at
//     1080 lines, clamped to 1; light = the point's light; coverage = its opacity;
//   - opacity = style opacity * its modulation * the chain point's own opacity, so a
//     line the film found faintly is drawn faintly in every style (as composite_lines
//     draws it today);
//   - cut into dashes of `dash` pixels `gap` apart when both are set, after tapering,
//     so a dashed tapered line still tapers over its whole length.
std::vector<LineStroke> stroke_chains(const std::vector<Chain>& chains, const std::vector<LineSet>& sets,
                                      int image_height);

// Whether `select` takes `chain`: its type and path bits set, and its object and
// material true in their vectors where those are not empty (an index out of range,
// or -1, is not selected then).
bool selects(const LineSelection& select, const Chain& chain);

}  // namespace inkray
