// Corners of chains: where a line set's style breaks a chain into pieces, each
// drawn as its own stroke (so a tapered style tapers into every sharp corner).
#pragma once

#include "core/world/chain.h"

#include <vector>

namespace inkray {

// How far either side of a point its incoming and outgoing directions are measured,
// pixels: far enough to see past the one-pixel stair steps of a traced line, near
// enough that a corner stays a point.
inline constexpr float kCornerReachPx = 3.f;

// The turn at each point, degrees in [0, 180]: the angle between the direction from
// the point kCornerReachPx behind it to it and the direction from it to the point
// kCornerReachPx ahead. 0 within that reach of an open chain's ends, where only one
// side is seen.
std::vector<float> chain_turns(const Chain& chain);

// The chain cut at its corners: points turning more than 180 - corner_angle degrees,
// one cut at the sharpest point of each run of such points. A piece ends at a corner
// and the next starts there. A closed chain with corners opens into pieces, the last
// wrapping round to the first corner; without corners (or with corner_angle <= 0) the
// chain comes back whole. Pieces keep the chain's type, path, object and material.
std::vector<Chain> split_at_corners(const Chain& chain, float corner_angle);

}  // namespace inkray
