// Stroke roots: exactly `count` points over the whole surface, area-weighted,
// with blue-noise spacing so strokes neither clump nor leave holes.
#pragma once

#include "core/base/cancel.h"

#include "core/npr/strokes/stroke_surface.h"

#include <vector>

namespace inkray {

struct PlacementStats {
  double mean_spacing = 0.0;  // sqrt(area / count)
  double final_radius = 0.0;  // no two roots are closer than this (3D distance)
  size_t candidates = 0;
};

// Progressive dart throwing (McCool & Fiume 1992) over area-uniform candidates
// drawn from (seed, candidate index): a candidate is accepted when no accepted
// root lies within the current radius, and the radius shrinks by 5% per pass
// until `count` roots are accepted, so the spacing is close to the largest the
// candidates allow. A grid of cells finds neighbours; a pass works through its
// cells in eight parity classes, each class's cells in parallel (they are never
// neighbours); a rejected candidate remembers its nearest root, so later passes
// re-test only those that may now fit. The roots come out in an order hashed
// from their candidates: strokes are painted in it, the later on top.
// Deterministic: the same seed gives the same roots in the same order at any
// thread count. Returns nothing once `cancel` is requested.
std::vector<SurfacePoint> place_roots(const StrokeSurface& surface, size_t count, uint32_t seed,
                                      PlacementStats* stats = nullptr, const Cancel& cancel = {});

}  // namespace inkray
