// A line style drawn on a sample line, for the Line sets panel's swatches: a gentle S
// across a box, styled by the renderer's own stroke code (core/npr/lines/line_strokes.h),
// so width, taper, wobble, passes, overshoot and dashes look as they will in the image.
// Window-free: the widget that draws it is ui/widgets/line_style_swatch.h.
#pragma once

#include "core/document/line_set_desc.h"
#include "core/npr/lines/line_strokes.h"

#include <vector>

namespace inkray {

// The strokes `style` draws along the sample line in a box `width` x `height` pixels
// (origin at its top left, y down), at `scale` box pixels per pixel of a 1080-line image.
// Along the line, whatever a modulation reads from (depth, light, ...) runs from 0 at
// the left end to 1 at the right, so the style's whole range shows.
std::vector<LineStroke> sample_strokes(const LineSetStyleDesc& style, float width, float height, float scale);

// The style's brush over a stroke: its coverage at `u` across (0 at the left of the way
// it runs) at `v` pixels along it. 1 for a solid line, and for an image brush, which a
// swatch does not read from disk.
float sample_brush_alpha(const LineSetStyleDesc& style, const LineStroke& stroke, float u, float v);

}  // namespace inkray
