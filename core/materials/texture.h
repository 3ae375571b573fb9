// Colour textures: constants, images (through stb_image) and checkers.
#pragma once

#include "core/math/types.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace inkray {

// Linear RGB texels, row 0 at the top of the image (v = 1 in uv).
struct Image {
  int width = 0;
  int height = 0;
  std::vector<Color> texels;
  Color average{0.f};
};

// PNG/JPEG/TGA/BMP/HDR. 8-bit images are decoded from sRGB when srgb is true.
std::optional<Image> load_image(const std::filesystem::path& file, bool srgb, std::string* error);

struct ConstantTexture {
  Color value{0.f};
};
struct ImageTexture {
  std::shared_ptr<const Image> image;  // shared between materials using the same file
  Color scale{1.f};
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
