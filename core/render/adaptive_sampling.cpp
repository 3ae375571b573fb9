#include "core/render/adaptive_sampling.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

// A pixel's mean darker than this counts as this dark: near black, relative error means
// nothing on a display.
constexpr double kDarkest = 1e-3;

struct TileSums {
  double relative_var = 0.0;  // sum over the tile's pixels with both halves of Var(mean) / mean^2
  double pixels = 0.0;
  void add(const TileSums& o) { relative_var += o.relative_var, pixels += o.pixels; }
  // RMS of the pixels' relative errors. Each pixel is relative to itself, so a lamp's
  // brightness does not hide the noise of the dim rim beside it; a black tile without
  // noise has none.
  double error() const { return pixels > 0.0 ? std::sqrt(relative_var / pixels) : 0.0; }
};

std::vector<TileSums> tile_sums(const Film& film, const TileGrid& grid, const PixelWindow& active) {
  std::vector<TileSums> sums(size_t(grid.count()));
  for (int t = 0; t < grid.count(); ++t) {
    const PixelWindow w = grid.window(t);
    TileSums& s = sums[size_t(t)];
    for (int y = std::max(w.y0, active.y0); y < std::min(w.y1, active.y1); ++y)
      for (int x = std::max(w.x0, active.x0); x < std::min(w.x1, active.x1); ++x) {
        if (!film.half_count(x, y, 0) || !film.half_count(x, y, 1)) continue;
        const double a = film.half_luminance(x, y, 0), b = film.half_luminance(x, y, 1);
        const double mean = std::max(0.5 * (a + b), kDarkest);
        s.relative_var += 0.25 * (a - b) * (a - b) / (mean * mean);  // Var(mean of both) ~ (a - b)^2 / 4
        s.pixels += 1.0;
      }
  }
  return sums;
}

}  // namespace

PixelWindow TileGrid::window(int tile) const {
  const int tx = tile % tiles_x(), ty = tile / tiles_x();
  return {tx * tile_size, ty * tile_size, std::min((tx + 1) * tile_size, width),
          std::min((ty + 1) * tile_size, height)};
}

std::vector<double> tile_errors(const Film& film, const TileGrid& grid, const PixelWindow& active) {
  const std::vector<TileSums> sums = tile_sums(film, grid, active);
  std::vector<double> errors(sums.size());
  for (size_t t = 0; t < sums.size(); ++t) errors[t] = sums[t].error();
  return errors;
}

int stop_converged_tiles(const Film& film, const TileGrid& grid, const PixelWindow& active,
                         const AdaptiveSampling& settings, const std::vector<LinePixel>& lines,
                         std::vector<uint8_t>& active_tiles) {
  const std::vector<TileSums> sums = tile_sums(film, grid, active);
  const int tx = grid.tiles_x(), ty = grid.tiles_y();
  int still = 0;
  for (int t = 0; t < grid.count(); ++t) {
    if (!active_tiles[size_t(t)]) continue;
    const PixelWindow w = grid.window(t);
    if (w.x1 <= active.x0 || w.x0 >= active.x1 || w.y1 <= active.y0 || w.y0 >= active.y1) continue;
    TileSums pooled;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = t % tx + dx, y = t / tx + dy;
        if (x >= 0 && y >= 0 && x < tx && y < ty) pooled.add(sums[size_t(y * tx + x)]);
      }
    bool deciding = false;
    if (!lines.empty())
      for (int y = w.y0; y < w.y1 && !deciding; ++y)
        for (int x = w.x0; x < w.x1 && !deciding; ++x) {
          const LineKind k = lines[size_t(y) * size_t(grid.width) + size_t(x)].kind;
          deciding = k == LineKind::probing || k == LineKind::finding;
        }
    const bool own_sampled = sums[size_t(t)].pixels > 0.0;
    if (!deciding && own_sampled && pooled.error() < settings.threshold &&
        sums[size_t(t)].error() < settings.threshold) {
      active_tiles[size_t(t)] = 0;
      continue;
    }
    ++still;
  }
  return still;
}

}  // namespace inkray
