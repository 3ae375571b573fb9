// Adaptive sampling: which tiles of a film still take samples (docs/architecture.md,
// "Adaptive sampling"). A tile stops once its estimated relative error, and that of
// the 3 x 3 tiles around it pooled, are both below the threshold. The pooled estimate
// reads about 2300 pixels, so no tile stops on one lucky draw of its own, and a
// decision is taken only with equal passes in both half-buffers (their difference
// is the estimate). A stopped tile stays stopped: its pixels' means stay unbiased,
// only their sample counts differ.
#pragma once

#include "core/film/film.h"
#include "core/npr/outlines/line_sampling.h"

#include <cstdint>
#include <vector>

namespace inkray {

struct AdaptiveSampling {
  double threshold = 0.0;  // relative error at which a tile stops; 0: off
  uint32_t min_spp = 16;   // passes every tile takes before it may stop
  bool on() const { return threshold > 0.0; }
};

// A film's tiles of `tile_size` pixels, row by row.
struct TileGrid {
  int width = 0, height = 0, tile_size = 16;
  int tiles_x() const { return (width + tile_size - 1) / tile_size; }
  int tiles_y() const { return (height + tile_size - 1) / tile_size; }
  int count() const { return tiles_x() * tiles_y(); }
  PixelWindow window(int tile) const;
};

// Per tile, the RMS over its pixels of each pixel's estimated relative error (from the
// halves' difference, relative to the pixel's own mean, at least 1e-3): 0 for tiles
// without two halves.
std::vector<double> tile_errors(const Film& film, const TileGrid& grid, const PixelWindow& active);

// Clears active[t] for tiles of `active` window that may stop: both estimates below the
// threshold and no pixel of the tile still deciding its lines (`lines` empty without lines).
// Returns how many tiles are still active.
int stop_converged_tiles(const Film& film, const TileGrid& grid, const PixelWindow& active,
                         const AdaptiveSampling& settings, const std::vector<LinePixel>& lines,
                         std::vector<uint8_t>& active_tiles);

}  // namespace inkray
