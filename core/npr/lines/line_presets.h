// Named line styles to start from: what the editor offers and scene files may name.
#pragma once

#include "core/world/line_sets.h"

#include <array>
#include <string_view>

namespace inkray {

inline constexpr std::array<std::string_view, 6> kLinePresetNames = {
    "ink", "pencil", "brush", "sketch", "technical", "technical_hidden"};

// The style of a preset named in kLinePresetNames; LineStyle{} for any other name.
//   ink:              3 px black, tapered at both ends
//   pencil:           1.2 px grey, two slightly jittered passes
//   brush:            5 px, tapered; the compiler attaches the bristle brush
//   sketch:           three loose passes, jittered and overshooting, translucent
//   technical:        1.5 px, even, unbroken
//   technical_hidden: the same dashed 6 / 4, for hidden lines
LineStyle line_preset(std::string_view name);

}  // namespace inkray
