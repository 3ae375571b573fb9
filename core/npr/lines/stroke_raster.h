// Strokes drawn into an image, anti-aliased, composited in the display's space as
// the film's lines are (core/film/resolve.h): each covered pixel is mapped to the
// display, mixed with the stroke's colour by its alpha, and mapped back.
#pragma once

#include "core/image/rgb_image.h"
#include "core/image/view_transform.h"
#include "core/npr/lines/line_strokes.h"

#include <vector>

namespace inkray {

// Draws `strokes` in order over `image` (each OVER what is there). A stroke is the
// union of its segments' capsules, the half width varying linearly along each, with
// flat ends at an open stroke's first and last samples. A pixel takes its alpha and
// colour from one segment, the one covering its centre most (the nearest among those
// covering it fully), so a stroke never darkens where it crosses itself:
//   coverage = clamp(half_width - distance + 0.5, 0, 1) of the pixel centre,
//   times the brush's coverage at (u across, v along) when there is a brush,
//   times the opacity there.
// Strokes thinner than a pixel are drawn a pixel wide at proportionally lower
// opacity (as the film draws thin lines, kMinLineWidthPx), so they fade rather than
// break up.
void draw_strokes(const std::vector<LineStroke>& strokes, const DisplayEncoding& display, RgbImage& image);

}  // namespace inkray
