#include "core/npr/outlines/line_gain.h"

#include "core/world/line_types.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace inkray {
namespace {

// Fraction of a unit disc beyond a straight edge at distance x from its centre.
double edge_coverage(double x) {
  x = std::min(std::abs(x), 1.0);
  return (std::acos(x) - x * std::sqrt(1.0 - x * x)) / kPi;
}

// Integral of edge_coverage(|u|) from 0 to u, signed: the coverage summed over
// a stretch of pixel positions in closed form.
double coverage_integral(double u) {
  const double x = std::min(std::abs(u), 1.0);
  const double s = std::sqrt(1.0 - x * x);
  const double f = (x * std::acos(x) - s + 1.0 - (1.0 - s * s * s) / 3.0) / kPi;
  return u < 0.0 ? -f : f;
}

// Opacity summed across a straight edge (ink per unit length, in radii) in the
// limit of tiny pixels: integral of min(1, kLineGain * coverage).
double fine_ink() {
  constexpr int kSteps = 4096;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double x = (i + 0.5) / kSteps;
    sum += std::min(1.0, double(kLineGain) * edge_coverage(x));
  }
  return 2.0 * sum / kSteps;  // both sides of the edge
}

// The same for pixels `p` radii wide and `gain`, averaged over where the edge falls in a pixel.
double pixel_ink(double p, double gain) {
  constexpr int kOffsets = 32;
  double total = 0.0;
  for (int o = 0; o < kOffsets; ++o) {
    const double offset = (o + 0.5) / kOffsets * p;
    // Pixels [k p - offset, (k + 1) p - offset) for every k that touches [-1, 1].
    const int k0 = int(std::floor((-1.0 + offset) / p)) - 1, k1 = int(std::ceil((1.0 + offset) / p)) + 1;
    for (int k = k0; k <= k1; ++k) {
      const double a = k * p - offset, b = a + p;
      const double mean = (coverage_integral(b) - coverage_integral(a)) / p;
      total += p * std::min(1.0, gain * mean);
    }
  }
  return total / kOffsets;
}

// Gains at pixel_over_radius = 2^(kLow + i / kPerOctave).
constexpr int kLow = -5, kHigh = 7, kPerOctave = 4, kEntries = (kHigh - kLow) * kPerOctave + 1;

std::array<float, kEntries> make_table() {
  std::array<float, kEntries> table{};
  const double target = fine_ink();
  for (int i = 0; i < kEntries; ++i) {
    const double p = std::exp2(kLow + double(i) / kPerOctave);
    double lo = 0.5, hi = kLineGain;         // ink grows with the gain
    for (int step = 0; step < 24; ++step) {  // 2^-24 of the bracket: float precision
      const double mid = 0.5 * (lo + hi);
      (pixel_ink(p, mid) < target ? lo : hi) = mid;
    }
    table[size_t(i)] = float(0.5 * (lo + hi));
  }
  return table;
}

}  // namespace

float ink_preserving_gain(float pixel_over_radius) {
  static const std::array<float, kEntries> table = make_table();
  if (!(pixel_over_radius > 0.f)) return kLineGain;
  const float at = (std::log2(pixel_over_radius) - float(kLow)) * float(kPerOctave);
  if (at <= 0.f) return table.front();
  if (at >= float(kEntries - 1)) return table.back();
  const int i = int(at);
  const float t = at - float(i);
  return table[size_t(i)] + t * (table[size_t(i) + 1] - table[size_t(i)]);
}

}  // namespace inkray
