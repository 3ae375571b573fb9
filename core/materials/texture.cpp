#include "core/materials/texture.h"

#include <cmath>

namespace inkray {
namespace {

Color bilinear_repeat(const RgbImage& img, Vec2 uv) {
  const float x = (uv.x - std::floor(uv.x)) * float(img.width) - 0.5f;
  const float y = (1.f - (uv.y - std::floor(uv.y))) * float(img.height) - 0.5f;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const float fx = x - float(x0), fy = y - float(y0);
  auto texel = [&](int xi, int yi) {
    xi = ((xi % img.width) + img.width) % img.width;
    yi = ((yi % img.height) + img.height) % img.height;
    return img.at(xi, yi);
  };
  return glm::mix(glm::mix(texel(x0, y0), texel(x0 + 1, y0), fx),
                  glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), fx), fy);
}

}  // namespace

Color texture_eval(const Texture& texture, Vec2 uv) {
  if (const auto* c = std::get_if<ConstantTexture>(&texture)) return c->value;
  if (const auto* i = std::get_if<ImageTexture>(&texture)) return i->scale * bilinear_repeat(*i->image, uv);
  const auto& ch = std::get<CheckerTexture>(texture);
  const int parity = int(std::floor(uv.x * ch.scale)) + int(std::floor(uv.y * ch.scale));
  return (parity & 1) ? ch.odd : ch.even;
}

Color texture_average(const Texture& texture) {
  if (const auto* c = std::get_if<ConstantTexture>(&texture)) return c->value;
  if (const auto* i = std::get_if<ImageTexture>(&texture)) return i->scale * i->average;
  const auto& ch = std::get<CheckerTexture>(texture);
  return 0.5f * (ch.even + ch.odd);
}

}  // namespace inkray
