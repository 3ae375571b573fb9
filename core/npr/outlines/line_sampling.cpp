#include "core/npr/outlines/line_sampling.h"

#include "core/math/hash.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

// Share of samples that keep probing a pixel where no probe nearby has seen a
// line, one beside a line whose own first kMinSolidRays rays have seen none,
// and one inside a solid line.
constexpr float kQuietRate = 1.f / 16.f;
constexpr float kSolidRate = 1.f / 4.f;
constexpr float kBesideRate = 1.f / 4.f;
// A pixel near a line decides once it has traced this many rays: solid when
// its opacity, less two standard errors, stays above full opacity by a margin.
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
// samples, and cheap, since every sample of every pixel asks. The first round
// is the pixel's own.
uint32_t pixel_key(uint32_t x, uint32_t y, uint32_t seed) {
  return hash_u32(x ^ (y << 16) ^ (y >> 16) ^ (seed * 0x9e3779b9u));
}
bool draws_at(float rate, uint32_t key, uint32_t pass) {
  return u32_to_unit_float(hash_u32(key + pass * 0x85ebca6bu + 0x11e5u)) < rate;
}
bool draws(float rate, uint32_t x, uint32_t y, uint32_t pass, uint32_t seed) {
  return draws_at(rate, pixel_key(x, y, seed), pass);
}

int edge_rays(const LineSetup& setup) {
  const int multiple =
      std::clamp(int(std::lround(setup.nominal_radius_px / kEdgeRadiusPerRay)), 1, kMaxEdgeMultiple);
  return std::min(setup.quality * multiple, kMaxRays);
}

}  // namespace

int line_reach(const LineSetup& setup) {
  return std::max(int(std::ceil(setup.nominal_radius_px / setup.film_pixel)), 0);
}

void mark_line_neighbourhoods(std::vector<LinePixel>& pixels, int w, int h, const LineSetup& setup,
                              const PixelWindow& window) {
  const int reach = line_reach(setup);
  const auto at = [w](int x, int y) { return size_t(y) * size_t(w) + size_t(x); };
  // Separable dilation: rows, then columns.
  std::vector<uint8_t> rows(size_t(w) * size_t(h), 0), near(size_t(w) * size_t(h), 0);
  for (int y = 0; y < h; ++y) {
    int last = -1 << 30;  // x of the last pixel with a break seen, scanning right
    for (int x = 0; x < w; ++x) {
      if (pixels[at(x, y)].hit_rays > 0.f) last = x;
      if (x - last <= reach) rows[at(x, y)] = 1;
    }
    last = 1 << 30;
    for (int x = w - 1; x >= 0; --x) {
      if (pixels[at(x, y)].hit_rays > 0.f) last = x;
      if (last - x <= reach) rows[at(x, y)] = 1;
    }
  }
  for (int x = 0; x < w; ++x) {
    int last = -1 << 30;
    for (int y = 0; y < h; ++y) {
      if (rows[at(x, y)]) last = y;
      if (y - last <= reach) near[at(x, y)] = 1;
    }
    last = 1 << 30;
    for (int y = h - 1; y >= 0; --y) {
      if (rows[at(x, y)]) last = y;
      if (last - y <= reach) near[at(x, y)] = 1;
    }
  }
  for (int y = std::max(window.y0, 0); y < std::min(window.y1, h); ++y)
    for (int x = std::max(window.x0, 0); x < std::min(window.x1, w); ++x) {
      LinePixel& p = pixels[at(x, y)];
      if (p.kind == LineKind::probing) p.kind = near[at(x, y)] ? LineKind::finding : LineKind::quiet;
    }
}

namespace {

// What a pixel near a line is, from its own rays.
LineKind decide(const LinePixel& p) {
  const float rays = float(p.rays);
  if (p.hit_rays <= 0.f) return LineKind::beside;
  // Inside a solid line: every type's opacity is clamped with a margin to spare.
  const float hit = std::min(p.hit_rays / rays, 1.f);
  const float standard_error = std::sqrt(hit * (1.f - hit) / rays);
  float solid = 0.f;
  for (const float c : p.coverage) solid = std::max(solid, kLineGain * c / rays);
  // The weight of a hit ray scales the error alike.
  const float scale = p.weight / p.hit_rays;
  if (solid - 2.f * kLineGain * scale * standard_error >= 1.f + kSolidMargin) return LineKind::solid;
  return LineKind::edge;
}

}  // namespace

int stencil_rays(const LineSetup& setup, LinePixel& pixel, uint32_t x, uint32_t y, uint32_t pass,
                 uint32_t seed) {
  const int quality = setup.quality;
  if (!setup.adaptive || pass < kLineProbeSamples || pixel.kind == LineKind::probing) return quality;
  if (pixel.kind == LineKind::finding && pixel.rays >= kMinSolidRays) pixel.kind = decide(pixel);
  switch (pixel.kind) {
    case LineKind::quiet:
      return draws(kQuietRate, x, y, pass, seed) ? quality : 0;
    case LineKind::beside:
      return draws(kBesideRate, x, y, pass, seed) ? quality : 0;
    case LineKind::solid:
      return draws(kSolidRate, x, y, pass, seed) ? quality : 0;
    case LineKind::probing:
    case LineKind::finding:
    case LineKind::edge:
      break;
  }
  return edge_rays(setup);
}

uint32_t stencil_rays_between(const LineSetup& setup, const LinePixel& pixel, uint32_t x, uint32_t y,
                              uint32_t first, uint32_t end, uint32_t seed) {
  const uint32_t quality = uint32_t(setup.quality);
  float rate = 1.f;
  switch (setup.adaptive ? pixel.kind : LineKind::probing) {
    case LineKind::probing:
      return quality * (end - first);
    case LineKind::edge:
      return uint32_t(edge_rays(setup)) * (end - first);
    case LineKind::quiet:
      rate = kQuietRate;
      break;
    case LineKind::beside:
      rate = kBesideRate;
      break;
    case LineKind::solid:
      rate = kSolidRate;
      break;
    case LineKind::finding: {
      LinePixel p = pixel;  // decides on the way: count sample by sample
      for (uint32_t pass = first; pass < end; ++pass)
        p.rays += uint32_t(stencil_rays(setup, p, x, y, pass, seed));
      return p.rays - pixel.rays;
    }
  }
  const uint32_t key = pixel_key(x, y, seed);
  uint32_t samples = 0;
  for (uint32_t pass = first; pass < end; ++pass) samples += draws_at(rate, key, pass) ? 1u : 0u;
  return quality * samples;
}

void record_line_sample(const LineSetup& setup, LinePixel& pixel, const LineSample& sample) {
  const bool pending = line_decision_pending(setup, pixel);
  pixel.rays += uint32_t(sample.rays);
  if (!pending) return;
  pixel.hit_rays += sample.hit_rays;
  pixel.weight += sample.weight;
  for (size_t t = 0; t < pixel.coverage.size(); ++t) pixel.coverage[t] += sample.coverage[t];
}

}  // namespace inkray
