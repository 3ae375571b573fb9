// The spline through a traced pixel path: smoothed, simplified to the fewest
// points within a tolerance (Douglas-Peucker), and sampled at even spacing along
// a centripetal Catmull-Rom spline through them, so a staircase of pixels becomes
// the straight or curved line it stands for.
#pragma once

#include "core/world/chain.h"

#include <vector>

namespace inkray {

// Points of the fitted chain, `spacing` pixels apart (about); attributes other than
// the position are left for the caller. Fewer than two pixels give no points.
std::vector<ChainPoint> fit_chain(const std::vector<Vec2>& pixels, bool closed, float tolerance,
                                  float spacing);

}  // namespace inkray
