// Turns raw AOV values into colours a person can read: normals to 0.5+0.5n,
// depth normalised to the nearest and farthest hits, ids to distinct colours.
#pragma once

#include "core/film/film.h"

namespace inkray {

RgbImage aov_for_display(Aov aov, const RgbImage& raw);

}  // namespace inkray
