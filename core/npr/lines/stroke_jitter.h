// The hand's wobble: smooth noise that displaces a stroke across itself, seeded so
// that the same line jitters the same way from frame to frame.
#pragma once

#include "core/world/chain.h"

#include <cstdint>
#include <vector>

namespace inkray {

// Smooth 1D value noise in [-1, 1]: a hashed value per integer x, blended with a
// quintic so the noise and its slope are continuous. With period > 0 the lattice
// repeats every `period` cells (a loop's noise meets itself).
float value_noise(uint32_t seed, float x, int period = 0);

// A key of a chain (or piece) that holds while it moves a little and whatever its
// index or direction: its type, path and bounding box, quantised to 4 pixels.
uint32_t chain_key(const Chain& chain);

// Moves each point across the line (along its normal) by amplitude * value_noise
// of its distance along the line over `wavelength`. The distance runs from whichever
// end of an open line comes first (its quantised position's row, then column), or
// from a loop's topmost point in its own orientation, and the side of the normal
// follows: a line traced the other way round moves the same way. `closed` joins the
// last point to the first.
void jitter_points(std::vector<ChainPoint>& points, bool closed, uint32_t seed, float amplitude,
                   float wavelength);

}  // namespace inkray
