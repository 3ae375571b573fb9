// Linear float RGB images: film output, AOVs and textures.
#pragma once

#include "core/math/types.h"

#include <vector>

namespace inkray {

// Row 0 at the top.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<Color> pixels;
  Color& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  const Color& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

}  // namespace inkray
