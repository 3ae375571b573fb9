// The denoiser (docs/architecture.md, "Denoising"). Each half-buffer is filtered on
// its own by a cascade of edge-avoiding a-trous passes (Dammertz et al. 2010, with
// the variance-guided colour weight of Schied et al. 2017), so every pixel has a
// ladder of estimates from the raw mean to a wide blur. Which rung a pixel takes is
// chosen by cross-validation between the halves (in the spirit of Rousselle et al.
// 2011/2013): a half filtered alone is compared with the other, independent half, and
// E[(F(A) - B)^2] = MSE(F(A)) + Var(B), the same Var(B) for every rung, so the rung
// with the smallest smoothed squared difference has the smallest error. The same
// numbers estimate the denoised image's error without a reference.
#include "core/film/denoise.h"

#include "core/math/hash.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace inkray {
namespace {

constexpr int kLevels = 5;              // a-trous passes: steps 1, 2, 4, 8, 16 (a 63-pixel reach)
constexpr float kSigmaColor = 4.f;      // a neighbour this many standard deviations off weighs e^-1
constexpr float kSigmaDepth = 2.f;      // depth difference allowed over the expected slope
constexpr float kAlbedoScale = 20.f;    // 1/sigma^2 of the albedo difference
constexpr float kBandTolerance = 0.1f;  // toon band values farther apart are different bands
constexpr float kDemodulateEps = 0.02f;
constexpr int kErrorRadius = 4;  // the cross-validation error is averaged over 9 x 9 pixels

// What the weights read of a pixel.
struct Guide {
  Vec3 normal{0.f};                // unit; zero where nothing was hit
  float depth = 0.f, slope = 0.f;  // slope: expected |depth change| per pixel step
  Color albedo{0.f};
  Color divisor{1.f};  // demodulation: radiance / divisor is filtered, then multiplied back
  float band = -1.f;
  int object = -1, material = -1;
  bool sampled = false;  // both halves have samples
  // Both halves agree exactly on a value that is not black: no noise to remove (an
  // emitter, the sky, a noise-free render). Kept as it is and lent to no neighbour:
  // an emitter's anti-aliased rim must not be pulled to its full brightness.
  bool exact = false;
};

struct Features {
  bool normal, depth, albedo, band, object, material;
};

// Squares `x` five times: x^32, a sharp cosine lobe without pow.
float pow32(float x) {
  x *= x;
  x *= x;
  x *= x;
  x *= x;
  return x * x;
}

// A box average of radius r (separable), the same size as `v`.
std::vector<float> box_blur(const std::vector<float>& v, int w, int h, int r, ThreadBudget* pool,
                            const Cancel& cancel) {
  std::vector<float> tmp(v.size()), out(v.size());
  parallel_rows(
      h, pool,
      [&](int y) {
        const float* row = &v[size_t(y) * size_t(w)];
        for (int x = 0; x < w; ++x) {
          float s = 0.f;
          int n = 0;
          for (int k = std::max(0, x - r); k <= std::min(w - 1, x + r); ++k, ++n) s += row[k];
          tmp[size_t(y) * size_t(w) + size_t(x)] = s / float(n);
        }
      },
      cancel);
  parallel_rows(
      h, pool,
      [&](int y) {
        for (int x = 0; x < w; ++x) {
          float s = 0.f;
          int n = 0;
          for (int k = std::max(0, y - r); k <= std::min(h - 1, y + r); ++k, ++n)
            s += tmp[size_t(k) * size_t(w) + size_t(x)];
          out[size_t(y) * size_t(w) + size_t(x)] = s / float(n);
        }
      },
      cancel);
  return out;
}

std::vector<Guide> make_guides(const Film& film, const Features& f, ThreadBudget* pool,
                               const Cancel& cancel) {
  const int w = film.width(), h = film.height();
  const size_t n = size_t(w) * size_t(h);
  std::vector<Guide> g(n);
  const RgbImage albedo = film.resolve_aov(Aov::albedo), normal = film.resolve_aov(Aov::normal),
                 depth = film.resolve_aov(Aov::depth), band = film.resolve_aov(Aov::toon_band),
                 object = film.resolve_aov(Aov::object_id), material = film.resolve_aov(Aov::material_id);
  parallel_rows(
      h, pool,
      [&](int y) {
        for (int x = 0; x < w; ++x) {
          const size_t i = size_t(y) * size_t(w) + size_t(x);
          Guide& p = g[i];
          const FilmPixel fp = film.pixel(x, y);
          p.sampled = fp.count[0] > 0 && fp.count[1] > 0;
          if (p.sampled) {
            const glm::dvec3 a = fp.sum[0] / double(fp.count[0]), b = fp.sum[1] / double(fp.count[1]);
            p.exact = a == b && a != glm::dvec3(0.0);
          }
          // An anti-aliased edge's samples saw two ids: it lends to and borrows from
          // other edge pixels only, so it is smoothed along the edge, not into either side.
          if (f.object) p.object = (fp.ids_mixed & 1u) ? -3 : int(object.pixels[i].x);
          if (f.material) p.material = (fp.ids_mixed & 2u) ? -3 : int(material.pixels[i].x);
          if (f.band) p.band = band.pixels[i].x;
          const float len = glm::length(normal.pixels[i]);
          if (f.normal && len > 0.f) p.normal = normal.pixels[i] / len;
          if (f.depth) p.depth = depth.pixels[i].x;
          if (f.albedo) {
            p.albedo = albedo.pixels[i];
            // Nothing hit, or black: nothing to divide by, the radiance is filtered as it is.
            if (max_component(p.albedo) > 0.f) p.divisor = p.albedo + Color(kDemodulateEps);
          }
        }
      },
      cancel);
  // A pixel between two edge pixels (along a row, a column or a diagonal) is on the edge
  // too, whichever ids its own samples happened to draw: under a lamp's rim a pixel whose
  // samples all missed the rim's few percent is otherwise cut off from the ones that drew
  // it, and neither side can average to the row's mean.
  constexpr int kAxes[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  std::vector<uint8_t> between(n, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      for (const auto& d : kAxes) {
        const int ax = x - d[0], ay = y - d[1], bx = x + d[0], by = y + d[1];
        if (ax < 0 || ay < 0 || bx < 0 || by < 0 || ax >= w || ay >= h || bx >= w || by >= h) continue;
        const Guide& a = g[size_t(ay) * size_t(w) + size_t(ax)];
        const Guide& b = g[size_t(by) * size_t(w) + size_t(bx)];
        if (a.object == -3 && b.object == -3) between[i] |= 1u;
        if (a.material == -3 && b.material == -3) between[i] |= 2u;
      }
    }
  for (size_t i = 0; i < n; ++i) {
    if (f.object && (between[i] & 1u)) g[i].object = -3;
    if (f.material && (between[i] & 2u)) g[i].material = -3;
  }
  if (!f.depth) return g;
  // The depth slope: the smaller one-sided difference along each axis among pixels of
  // the same object (so a silhouette does not count), summed over the axes.
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      Guide& p = g[size_t(y) * size_t(w) + size_t(x)];
      float slope = 0.f;
      for (int axis = 0; axis < 2; ++axis) {
        float best = kInfinity;
        for (int s = -1; s <= 1; s += 2) {
          const int qx = x + (axis == 0 ? s : 0), qy = y + (axis == 1 ? s : 0);
          if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
          const Guide& q = g[size_t(qy) * size_t(w) + size_t(qx)];
          if (q.object != p.object) continue;
          best = std::min(best, std::abs(q.depth - p.depth));
        }
        if (best < kInfinity) slope += best;
      }
      p.slope = slope;
    }
  }
  return g;
}

