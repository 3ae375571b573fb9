// Procedural brushes and brush images (RGBA through stb_image, since the
// image module reads RGB only), baked into alpha masks.
#include "core/npr/strokes/brush.h"

#include "core/base/parallel.h"
#include "core/image/image_header.h"
#include "core/math/hash.h"

#include <stb_image.h>

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

float lattice(uint32_t seed, int64_t i) {
  return u32_to_unit_float(hash_combine(seed, uint32_t(i), 0x5bd1e995u));
}

// 1D value noise in [0, 1], smooth (C1) between integer lattice points.
float value_noise(float x, uint32_t seed) {
  const float fx = std::floor(x);
  const float t = x - fx;
  const int64_t i = int64_t(fx);
  return glm::mix(lattice(seed, i), lattice(seed, i + 1), t * t * (3.f - 2.f * t));
}

uint8_t to_texel(float alpha) { return uint8_t(std::lround(std::clamp(alpha, 0.f, 1.f) * 255.f)); }

AlphaMask procedural_mask(const StrokeEmitterDesc& e) {
  AlphaMask mask;
  const bool bristle = e.brush == BrushKind::bristle;
  // About 8 texels per bristle so streaks survive bilinear filtering.
  mask.width = bristle ? std::clamp(int(std::ceil(8.f * e.bristles)), 64, 1024) : 64;
  mask.height = 256;
  mask.variants = bristle ? kBrushVariants : 1;
  mask.texels.resize(size_t(mask.variants) * size_t(mask.width) * size_t(mask.height));
  // Rows of every variant in parallel: the bake would otherwise cost more than a
  // thousand strokes' geometry.
  parallel_for_chunks(size_t(mask.variants) * size_t(mask.height), 64, [&](size_t begin, size_t end) {
    for (size_t row = begin; row < end; ++row) {
      const int layer = int(row / size_t(mask.height)), y = int(row % size_t(mask.height));
      for (int x = 0; x < mask.width; ++x) {
        const float u = (float(x) + 0.5f) / float(mask.width), v = (float(y) + 0.5f) / float(mask.height);
        const float a = bristle ? bristle_alpha(u, v, e.bristles, e.pressure, uint32_t(layer))
                                : flat_alpha(u, v, e.pressure);
        mask.at(layer, x, y) = to_texel(a);
      }
    }
  });
  return mask;
}

bool image_mask(const std::filesystem::path& file, AlphaMask* mask, std::string* error) {
  int w = 0, h = 0, channels = 0;
  std::string header_error;
  if (!read_image_size(file, &header_error)) {  // before decoding: the header may ask for gigabytes
    *error = "cannot read brush image " + header_error;
    return false;
  }
  unsigned char* data = stbi_load(file.string().c_str(), &w, &h, &channels, 4);
  if (!data) {
    const char* reason = stbi_failure_reason();
    *error = "cannot read brush image " + file.string() + ": " + (reason ? reason : "unknown error");
    return false;
  }
  // The stroke runs along the image's x: mask rows (v) are image columns.
  mask->width = h;
  mask->height = w;
  mask->variants = 2;  // as drawn, and mirrored across the stroke
  mask->texels.resize(2 * size_t(w) * size_t(h));
  const bool has_alpha = channels == 2 || channels == 4;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* px = data + 4 * (size_t(y) * size_t(w) + size_t(x));
      const uint8_t a = has_alpha ? px[3] : uint8_t((54u * px[0] + 183u * px[1] + 19u * px[2]) / 256u);
      mask->at(0, y, x) = a;
      mask->at(1, h - 1 - y, x) = a;
    }
  stbi_image_free(data);
  return true;
}

}  // namespace

float bristle_alpha(float u, float v, float bristles, float pressure, uint32_t variant) {
  const uint32_t seed = hash_combine(variant, 0xb7e15163u);
  const float x = 2.f * u - 1.f;
  // Sides: soft, slightly wavy, narrowing a little as the brush unloads.
  const float wobble = 0.08f * (value_noise(3.f * v, seed + 1) - 0.5f);
  const float shift = 0.05f * (value_noise(2.f * v, seed + 2) - 0.5f);
  const float half = 0.94f - 0.1f * pressure * v + wobble;
  const float sides = smoothstep(half, half - 0.16f, std::abs(x - shift));
  // Head: the brush lands with a rounded front.
  const float head = smoothstep(0.f, 0.06f, v - 0.08f * x * x);
  // Bristles: loads and lengths vary smoothly across the stroke (value noise over
  // the bristle index), so neighbouring streaks differ without hard seams.
  const float f = u * bristles;
  const float load = 0.55f + 0.45f * value_noise(f, seed + 3);
  const float reach = 1.f - pressure * (0.1f + 0.55f * value_noise(1.3f * f, seed + 4));
  const float tail = smoothstep(reach + 0.06f, reach - 0.1f, v);
  const float t = f - std::floor(f);
  const float streak = smoothstep(0.f, 0.35f, t) * smoothstep(0.f, 0.35f, 1.f - t);
  // Dry brush: the gaps between bristles open as the paint runs out.
  const float dryness = std::clamp(0.3f + 0.7f * pressure * smoothstep(0.05f, 0.9f, v), 0.f, 1.f);
  const float bristle = glm::mix(1.f, streak * load, dryness);
  const float grain = 0.8f + 0.2f * value_noise(24.f * v + 7.f * std::floor(f), seed + 5);
  return sides * head * tail * bristle * grain;
}

float flat_alpha(float u, float v, float pressure) {
  const float x = 2.f * u - 1.f;
  const float sides = smoothstep(1.f, 0.75f, std::abs(x));
  const float head = smoothstep(0.f, 0.06f, v - 0.06f * x * x);
  const float tail = smoothstep(1.f, 0.94f, v + 0.06f * x * x);
  return sides * head * tail * (1.f - 0.5f * pressure * v);
}

std::shared_ptr<AlphaMask> make_brush_mask(const StrokeEmitterDesc& e, const std::filesystem::path& base_dir,
                                           std::string* error) {
  auto mask = std::make_shared<AlphaMask>();
  if (e.brush != BrushKind::image) {
    *mask = procedural_mask(e);
    return mask;
  }
  if (e.brush_image.empty()) {
    *error = "brush \"image\" needs a brush_image";
    return nullptr;
  }
  if (!image_mask(base_dir / e.brush_image, mask.get(), error)) return nullptr;
  return mask;
}

}  // namespace inkray
