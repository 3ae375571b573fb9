// Per-sample source of random numbers for the path loop. Values depend only
// on (pixel, sample index, dimension, seed), never on what was drawn before,
// so a decision can draw its own fixed dimension in any order.
#pragma once

#include "core/sampling/sobol.h"

namespace inkray {

// The pair whose x is a camera sample's instant of the shutter (Sampler::get_time).
// Far above the path's, the toon lights' (1 << 24) and the outline stencil's
// (1 << 25) pairs, so drawing it changes no other decision's value.
inline constexpr uint32_t kShutterPair = 1u << 26;

class Sampler {
 public:
  Sampler(uint32_t pixel_x, uint32_t pixel_y, uint32_t sample_index, uint32_t seed)
      : pixel_seed_(hash_combine(pixel_x, pixel_y, seed)), index_(sample_index) {}

  // A stratified 2D value: dimension pair `pair` of the Owen-scrambled Sobol set.
  Vec2 get_pair(uint32_t pair) const { return owen_sobol_2d(index_, pixel_seed_, pair); }
  // The same pixel's value for another sample index: a loop over a pixel's
  // points hashes the pixel once.
  Vec2 get_pair_at(uint32_t sample_index, uint32_t pair) const {
    return owen_sobol_2d(sample_index, pixel_seed_, pair);
  }
  // An unstratified value from a counter-based hash, for decisions that gain
  // nothing from stratification (Russian roulette).
  float get_hashed(uint32_t dimension) const {
    return u32_to_unit_float(hash_combine(pixel_seed_, index_, dimension));
  }
  // The sample's instant of the shutter, in [0, 1): stratified over the pixel's
  // samples like every pair. Drawn only when the shutter is open for a time.
  float get_time() const { return get_pair(kShutterPair).x; }
  uint32_t sample_index() const { return index_; }

 private:
  uint32_t pixel_seed_;
  uint32_t index_;
};

}  // namespace inkray
