#include "core/render/display_encode.h"

#include "core/image/image_io.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

// sRGB encoding of [0,1] through a table: a 960x540 image per pass must cost
// far less than the pass, and pow() per channel does not.
struct SrgbTable {
  static constexpr int kSize = 4096;
  std::array<uint8_t, kSize + 1> values{};
  SrgbTable() {
    for (int i = 0; i <= kSize; ++i) {
      values[size_t(i)] = uint8_t(std::lround(255.f * linear_to_srgb(float(i) / kSize)));
    }
  }
  uint8_t operator()(float v) const {
    if (!(v > 0.f)) return 0;
    if (v >= 1.f) return 255;
    return values[size_t(v * kSize + 0.5f)];
  }
};

}  // namespace

std::vector<uint8_t> encode_display(const RgbImage& image, const DisplayEncoding& encoding) {
  static const SrgbTable table;
  const DisplayMapping display(encoding);
  const bool raw = encoding.transform == ViewTransform::raw;
  std::vector<uint8_t> out(image.pixels.size() * 4);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const Color c = image.pixels[i];
    uint8_t* px = &out[i * 4];
    for (int k = 0; k < 3; ++k) {
      const float v = display.to_display(c[k]);
      px[k] = raw ? uint8_t(std::clamp(v, 0.f, 1.f) * 255.f + 0.5f) : table(v);
    }
    px[3] = 255;
  }
  return out;
}

void paint_highlight(std::vector<uint8_t>& rgba, const RgbImage& object_ids, int object,
                     std::array<uint8_t, 3> rgb, int thickness, std::array<uint8_t, 3> rim) {
  if (object < 0) return;
  const int w = object_ids.width, h = object_ids.height;
  if (rgba.size() != size_t(w) * size_t(h) * 4) return;
  const auto is_selected = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= w || y >= h) return false;
    return int(object_ids.at(x, y).x) == object;
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      uint8_t* px = &rgba[(size_t(y) * size_t(w) + size_t(x)) * 4];
      if (!is_selected(x, y)) {
        if (is_selected(x - 1, y) || is_selected(x + 1, y) || is_selected(x, y - 1) || is_selected(x, y + 1))
          px[0] = rim[0], px[1] = rim[1], px[2] = rim[2];
        continue;
      }
      bool edge = false;
      for (int d = 1; d <= std::max(thickness, 1) && !edge; ++d)
        edge = !is_selected(x - d, y) || !is_selected(x + d, y) || !is_selected(x, y - d) ||
               !is_selected(x, y + d);
      if (!edge) continue;
      px[0] = rgb[0], px[1] = rgb[1], px[2] = rgb[2];
    }
  }
}

}  // namespace inkray
