// A line style's swatch: its sample strokes (ui/model/line_style_sample.h) drawn with
// ImGui's draw list on a patch of paper, each stroke a strip whose width, colour and
// opacity follow its samples, with a soft pixel at its sides and the brush across it.
#pragma once

#include "core/document/line_set_desc.h"

struct ImDrawList;
struct ImVec2;

namespace inkray {

// Draws the swatch over [lo, hi] (screen pixels); `dimmed` draws it faded (a disabled set).
void draw_line_style_swatch(ImDrawList* draw, const ImVec2& lo, const ImVec2& hi,
                            const LineSetStyleDesc& style, bool dimmed = false);

}  // namespace inkray
