// Counter-based hashing: every random decision derives from integer keys
// (pixel, sample, dimension, seed), never from generator state.
#pragma once

#include <cstdint>

namespace inkray {

// Bit mixer from "Hash Functions for GPU Rendering" (Jarzynski, Olano 2020), pcg-based.
inline uint32_t hash_u32(uint32_t v) {
  uint32_t state = v * 747796405u + 2891336453u;
  uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
inline uint32_t hash_combine(uint32_t a, uint32_t b) {
  return hash_u32(a ^ (hash_u32(b) + 0x9e3779b9u + (a << 6) + (a >> 2)));
}
inline uint32_t hash_combine(uint32_t a, uint32_t b, uint32_t c) {
  return hash_combine(hash_combine(a, b), c);
}
inline uint32_t hash_combine(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  return hash_combine(hash_combine(a, b, c), d);
}
// Map 32 random bits to a float in [0,1).
inline float u32_to_unit_float(uint32_t v) { return float(v >> 8) * 0x1p-24f; }

// Small counter-free generator for non-sample uses (scene construction, tests).
struct Pcg32 {
  uint64_t state = 0x853c49e6748fea9bULL;
  uint64_t inc = 0xda3e39cb94b95bdbULL;
  explicit Pcg32(uint64_t seed = 0, uint64_t stream = 1) {
    state = 0u;
    inc = (stream << 1u) | 1u;
    next_u32();
    state += seed;
    next_u32();
  }
  uint32_t next_u32() {
    uint64_t old = state;
    state = old * 6364136223846793005ULL + inc;
    uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
  }
  float next_float() { return u32_to_unit_float(next_u32()); }
};

}  // namespace inkray
