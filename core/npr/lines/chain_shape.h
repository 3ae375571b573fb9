// Where a chain starts and which way it runs, and how it turns: what every chain
// gets once its points are in place, whichever way it was found (traced from the
// film's coverage, or from the surfaces' own edges).
#pragma once

#include "core/world/chain.h"

namespace inkray {

// The stable start and direction: an open chain starts at its end with the smaller x
// (then y), a closed one at its topmost point running clockwise on screen (y down),
// so a chain keeps its parameterisation from frame to frame.
void orient_chain(Chain& c);

// Sets each point's curvature: the turn between its neighbouring segments over their
// mean length, radians per pixel, positive clockwise on screen. An open chain's ends
// take their neighbours' values.
void measure_curvature(Chain& c);

}  // namespace inkray
