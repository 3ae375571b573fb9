// Per-sample source of random numbers for the path loop. Each call consumes
// the next dimension pair; values depend only on (pixel, sample, dimension,
// seed), never on what other samples drew.
#pragma once

#include "core/sampling/sobol.h"

namespace inkray {

class Sampler {
 public:
  Sampler(uint32_t pixel_x, uint32_t pixel_y, uint32_t sample_index, uint32_t seed)
      : pixel_seed_(hash_combine(pixel_x, pixel_y, seed)), index_(sample_index) {}

  Vec2 get_2d() { return owen_sobol_2d(index_, pixel_seed_, pair_++); }
  // A 1D value uses its own pair so that dimension numbering stays simple.
  float get_1d() { return get_2d().x; }
  // Skips to a fixed dimension, so the same decision uses the same dimension
  // regardless of what an earlier bounce consumed.
  void start_dimension(uint32_t pair) { pair_ = pair; }
  uint32_t sample_index() const { return index_; }

 private:
  uint32_t pixel_seed_;
  uint32_t index_;
  uint32_t pair_ = 0;
};

}  // namespace inkray
