#include "core/npr/outlines/line_sampling.h"

#include "core/math/hash.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

// Share of samples that keep probing a pixel where no ray nearby has seen a
// line, one beside a line whose own rays have seen none in kMinSolidRays and
// more, and one inside a solid line.
constexpr float kQuietRate = 1.f / 16.f;
constexpr float kSolidRate = 1.f / 4.f;
constexpr float kBesideRate = 1.f / 4.f;
// A pixel counts as solid once its opacity, less two standard errors, stays
// above full opacity by this margin.
constexpr float kSolidMargin = 0.25f;
constexpr uint32_t kMinSolidRays = 16;
// Rays per sample on a line's edge: `quality` for each this many pixels of
// stencil radius (rounded, at least one), so wide lines' long soft edges
// converge as fast as thin ones' while lines a few pixels wide trace no more
// than full sampling would.
constexpr float kEdgeRadiusPerRay = 2.f;
constexpr int kMaxEdgeMultiple = 8;
constexpr int kMaxRays = 64;

// Two rounds of the mixer over the packed keys: decorrelated enough to pick
// samples, and cheap, since every sample of every pixel asks.
bool draws(float rate, uint32_t x, uint32_t y, uint32_t pass, uint32_t seed) {
  const uint32_t pixel = hash_u32(x ^ (y << 16) ^ (y >> 16) ^ (seed * 0x9e3779b9u));
  return u32_to_unit_float(hash_u32(pixel + pass * 0x85ebca6bu + 0x11e5u)) < rate;
}

}  // namespace

void mark_line_neighbourhoods(const Film& film, const LineSetup& setup, std::vector<uint8_t>& near_line) {
  const int w = film.width(), h = film.height();
  // The stencil reaches this many film pixels.
  const int reach = int(std::ceil(setup.nominal_radius_px / setup.film_pixel));
  // Separable dilation: rows, then columns.
  std::vector<uint8_t> rows(size_t(w) * size_t(h), 0);
  for (int y = 0; y < h; ++y) {
    int last = -1 << 30;  // x of the last pixel with a break seen, scanning right
    for (int x = 0; x < w; ++x) {
      if (film.line_sum(x, y).hit_rays > 0.f) last = x;
      if (x - last <= reach) rows[size_t(y) * size_t(w) + size_t(x)] = 1;
    }
    last = 1 << 30;
    for (int x = w - 1; x >= 0; --x) {
      if (film.line_sum(x, y).hit_rays > 0.f) last = x;
      if (last - x <= reach) rows[size_t(y) * size_t(w) + size_t(x)] = 1;
    }
  }
  near_line.assign(size_t(w) * size_t(h), 0);
  for (int x = 0; x < w; ++x) {
    int last = -1 << 30;
    for (int y = 0; y < h; ++y) {
      if (rows[size_t(y) * size_t(w) + size_t(x)]) last = y;
      if (y - last <= reach) near_line[size_t(y) * size_t(w) + size_t(x)] = 1;
    }
    last = 1 << 30;
    for (int y = h - 1; y >= 0; --y) {
      if (rows[size_t(y) * size_t(w) + size_t(x)]) last = y;
      if (last - y <= reach) near_line[size_t(y) * size_t(w) + size_t(x)] = 1;
    }
  }
}

int stencil_rays(const LineSetup& setup, const LineSample& sum, uint32_t samples, bool near_line, uint32_t x,
                 uint32_t y, uint32_t pass, uint32_t seed) {
  const int quality = setup.quality;
  if (!setup.adaptive || samples < kLineProbeSamples || sum.rays <= 0.f) return quality;
  if (!near_line) return draws(kQuietRate, x, y, pass, seed) ? quality : 0;
  if (sum.hit_rays <= 0.f && sum.rays >= float(kMinSolidRays)) return draws(kBesideRate, x, y, pass, seed) ? quality : 0;
  // Inside a solid line: every type's opacity is clamped with a margin to spare.
  if (sum.rays >= float(kMinSolidRays)) {
    const float p = std::min(sum.hit_rays / sum.rays, 1.f);
    const float standard_error = std::sqrt(p * (1.f - p) / sum.rays);
    float solid = 0.f;
    for (const float c : sum.coverage) solid = std::max(solid, kLineGain * c / sum.rays);
    // The weight of a hit ray scales the error alike.
    const float scale = sum.hit_rays > 0.f ? sum.weight / sum.hit_rays : 1.f;
    if (solid - 2.f * kLineGain * scale * standard_error >= 1.f + kSolidMargin)
      return draws(kSolidRate, x, y, pass, seed) ? quality : 0;
  }
  const int multiple = std::clamp(int(std::lround(setup.nominal_radius_px / kEdgeRadiusPerRay)), 1, kMaxEdgeMultiple);
  return std::min(quality * multiple, kMaxRays);
}

}  // namespace inkray
