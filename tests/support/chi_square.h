// Chi-square goodness-of-fit of a direction sampler against its pdf, after
// pbrt-v3's src/tests/bsdfs.cpp and Mitsuba's chi2 test. Header-only because
// the test build compiles only *_test.cpp files.
#pragma once

#include "core/math/hash.h"
#include "core/math/types.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace inkray::test_support {

// ---- Regularised incomplete gamma (Numerical Recipes 6.2), in double: the
// p-value of a chi-square statistic with k dof is Q(k/2, x/2).

inline double gamma_p_series(double a, double x) {
  double ap = a, term = 1.0 / a, sum = term;
  for (int n = 0; n < 100000; ++n) {
    ap += 1.0;
    term *= x / ap;
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-15) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Lentz's method for the continued fraction of Q, converging fast for x > a + 1.
inline double gamma_q_continued_fraction(double a, double x) {
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 100000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

// Q(a, x) = Gamma(a, x) / Gamma(a), the upper tail.
inline double regularized_gamma_q(double a, double x) {
  if (x <= 0.0) return 1.0;
  if (std::isinf(x)) return 0.0;
  return x < a + 1.0 ? 1.0 - gamma_p_series(a, x) : gamma_q_continued_fraction(a, x);
}

inline double chi_square_p_value(double statistic, int dof) {
  return dof > 0 ? regularized_gamma_q(0.5 * dof, 0.5 * statistic) : 1.0;
}

// Per-test significance that keeps the family-wise false-alarm rate at alpha
// over num_tests independent tests.
inline double sidak_significance(double alpha, int num_tests) {
  return 1.0 - std::pow(1.0 - alpha, 1.0 / num_tests);
}

// ---- Adaptive Simpson quadrature (pbrt-v3's test helper), nested for 2D.

template <class F>
double adaptive_simpson_step(const F& f, double a, double b, double c, double fa, double fb, double fc,
                             double whole, double eps, int depth) {
  const double d = 0.5 * (a + b), e = 0.5 * (b + c);
  const double fd = f(d), fe = f(e);
  const double h = c - a;
  const double left = h / 12.0 * (fa + 4.0 * fd + fb);
  const double right = h / 12.0 * (fb + 4.0 * fe + fc);
  const double both = left + right;
  if (depth <= 0 || std::abs(both - whole) < 15.0 * eps) return both + (both - whole) / 15.0;
  return adaptive_simpson_step(f, a, d, b, fa, fd, fb, left, 0.5 * eps, depth - 1) +
         adaptive_simpson_step(f, b, e, c, fb, fe, fc, right, 0.5 * eps, depth - 1);
}

template <class F>
double adaptive_simpson(const F& f, double x0, double x1, double eps, int max_depth) {
  const double b = 0.5 * (x0 + x1);
  const double fa = f(x0), fb = f(b), fc = f(x1);
  const double whole = (x1 - x0) / 6.0 * (fa + 4.0 * fb + fc);
  return adaptive_simpson_step(f, x0, b, x1, fa, fb, fc, whole, eps, max_depth);
}

template <class F>
double adaptive_simpson_2d(const F& f, double x0, double y0, double x1, double y1, double eps,
                           int max_depth) {
  const auto row = [&](double y) {
    return adaptive_simpson([&](double x) { return f(x, y); }, x0, x1, eps, max_depth);
  };
  return adaptive_simpson(row, y0, y1, eps, max_depth);
}

// ---- Sphere histogram over (cos theta, phi): cells of equal solid angle, and
// no Jacobian when integrating a solid-angle pdf over them.

struct SphereGrid {
  int cos_bins = 40;
  int phi_bins = 80;

  int cells() const { return cos_bins * phi_bins; }
  int cell_of(const Vec3& w) const {
    const float z = glm::clamp(w.z / glm::length(w), -1.f, 1.f);
    float phi = std::atan2(w.y, w.x);
    if (phi < 0.f) phi += 2.f * kPi;
    const int i = std::min(int((z + 1.f) * 0.5f * float(cos_bins)), cos_bins - 1);
    const int j = std::min(int(phi * kInv2Pi * float(phi_bins)), phi_bins - 1);
    return i * phi_bins + j;
  }
  static Vec3 direction(double cos_theta, double phi) {
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    return Vec3(float(sin_theta * std::cos(phi)), float(sin_theta * std::sin(phi)), float(cos_theta));
  }
};

struct Histogram {
  std::vector<double> counts;
  long rejected = 0;  // samples the sampler declined to produce
};

// sample(rng) returns an optional direction; each call is one attempt.
template <class SampleFn>
Histogram sample_histogram(const SphereGrid& grid, long sample_count, uint64_t seed, SampleFn&& sample) {
  Histogram h{std::vector<double>(grid.cells(), 0.0), 0};
  Pcg32 rng(seed);
  for (long k = 0; k < sample_count; ++k) {
    if (const std::optional<Vec3> w = sample(rng))
      h.counts[grid.cell_of(*w)] += 1.0;
    else
      ++h.rejected;
  }
  return h;
}

// Expected counts: sample_count times the pdf integrated over each cell. The
// absolute tolerance is set so that the quadrature error of a cell is well
// below one count.
template <class PdfFn>
std::vector<double> expected_counts(const SphereGrid& grid, long sample_count, PdfFn&& pdf) {
  std::vector<double> expected(grid.cells());
  const double dz = 2.0 / grid.cos_bins, dphi = 2.0 * kPi / grid.phi_bins;
  const double eps = 0.1 / double(sample_count);
  for (int i = 0; i < grid.cos_bins; ++i) {
    for (int j = 0; j < grid.phi_bins; ++j) {
      const auto f = [&](double phi, double z) { return double(pdf(SphereGrid::direction(z, phi))); };
      const double integral =
          adaptive_simpson_2d(f, j * dphi, -1.0 + i * dz, (j + 1) * dphi, -1.0 + (i + 1) * dz, eps, 6);
      expected[i * grid.phi_bins + j] = integral * double(sample_count);
    }
  }
  return expected;
}

struct ChiSquareResult {
  double statistic = 0.0;
  int dof = 0;
  double p_value = 1.0;
  int pooled_cells = 0;
  std::string error;  // set when a sample fell where the pdf is zero
};

// Pearson's statistic with cells of expected count below min_expected pooled
// into one, so the chi-square approximation holds (Mitsuba's procedure).
inline ChiSquareResult chi_square(const std::vector<double>& observed, const std::vector<double>& expected,
                                  double min_expected = 5.0) {
  std::vector<size_t> order(observed.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
  ChiSquareResult r;
  double pooled_obs = 0.0, pooled_exp = 0.0;
  for (const size_t c : order) {
    if (expected[c] <= 0.0 && observed[c] > 0.0) {
      r.error = std::to_string(long(observed[c])) + " samples in cell " + std::to_string(c) +
                " where the pdf integrates to zero";
      r.statistic = kInfinity;
      r.p_value = 0.0;
      return r;
    }
    if (expected[c] < min_expected) {
      pooled_obs += observed[c];
      pooled_exp += expected[c];
      ++r.pooled_cells;
    } else {
      const double diff = observed[c] - expected[c];
      r.statistic += diff * diff / expected[c];
      ++r.dof;
    }
  }
  if (pooled_exp > 0.0) {
    r.statistic += (pooled_obs - pooled_exp) * (pooled_obs - pooled_exp) / pooled_exp;
    ++r.dof;
  }
  r.dof -= 1;  // the total is fixed by the sample count
  r.p_value = chi_square_p_value(r.statistic, r.dof);
  return r;
}

}  // namespace inkray::test_support
