#include "core/materials/texture.h"

#include <stb_image.h>

#include <cmath>

namespace inkray {
namespace {

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

Color bilinear_repeat(const Image& img, Vec2 uv) {
  const float x = (uv.x - std::floor(uv.x)) * float(img.width) - 0.5f;
  const float y = (1.f - (uv.y - std::floor(uv.y))) * float(img.height) - 0.5f;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const float fx = x - float(x0), fy = y - float(y0);
  auto texel = [&](int xi, int yi) {
    xi = ((xi % img.width) + img.width) % img.width;
    yi = ((yi % img.height) + img.height) % img.height;
    return img.texels[size_t(yi) * size_t(img.width) + size_t(xi)];
  };
  return glm::mix(glm::mix(texel(x0, y0), texel(x0 + 1, y0), fx), glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), fx),
                  fy);
}

}  // namespace

std::optional<Image> load_image(const std::filesystem::path& file, bool srgb, std::string* error) {
  int w = 0, h = 0, channels = 0;
  const std::string name = file.string();
  Image img;
  if (stbi_is_hdr(name.c_str())) {
    float* data = stbi_loadf(name.c_str(), &w, &h, &channels, 3);
    if (!data) {
      *error = name + ": cannot read image (" + stbi_failure_reason() + ")";
      return std::nullopt;
    }
    img.texels.resize(size_t(w) * size_t(h));
    for (size_t i = 0; i < img.texels.size(); ++i) img.texels[i] = {data[3 * i], data[3 * i + 1], data[3 * i + 2]};
    stbi_image_free(data);
  } else {
    unsigned char* data = stbi_load(name.c_str(), &w, &h, &channels, 3);
    if (!data) {
      *error = name + ": cannot read image (" + stbi_failure_reason() + ")";
      return std::nullopt;
    }
    float lut[256];
    for (int i = 0; i < 256; ++i) lut[i] = srgb ? srgb_to_linear(float(i) / 255.f) : float(i) / 255.f;
    img.texels.resize(size_t(w) * size_t(h));
    for (size_t i = 0; i < img.texels.size(); ++i)
      img.texels[i] = {lut[data[3 * i]], lut[data[3 * i + 1]], lut[data[3 * i + 2]]};
    stbi_image_free(data);
  }
  img.width = w;
  img.height = h;
  glm::dvec3 sum(0.0);
  for (const Color& c : img.texels) sum += glm::dvec3(c);
  img.average = Color(sum / double(img.texels.size()));
  return img;
}

Color texture_eval(const Texture& texture, Vec2 uv) {
  if (const auto* c = std::get_if<ConstantTexture>(&texture)) return c->value;
  if (const auto* i = std::get_if<ImageTexture>(&texture)) return i->scale * bilinear_repeat(*i->image, uv);
  const auto& ch = std::get<CheckerTexture>(texture);
  const int parity = int(std::floor(uv.x * ch.scale)) + int(std::floor(uv.y * ch.scale));
  return (parity & 1) ? ch.odd : ch.even;
}

Color texture_average(const Texture& texture) {
  if (const auto* c = std::get_if<ConstantTexture>(&texture)) return c->value;
  if (const auto* i = std::get_if<ImageTexture>(&texture)) return i->scale * i->image->average;
  const auto& ch = std::get<CheckerTexture>(texture);
  return 0.5f * (ch.even + ch.odd);
}

}  // namespace inkray
