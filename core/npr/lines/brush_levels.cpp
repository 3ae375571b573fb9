// Brush levels for drawing strokes into images.
#include "core/npr/lines/brush_levels.h"

#include <algorithm>
#include <cmath>

namespace inkray {

const AlphaTexture& BrushLevels::for_width(float drawn_width) const {
  const float texels_per_px = float(source->width) / std::max(drawn_width, 1e-6f);
  const int level =
      std::clamp(int(std::lround(std::log2(std::max(texels_per_px, 1.f)))), 0, int(coarser.size()));
  return level == 0 ? *source : coarser[size_t(level - 1)];
}

BrushLevels make_brush_levels(const AlphaTexture& source) {
  BrushLevels b{&source, {}};
  const AlphaTexture* fine = &source;
  while (fine->width > 1) {
    AlphaTexture coarse{(fine->width + 1) / 2, fine->height, fine->variants, {}};
    coarse.texels.resize(size_t(coarse.variants) * size_t(coarse.height) * size_t(coarse.width));
    for (int layer = 0; layer < fine->variants; ++layer)
      for (int v = 0; v < fine->height; ++v)
        for (int u = 0; u < coarse.width; ++u) {
          const int u1 = std::min(2 * u + 1, fine->width - 1);
          coarse.at(layer, u, v) =
              uint8_t((int(fine->at(layer, 2 * u, v)) + int(fine->at(layer, u1, v)) + 1) / 2);
        }
    b.coarser.push_back(std::move(coarse));
    fine = &b.coarser.back();
  }
  return b;
}

const BrushLevels& BrushLevelCache::levels_of(const AlphaTexture& texture) {
  for (const BrushLevels& b : brushes_)
    if (b.source == &texture) return b;
  brushes_.push_back(make_brush_levels(texture));
  return brushes_.back();
}

}  // namespace inkray