// Whether q may lend to p at all: the same object, material and toon band.
bool same_region(const Guide& p, const Guide& q) {
  return q.sampled && !q.exact && p.object == q.object && p.material == q.material &&
         std::abs(p.band - q.band) < kBandTolerance;
}

// The weight of the features alone (normal, depth, albedo), at `step` pixels apart, as
// a factor (the normals') and an exponent (depth and albedo), so the colour weight
// joins the exponent and a tap costs one exp per half.
struct FeatureWeight {
  float factor, exponent;
};
FeatureWeight feature_weight(const Guide& p, const Guide& q, int step) {
  float wn = 1.f;
  if (p.normal != Vec3(0.f) || q.normal != Vec3(0.f)) wn = pow32(std::max(0.f, glm::dot(p.normal, q.normal)));
  const float dz =
      std::abs(p.depth - q.depth) / (kSigmaDepth * p.slope * float(step) + 1e-3f * p.depth + 1e-6f);
  const Color da = p.albedo - q.albedo;
  return {wn, dz + kAlbedoScale * glm::dot(da, da)};
}

}  // namespace

AovSet denoise_aovs() {
  AovSet a;
  for (const Aov x : {Aov::albedo, Aov::normal, Aov::depth, Aov::object_id, Aov::material_id, Aov::toon_band})
    a.add(x);
  return a;
}

