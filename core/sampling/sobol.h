// Owen-scrambled Sobol samples, padded in 2D pairs (Burley 2020, "Practical
// Hash-based Owen Scrambling"). Every value is a pure function of
// (pixel, sample index, dimension, seed): images do not depend on thread
// count, tile order or the order samples are drawn in.
#pragma once

#include "core/math/hash.h"
#include "core/math/types.h"

#include <bit>
#include <cstdint>

namespace inkray {

inline uint32_t reverse_bits(uint32_t v) {
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
  v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
  return (v >> 16) | (v << 16);
}

// The first two Sobol dimensions form a (0,2)-sequence: every aligned block of
// 2^k points has one point in each elementary interval of area 2^-k.
// Dimension 0 is the bit-reversed index; dimension 1 is generated here directly
// in bit-reversed form (direction numbers reversed), which is the form the
// scramble below works in.
inline uint32_t sobol_dim0_reversed(uint32_t index) { return index; }
namespace detail {
// Sobol dimension 1 is linear over GF(2): the XOR of one table entry per index
// byte. Four 256-entry tables replace a loop over all 32 index bits.
struct SobolDim1Tables {
  uint32_t t[4][256];
  constexpr SobolDim1Tables() : t{} {
    uint32_t v[32] = {};
    v[0] = 1u;  // reverse of 1 << 31; v ^= v >> 1 becomes v ^= v << 1
    for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] << 1);
    for (int byte = 0; byte < 4; ++byte)
      for (uint32_t b = 0; b < 256; ++b) {
        uint32_t r = 0;
        for (int bit = 0; bit < 8; ++bit)
          if (b & (1u << bit)) r ^= v[8 * byte + bit];
        t[byte][b] = r;
      }
  }
};
inline constexpr SobolDim1Tables kSobolDim1{};
}  // namespace detail

inline uint32_t sobol_dim1_reversed(uint32_t index) {
  const auto& t = detail::kSobolDim1.t;
  return t[0][index & 255u] ^ t[1][(index >> 8) & 255u] ^ t[2][(index >> 16) & 255u] ^ t[3][index >> 24];
}
inline uint32_t sobol_dim0(uint32_t index) { return reverse_bits(sobol_dim0_reversed(index)); }
inline uint32_t sobol_dim1(uint32_t index) { return reverse_bits(sobol_dim1_reversed(index)); }

// Laine-Karras style permutation: bit i of the output depends only on bits <= i
// of the input. Applied to bit-reversed values it is a nested uniform (Owen)
// scramble: each bit flips depending only on the more significant bits.
inline uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}
inline uint32_t nested_uniform_scramble(uint32_t x, uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

// A cheap bijective mixer (lowbias32) to derive independent seeds.
inline uint32_t mix_seed(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// Sample `index` of the 2D point set for dimension pair `pair` of one pixel.
// The index shuffle maps every aligned block of 2^k indices onto an aligned
// block, so each prefix of 2^k samples is still a (0,k,2)-net; Owen scrambling
// of each coordinate keeps the net property. Everything stays in bit-reversed
// form until the end, which saves four of the six bit reversals.
inline Vec2 owen_sobol_2d(uint32_t index, uint32_t pixel_seed, uint32_t pair) {
  const uint32_t pair_seed = mix_seed(pixel_seed ^ (pair * 0x9e3779b9u));
  const uint32_t shuffled = reverse_bits(laine_karras_permutation(reverse_bits(index), pair_seed));
  const uint32_t x = reverse_bits(
      laine_karras_permutation(sobol_dim0_reversed(shuffled), mix_seed(pair_seed ^ 0x68bc21ebu)));
  const uint32_t y = reverse_bits(
      laine_karras_permutation(sobol_dim1_reversed(shuffled), mix_seed(pair_seed ^ 0x02e5be93u)));
  return {u32_to_unit_float(x), u32_to_unit_float(y)};
}

}  // namespace inkray
