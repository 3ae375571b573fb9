// Colour textures: constants, images (through stb_image) and checkers.
#pragma once

#include "core/image/rgb_image.h"

#include <memory>
#include <variant>

namespace inkray {

struct ConstantTexture {
  Color value{0.f};
};
struct ImageTexture {
  std::shared_ptr<const RgbImage> image;  // shared between materials using the same file
  Color scale{1.f};
  Color average{0.f};  // mean texel, unscaled
};
struct CheckerTexture {
  Color even{0.9f}, odd{0.1f};
  float scale = 10.f;
};

using Texture = std::variant<ConstantTexture, ImageTexture, CheckerTexture>;

Color texture_eval(const Texture& texture, Vec2 uv);
// Mean over uv in [0,1)^2: weights emitters for light selection.
Color texture_average(const Texture& texture);

}  // namespace inkray
