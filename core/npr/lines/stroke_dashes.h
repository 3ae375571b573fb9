// Dashed lines: a styled stroke cut into dashes along its length.
#pragma once

#include "core/npr/lines/line_strokes.h"

#include <vector>

namespace inkray {

// Dashes of `dash` pixels with `gap` pixels between, the first starting where the
// stroke does, the last cut short where it ends. Each dash keeps the samples (width,
// colour, opacity, v) of the stretch it covers, with samples interpolated at its
// ends, so a tapered stroke's dashes taper with it. A loop is cut round from its first
// sample back to it. Dashes are open strokes; set and brush are kept. With dash or
// gap not positive, the stroke comes back whole.
std::vector<LineStroke> cut_dashes(const LineStroke& stroke, float dash, float gap);

}  // namespace inkray
