// A line set's selection in a few words, for its row in the Line sets panel:
// "all lines", "silhouette, crease; hidden", "all types; in mirrors; objects bolt*".
// Only what differs from taking everything is named.
#pragma once

#include "core/document/line_set_desc.h"

#include <string>

namespace inkray {

std::string line_set_summary(const LineSetDesc& set);

}  // namespace inkray