Denoised denoise(const Film& film, ThreadBudget* pool, const Cancel& cancel) {
  const int w = film.width(), h = film.height();
  const size_t n = size_t(w) * size_t(h);
  const AovSet& has = film.aovs();
  const Features f{has.has(Aov::normal),    has.has(Aov::depth),     has.has(Aov::albedo),
                   has.has(Aov::toon_band), has.has(Aov::object_id), has.has(Aov::material_id)};
  const std::vector<Guide> g = make_guides(film, f, pool, cancel);

  // The halves' means (demodulated), their sample counts, and the variance of one
  // half's luminance: E[(a - b)^2] = Var(a) + Var(b), about 2 Var(a).
  std::array<std::vector<Color>, 2> cur{std::vector<Color>(n, Color(0.f)), std::vector<Color>(n, Color(0.f))};
  std::array<std::vector<float>, 2> var{std::vector<float>(n, 0.f), std::vector<float>(n, 0.f)};
  std::vector<Color> raw_a(n, Color(0.f)), raw_b(n, Color(0.f));
  std::vector<float> share_a(n, 0.5f);  // half a's share of the pixel's samples
  parallel_rows(
      h, pool,
      [&](int y) {
        for (int x = 0; x < w; ++x) {
          const size_t i = size_t(y) * size_t(w) + size_t(x);
          const FilmPixel fp = film.pixel(x, y);
          if (!g[i].sampled) {
            const uint32_t c = fp.count[0] + fp.count[1];
            raw_a[i] = raw_b[i] = c ? Color((fp.sum[0] + fp.sum[1]) / double(c)) : Color(0.f);
            continue;
          }
          raw_a[i] = Color(fp.sum[0] / double(fp.count[0]));
          raw_b[i] = Color(fp.sum[1] / double(fp.count[1]));
          share_a[i] = float(double(fp.count[0]) / double(fp.count[0] + fp.count[1]));
          cur[0][i] = raw_a[i] / g[i].divisor;
          cur[1][i] = raw_b[i] / g[i].divisor;
          const float d = luminance(cur[0][i] - cur[1][i]);
          var[0][i] = var[1][i] = 0.5f * d * d;
        }
      },
      cancel);

  // Rung 0: the raw mean. Its cross-validation error is 2 (a - b)^2.
  Denoised result;
  std::vector<Color> out(n);
  std::vector<float> err(n), best_err(n), best_diff2(n);
  std::vector<uint8_t> best_level(n, 0);
  for (size_t i = 0; i < n; ++i) {
    out[i] = share_a[i] * raw_a[i] + (1.f - share_a[i]) * raw_b[i];
    const float d = luminance(raw_a[i]) - luminance(raw_b[i]);
    err[i] = g[i].sampled ? 2.f * d * d : 0.f;
    best_diff2[i] = d * d;
  }
  std::vector<float> best_smoothed = box_blur(err, w, h, kErrorRadius, pool, cancel);
  best_err = err;

  std::array<std::vector<Color>, 2> next{std::vector<Color>(n), std::vector<Color>(n)};
  std::array<std::vector<float>, 2> next_var{std::vector<float>(n), std::vector<float>(n)};
  static constexpr float kKernel[3] = {0.25f, 0.5f, 0.25f};
  for (int level = 1; level <= kLevels; ++level) {
    const int step = 1 << (level - 1);
    // The colour weight reads a smoothed variance: one pixel's is a single draw.
    std::array<std::vector<float>, 2> sd;
    for (int half = 0; half < 2; ++half) {
      sd[half] = box_blur(var[half], w, h, 1, pool, cancel);
      for (float& s : sd[half]) s = kSigmaColor * std::sqrt(s) + 1e-6f;
    }
    const bool done = parallel_rows(
        h, pool,
        [&](int y) {
          for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            const Guide& p = g[i];
            if (!p.sampled || p.exact) {
              for (int half = 0; half < 2; ++half)
                next[half][i] = cur[half][i], next_var[half][i] = var[half][i];
              continue;
            }
            std::array<Color, 2> sum;
            std::array<float, 2> wsum, vsum, lp;
            for (int half = 0; half < 2; ++half) {
              const float k = kKernel[1] * kKernel[1];
              sum[half] = k * cur[half][i];
              wsum[half] = k;
              vsum[half] = k * k * var[half][i];
              lp[half] = luminance(cur[half][i]);
            }
            for (int dy = -1; dy <= 1; ++dy) {
              const int qy = y + dy * step;
              if (qy < 0 || qy >= h) continue;
              for (int dx = -1; dx <= 1; ++dx) {
                const int qx = x + dx * step;
                if ((dx == 0 && dy == 0) || qx < 0 || qx >= w) continue;
                const size_t j = size_t(qy) * size_t(w) + size_t(qx);
                const Guide& q = g[j];
                if (!same_region(p, q)) continue;
                const FeatureWeight fw = feature_weight(p, q, step);
                const float wf = kKernel[dx + 1] * kKernel[dy + 1] * fw.factor;
                if (!(wf > 1e-6f) || !(fw.exponent < 14.f)) continue;  // e^-14: under 1e-6
                for (int half = 0; half < 2; ++half) {
                  const float wc = wf * std::exp(-fw.exponent -
                                                 std::abs(lp[half] - luminance(cur[half][j])) / sd[half][i]);
                  sum[half] += wc * cur[half][j];
                  wsum[half] += wc;
                  vsum[half] += wc * wc * var[half][j];
                }
              }
            }
            for (int half = 0; half < 2; ++half) {
              next[half][i] = sum[half] / wsum[half];
              next_var[half][i] = vsum[half] / (wsum[half] * wsum[half]);
            }
          }
        },
        cancel);
    if (!done) return {};
    std::swap(cur, next);
    std::swap(var, next_var);

    // Cross-validation: this rung of half a against raw half b, and the other way.
    parallel_rows(
        h, pool,
        [&](int y) {
          for (size_t i = size_t(y) * size_t(w); i < size_t(y + 1) * size_t(w); ++i) {
            if (!g[i].sampled) {
              err[i] = 0.f;
              continue;
            }
            const float fa = luminance(cur[0][i] * g[i].divisor), fb = luminance(cur[1][i] * g[i].divisor);
            const float ea = fa - luminance(raw_b[i]), eb = fb - luminance(raw_a[i]);
            err[i] = ea * ea + eb * eb;
          }
        },
        cancel);
    const std::vector<float> smoothed = box_blur(err, w, h, kErrorRadius, pool, cancel);
    if (cancel.requested()) return {};
    parallel_rows(
        h, pool,
        [&](int y) {
          for (size_t i = size_t(y) * size_t(w); i < size_t(y + 1) * size_t(w); ++i) {
            if (!g[i].sampled || !(smoothed[i] < best_smoothed[i])) continue;
            best_smoothed[i] = smoothed[i];
            best_err[i] = err[i];
            best_level[i] = uint8_t(level);
            const Color a = cur[0][i] * g[i].divisor, b = cur[1][i] * g[i].divisor;
            out[i] = share_a[i] * a + (1.f - share_a[i]) * b;
            const float d = luminance(a) - luminance(b);
            best_diff2[i] = d * d;
          }
        },
        cancel);
  }

  // MSE of one denoised half: err / 2 - Var(half), Var(half) ~ (a - b)^2 / 2. The two
  // halves together keep its bias and halve its variance, ~ (F(a) - F(b))^2 / 2.
  double mse = 0.0, lum = 0.0;
  size_t counted = 0;
  result.scale_share.assign(kLevels + 1, 0.0);
  for (size_t i = 0; i < n; ++i) {
    if (!g[i].sampled) continue;
    const float d = luminance(raw_a[i]) - luminance(raw_b[i]);
    const double half_mse = 0.5 * double(best_err[i]) - 0.5 * double(d) * double(d);
    // One pixel's difference of squares is noisy (it can fall below zero), but never
    // below the variance part, which the halves' difference measures alone.
    const double variance = 0.25 * double(best_diff2[i]);
    mse += std::max(half_mse - variance, variance);
    lum += 0.5 * double(luminance(raw_a[i]) + luminance(raw_b[i]));
    result.scale_share[best_level[i]] += 1.0;
    ++counted;
  }
  if (counted) {
    for (double& s : result.scale_share) s /= double(counted);
    if (lum > 0.0)
      result.relative_error = std::sqrt(std::max(mse, 0.0) / double(counted)) / (lum / double(counted));
  }
  result.image = RgbImage{w, h, std::move(out)};
  return result;
}

double estimate_denoise_seconds(int width, int height, ThreadBudget* pool) {
  if (width <= 0 || height <= 0) return 0.0;
  // Two objects split by a diagonal edge, noisy samples in both halves: every filter
  // rung runs, as in a render. The cost per pixel hardly depends on the picture.
  const int w = std::min(width, 96), h = std::min(height, 96);
  Film film(w, h, denoise_aovs());
  for (uint32_t pass = 0; pass < 2; ++pass)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const bool left = x < y;
        const float noise =
            float(hash_u32(uint32_t(x) * 7919u + uint32_t(y) * 104729u + pass) >> 8) * 0x1p-24f;
        film.add_sample(x, y, pass, Color(left ? 0.2f : 0.7f) * (0.5f + noise));
        FirstHit hit;
        hit.albedo = Color(left ? 0.3f : 0.8f);
        hit.normal = Normal3(0.f, 0.f, 1.f);
        hit.depth = 1.f + 0.01f * float(x);
        hit.object = hit.material = left ? 0 : 1;
        film.add_first_hit(x, y, hit);
      }
  const auto start = std::chrono::steady_clock::now();
  denoise(film, pool);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return seconds * (double(width) * double(height)) / (double(w) * double(h));
}

}  // namespace inkray
