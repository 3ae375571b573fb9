// A brush for strokes drawn into images, halved across u level by level, so a
// stroke a few pixels wide reads about a texel per pixel across: a bristle brush
// of a hundred texels point-sampled that narrow shows as moiré hatching, not streaks.
#pragma once

#include "core/geometry/alpha_mask.h"

#include <vector>

namespace inkray {

struct BrushLevels {
  const AlphaTexture* source = nullptr;
  std::vector<AlphaTexture> coarser;  // half as many texels across as the level before

  // The level for a stroke `drawn_width` pixels wide: level 0 is the source.
  const AlphaTexture& for_width(float drawn_width) const;
};

BrushLevels make_brush_levels(const AlphaTexture& source);

// The levels of each brush met so far in one drawing (a scene has a few). References
// stay valid until the next levels_of.
class BrushLevelCache {
 public:
  const BrushLevels& levels_of(const AlphaTexture& texture);

 private:
  std::vector<BrushLevels> brushes_;
};

}  // namespace inkray
