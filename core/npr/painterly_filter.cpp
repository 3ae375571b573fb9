// The generalized and anisotropic Kuwahara filters. Both share one sector
// weight table and one per-pixel accumulation; they differ only in the shape
// (disc or ellipse) that maps pixel offsets into the unit disc.
#include "core/npr/painterly_filter.h"

#include "core/image/image_io.h"

#include <algorithm>
#include <atomic>
#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

namespace inkray {
namespace {

constexpr int kMaxSectors = 16;
// Papari's sector kernel: the sector's indicator blurred by sigma_s, times a radial
// Gaussian sigma_r, in units of the disc radius (the values of Kyprianidis' code).
constexpr float kSigmaRadial = 0.5f;
constexpr float kSigmaSmooth = kSigmaRadial / 3.f;
// Spread is measured in 8-bit code values, so q = 8 separates sectors as in the papers.
constexpr float kCodeValues = 255.f;
// Structure tensor smoothing (Kyprianidis et al. use 2 px).
constexpr float kTensorSigma = 2.f;
// Finite but huge inputs are capped so a sector sum cannot overflow to Inf.
constexpr float kLargestInput = 1e30f;

// A pixel as the filters read it: the linear colour is averaged, the bounded
// copy only decides which sectors to trust.
struct Texel {
  Color linear{0.f};
  Vec3 judged{0.f};
};

// The texels with clamp-to-edge reads.
struct Source {
  std::vector<Texel> texels;
  int width = 0, height = 0;
  const Texel& at(int x, int y) const { return texels[size_t(y) * size_t(width) + size_t(x)]; }
  const Texel& clamped(int x, int y) const {
    return at(std::clamp(x, 0, width - 1), std::clamp(y, 0, height - 1));
  }
};

// Reinhard then sRGB encoding: close to the display encoding in darks and
// midtones, and bounded, so a light of any brightness judges like white.
float judged_value(float linear) {
  const float x = std::max(linear, 0.f);
  return linear_to_srgb(x / (1.f + x));
}

Source prepare_source(const RgbImage& image, ThreadBudget* pool) {
  Source source{std::vector<Texel>(image.pixels.size()), image.width, image.height};
  std::vector<Texel>& texels = source.texels;
  parallel_rows(image.height, pool, [&](int y) {
    for (int x = 0; x < image.width; ++x) {
      const Color& c = image.at(x, y);
      Texel& t = texels[size_t(y) * size_t(image.width) + size_t(x)];
      if (!is_finite(c)) continue;  // read as black
      t.linear = glm::clamp(c, Color(-kLargestInput), Color(kLargestInput));
      t.judged = Vec3(judged_value(t.linear.r), judged_value(t.linear.g), judged_value(t.linear.b));
    }
  });
  return source;
}

// Four sectors to a SIMD register (a GCC/Clang vector extension: SSE on x86,
// NEON on ARM); counts are padded to a multiple of 4 with sectors that weigh
// zero everywhere, which combine() skips. Per-sample loops are compiled for
// each padded count so the accumulators stay in registers.
typedef float Lanes __attribute__((vector_size(16)));
constexpr int kLanes = 4;
int padded_sectors(int sectors) { return (sectors + kLanes - 1) / kLanes * kLanes; }

template <int N>
struct Weights {
  Lanes lane[N / kLanes];
  float operator[](int k) const { return lane[k / kLanes][k % kLanes]; }
};

// All sector weights on a grid over [-1, 1]^2, stored together per cell, so a
// sample's weights are four contiguous reads and a bilinear blend: no angle is
// computed per sample, whatever the sector count.
class SectorTable {
 public:
  explicit SectorTable(int sectors);
  // The N (padded) sector weights at v and at -v, |v| <= 1: samples come in
  // point-symmetric pairs, which share the cell lookup.
  template <int N>
  void weights_pair(Vec2 v, Weights<N>& w, Weights<N>& w_opposite) const;
  template <int N>
  Weights<N> weights(Vec2 v) const {
    Weights<N> w, w_opposite;
    weights_pair(v, w, w_opposite);
    return w;
  }

 private:
  // Fine enough that sigma_s spans almost three cells; small enough for L1 at N = 8.
  static constexpr int kGrid = 32;
  const Lanes* cell(int x, int y) const {
    return &table_[(size_t(y) * kGrid + size_t(x)) * size_t(stride_ / kLanes)];
  }

  int stride_;                // padded sector count
  std::vector<Lanes> table_;  // [y][x][sector / 4]
};

// Papari's sector kernel on the grid: the indicator of sector k (a wedge of the
// unit disc, centred on angle 2 pi k / N) blurred by sigma_s.
std::vector<float> smoothed_sector(int sectors, int k, int size) {
  constexpr int kSuper = 4;
  const float half_width = kPi / float(sectors);
  const float centre = 2.f * kPi * float(k) / float(sectors);
  std::vector<float> grid(size_t(size) * size_t(size), 0.f);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      int inside = 0;
      for (int sj = 0; sj < kSuper; ++sj)
        for (int si = 0; si < kSuper; ++si) {
          const float px = (float(i) + (float(si) + 0.5f) / kSuper) * 2.f / float(size) - 1.f;
          const float py = (float(j) + (float(sj) + 0.5f) / kSuper) * 2.f / float(size) - 1.f;
          const float off = std::remainder(std::atan2(py, px) - centre, 2.f * kPi);
          if (px * px + py * py <= 1.f && (sectors == 1 || std::abs(off) <= half_width)) ++inside;
        }
      grid[size_t(j) * size_t(size) + size_t(i)] = float(inside) / float(kSuper * kSuper);
    }
  // Separable Gaussian blur; zero outside the grid, where the indicator is zero anyway.
  const float sigma = kSigmaSmooth * float(size) / 2.f;
  const int reach = int(std::ceil(3.f * sigma));
  std::vector<float> kernel(size_t(2 * reach + 1));
  for (int d = -reach; d <= reach; ++d) kernel[size_t(d + reach)] = std::exp(-0.5f * sqr(float(d) / sigma));
  std::vector<float> pass(grid.size(), 0.f);
  for (int axis = 0; axis < 2; ++axis) {
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        float sum = 0.f;
        for (int d = -reach; d <= reach; ++d) {
          const int ii = axis == 0 ? i + d : i, jj = axis == 0 ? j : j + d;
          if (ii >= 0 && ii < size && jj >= 0 && jj < size)
            sum += kernel[size_t(d + reach)] * grid[size_t(jj) * size_t(size) + size_t(ii)];
        }
        pass[size_t(j) * size_t(size) + size_t(i)] = sum;
      }
    grid.swap(pass);
  }
  return grid;
}

SectorTable::SectorTable(int sectors)
    : stride_(padded_sectors(sectors)), table_(size_t(kGrid) * kGrid * size_t(stride_ / kLanes), Lanes{}) {
  for (int k = 0; k < sectors; ++k) {
    const std::vector<float> sector = smoothed_sector(sectors, k, kGrid);
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i) {
        const Vec2 p = (Vec2(float(i), float(j)) + 0.5f) * (2.f / kGrid) - 1.f;
        const float falloff = std::exp(-0.5f * glm::dot(p, p) / sqr(kSigmaRadial));
        table_[(size_t(j) * kGrid + size_t(i)) * size_t(stride_ / kLanes) + size_t(k / kLanes)][k % kLanes] =
            sector[size_t(j) * kGrid + size_t(i)] * falloff;
      }
  }
}

template <int N>
[[gnu::always_inline]] inline void SectorTable::weights_pair(Vec2 v, Weights<N>& w,
                                                             Weights<N>& w_opposite) const {
  const float fx = std::clamp((v.x + 1.f) * (0.5f * kGrid) - 0.5f, 0.f, float(kGrid - 1));
  const float fy = std::clamp((v.y + 1.f) * (0.5f * kGrid) - 0.5f, 0.f, float(kGrid - 1));
  const int x0 = std::min(int(fx), kGrid - 2), y0 = std::min(int(fy), kGrid - 2);
  const float tx = fx - float(x0), ty = fy - float(y0);
  const float w00 = (1.f - ty) * (1.f - tx), w01 = (1.f - ty) * tx, w10 = ty * (1.f - tx), w11 = ty * tx;
  // The grid is symmetric about the origin: -v falls in the mirrored cells with the same fractions.
  const int x1 = kGrid - 1 - x0, y1 = kGrid - 1 - y0;
  const Lanes *p00 = cell(x0, y0), *p01 = cell(x0 + 1, y0), *p10 = cell(x0, y0 + 1),
              *p11 = cell(x0 + 1, y0 + 1);
  const Lanes *m00 = cell(x1, y1), *m01 = cell(x1 - 1, y1), *m10 = cell(x1, y1 - 1),
              *m11 = cell(x1 - 1, y1 - 1);
  for (int g = 0; g < N / kLanes; ++g) {
    w.lane[g] = w00 * p00[g] + w01 * p01[g] + w10 * p10[g] + w11 * p11[g];
    w_opposite.lane[g] = w00 * m00[g] + w01 * m01[g] + w10 * m10[g] + w11 * m11[g];
  }
}

// Weighted sums per sector. Samples are taken relative to the centre pixel so a
// flat region gives exactly its own value and the variance loses no precision.
template <int N>
struct SectorSums {
  static constexpr int kGroups = N / kLanes;
  Lanes weight[kGroups]{}, r[kGroups]{}, g[kGroups]{}, b[kGroups]{};
  Lanes jr[kGroups]{}, jg[kGroups]{}, jb[kGroups]{}, jj[kGroups]{};

  void add(const Weights<N>& w, const Texel& sample, const Texel& centre) {
    const Color c = sample.linear - centre.linear;
    const Vec3 d = sample.judged - centre.judged;
    const float dd = d.x * d.x + d.y * d.y + d.z * d.z;
    for (int i = 0; i < kGroups; ++i) {
      const Lanes wi = w.lane[i];
      weight[i] += wi;
      r[i] += wi * c.r;
      g[i] += wi * c.g;
      b[i] += wi * c.b;
      jr[i] += wi * d.x;
      jg[i] += wi * d.y;
      jb[i] += wi * d.z;
      jj[i] += wi * dd;
    }
  }

  // Sum_i a_i m_i / Sum_i a_i with a_i = (1 + sigma_i)^-q, each a_i divided by
  // the best sector's so that a large q cannot underflow every weight to zero.
  Color combine(float q, const Texel& centre) const {
    float spread[N] = {};
    float best = kInfinity;
    for (int k = 0; k < N; ++k) {
      const int i = k / kLanes, l = k % kLanes;
      if (!(weight[i][l] > 0.f)) continue;
      const float inv = 1.f / weight[i][l];
      const Vec3 mean = Vec3(jr[i][l], jg[i][l], jb[i][l]) * inv;
      spread[k] = 1.f + kCodeValues * safe_sqrt(jj[i][l] * inv - glm::dot(mean, mean));
      best = std::min(best, spread[k]);
    }
    Color total_colour(0.f);
    float total = 0.f;
    for (int k = 0; k < N; ++k) {
      const int i = k / kLanes, l = k % kLanes;
      if (!(weight[i][l] > 0.f)) continue;
      const float a = std::pow(best / spread[k], q);
      total_colour += (a / weight[i][l]) * Color(r[i][l], g[i][l], b[i][l]);
      total += a;
    }
    return total > 0.f ? centre.linear + total_colour / total : centre.linear;
  }
};

// Calls body(std::integral_constant<int, N>) for the padded sector count N.
template <class Body>
void with_sector_count(int padded, const Body& body) {
  switch (padded) {
    case 4:
      body(std::integral_constant<int, 4>());
      break;
    case 8:
      body(std::integral_constant<int, 8>());
      break;
    case 12:
      body(std::integral_constant<int, 12>());
      break;
    default:
      body(std::integral_constant<int, kMaxSectors>());
      break;
  }
}

// ---------------------------------------------------------------- generalized Kuwahara

template <int N>
struct Tap {
  int dx = 0, dy = 0;
  Weights<N> w;
};

template <int N>
std::vector<Tap<N>> disc_taps(const SectorTable& table, float radius) {
  std::vector<Tap<N>> taps;
  const int reach = int(std::floor(radius));
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx) {
      const Vec2 v = Vec2(float(dx), float(dy)) / radius;
      if (glm::dot(v, v) <= 1.f) taps.push_back({dx, dy, table.weights<N>(v)});
    }
  return taps;
}

template <int N>
bool kuwahara_rows(const Source& source, const SectorTable& table, float radius, float q, ThreadBudget* pool,
                   const Cancel& cancel, RgbImage& out) {
  const std::vector<Tap<N>> taps = disc_taps<N>(table, radius);
  return parallel_rows(
      source.height, pool,
      [&](int y) {
        for (int x = 0; x < source.width; ++x) {
          const Texel& centre = source.at(x, y);
          SectorSums<N> sums;
          for (const Tap<N>& tap : taps) sums.add(tap.w, source.clamped(x + tap.dx, y + tap.dy), centre);
          out.at(x, y) = sums.combine(q, centre);
        }
      },
      cancel);
}

// ---------------------------------------------------------------- anisotropic Kuwahara

// Per channel Sobel gradients of the judged copy, summed into (E, F, G) =
// (fx.fx, fx.fy, fy.fy), then Gaussian-smoothed so the orientation is stable.
std::vector<Vec3> structure_tensor(const Source& source, ThreadBudget* pool) {
  const int width = source.width, height = source.height;
  const auto judged = [&](int x, int y) { return source.clamped(x, y).judged; };
  std::vector<Vec3> tensor(source.texels.size());
  parallel_rows(height, pool, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const Vec3 fx = (judged(x + 1, y - 1) + 2.f * judged(x + 1, y) + judged(x + 1, y + 1) -
                       judged(x - 1, y - 1) - 2.f * judged(x - 1, y) - judged(x - 1, y + 1)) *
                      0.25f;
      const Vec3 fy = (judged(x - 1, y + 1) + 2.f * judged(x, y + 1) + judged(x + 1, y + 1) -
                       judged(x - 1, y - 1) - 2.f * judged(x, y - 1) - judged(x + 1, y - 1)) *
                      0.25f;
      tensor[size_t(y) * size_t(width) + size_t(x)] =
          Vec3(glm::dot(fx, fx), glm::dot(fx, fy), glm::dot(fy, fy));
    }
  });
  const int reach = int(std::ceil(3.f * kTensorSigma));
  std::vector<float> kernel(size_t(2 * reach + 1));
  float norm = 0.f;
  for (int k = -reach; k <= reach; ++k)
    norm += kernel[size_t(k + reach)] = std::exp(-0.5f * sqr(k / kTensorSigma));
  for (float& k : kernel) k /= norm;
  std::vector<Vec3> pass(tensor.size());
  for (int axis = 0; axis < 2; ++axis) {
    parallel_rows(height, pool, [&](int y) {
      for (int x = 0; x < width; ++x) {
        Vec3 sum(0.f);
        for (int k = -reach; k <= reach; ++k) {
          const int sx = axis == 0 ? std::clamp(x + k, 0, width - 1) : x;
          const int sy = axis == 0 ? y : std::clamp(y + k, 0, height - 1);
          sum += kernel[size_t(k + reach)] * tensor[size_t(sy) * size_t(width) + size_t(sx)];
        }
        pass[size_t(y) * size_t(width) + size_t(x)] = sum;
      }
    });
    tensor.swap(pass);
  }
  return tensor;
}

// The filter's ellipse at one pixel: offsets d map into the unit disc by
// v = (dot(d, major) / a, dot(d, minor) / b).
struct Ellipse {
  Vec2 major{1.f, 0.f};  // along the flow (the tensor's minor eigenvector)
  float a = 1.f, b = 1.f;
};

Ellipse ellipse_from_tensor(Vec3 tensor, float radius) {
  const float e = tensor.x, f = tensor.y, g = tensor.z;
  const float root = std::sqrt(sqr(e - g) + 4.f * f * f);
  const float trace = e + g;
  const float anisotropy = trace > 1e-12f ? std::min(root / trace, 1.f) : 0.f;
  const float lambda1 = 0.5f * (trace + root);
  // Two expressions for the same eigenvector; the longer one is the well-conditioned one.
  const Vec2 t1(lambda1 - e, -f), t2(-f, lambda1 - g);
  const Vec2 t = glm::dot(t1, t1) >= glm::dot(t2, t2) ? t1 : t2;
  const float len = std::sqrt(glm::dot(t, t));
  Ellipse ellipse;
  if (len > 0.f && std::isfinite(len)) ellipse.major = t / len;
  ellipse.a = radius * (1.f + anisotropy);  // alpha = 1: a in [r, 2r], b in [r/2, r]
  ellipse.b = radius / (1.f + anisotropy);
  return ellipse;
}

// The columns dx of row dy inside the ellipse, from the roots of |v|^2 = 1.
// Taking the samples from these spans, without a per-sample test, keeps the
// inner loop free of unpredictable branches.
struct Span {
  int lo = 0, hi = -1;
};
Span ellipse_span(const Ellipse& ellipse, int dy) {
  const float c = ellipse.major.x, s = ellipse.major.y;
  const float ia = 1.f / sqr(ellipse.a), ib = 1.f / sqr(ellipse.b);
  const float qa = c * c * ia + s * s * ib;
  const float qb = 2.f * float(dy) * c * s * (ia - ib);
  const float qc = sqr(float(dy)) * (s * s * ia + c * c * ib) - 1.f;
  const float disc = qb * qb - 4.f * qa * qc;
  if (disc < 0.f) return {};
  const float root = std::sqrt(disc);
  return {int(std::ceil((-qb - root) / (2.f * qa))), int(std::floor((-qb + root) / (2.f * qa)))};
}

// Visits half the ellipse and takes each sample with its point reflection.
template <int N>
Color filter_ellipse(const Source& source, int x, int y, const Ellipse& ellipse, const SectorTable& table,
                     const Weights<N>& centre_weights, float q) {
  const Vec2 to_v_x = Vec2(ellipse.major.x / ellipse.a, -ellipse.major.y / ellipse.b);  // v per unit dx
  const Vec2 to_v_y = Vec2(ellipse.major.y / ellipse.a, ellipse.major.x / ellipse.b);   // v per unit dy
  const int reach_y = int(std::sqrt(sqr(ellipse.a * ellipse.major.y) + sqr(ellipse.b * ellipse.major.x)));
  const Texel& centre = source.at(x, y);
  SectorSums<N> sums;
  sums.add(centre_weights, centre, centre);
  Weights<N> w, w_opposite;
  for (int dy = 0; dy <= reach_y; ++dy) {
    const Span span = ellipse_span(ellipse, dy);
    for (int dx = dy == 0 ? 1 : span.lo; dx <= span.hi; ++dx) {
      table.weights_pair(float(dx) * to_v_x + float(dy) * to_v_y, w, w_opposite);
      sums.add(w, source.clamped(x + dx, y + dy), centre);
      sums.add(w_opposite, source.clamped(x - dx, y - dy), centre);
    }
  }
  return sums.combine(q, centre);
}

template <int N>
bool anisotropic_rows(const Source& source, const SectorTable& table, float radius, float q,
                      ThreadBudget* pool, const Cancel& cancel, RgbImage& out) {
  const std::vector<Vec3> tensor = structure_tensor(source, pool);
  const Weights<N> centre_weights = table.weights<N>(Vec2(0.f));
  return parallel_rows(
      source.height, pool,
      [&](int y) {
        for (int x = 0; x < source.width; ++x) {
          const Ellipse ellipse =
              ellipse_from_tensor(tensor[size_t(y) * size_t(source.width) + size_t(x)], radius);
          out.at(x, y) = filter_ellipse<N>(source, x, y, ellipse, table, centre_weights, q);
        }
      },
      cancel);
}

int clamp_sectors(int sectors) { return std::clamp(sectors, 1, kMaxSectors); }
float clamp_radius(float radius) { return std::isfinite(radius) ? std::clamp(radius, 0.5f, 256.f) : 4.f; }
float clamp_sharpness(float q) { return std::isfinite(q) ? std::max(q, 0.f) : 8.f; }

// Both filters: clamp the settings, prepare the source and run `rows` (kuwahara_rows
// or anisotropic_rows, for the padded sector count); an empty image when cancelled.
template <class Rows>
RgbImage filter_rows(const RgbImage& image, const PainterlyFilterParams& params, ThreadBudget* pool,
                     const Cancel& cancel, Rows rows) {
  RgbImage out{image.width, image.height, std::vector<Color>(image.pixels.size())};
  if (image.width <= 0 || image.height <= 0) return out;
  const int sectors = clamp_sectors(params.sectors);
  const SectorTable table(sectors);
  const Source source = prepare_source(image, pool);
  bool finished = false;
  with_sector_count(padded_sectors(sectors), [&](auto n) {
    finished = rows(n, source, table, clamp_radius(params.radius), clamp_sharpness(params.sharpness), pool,
                    cancel, out);
  });
  return finished ? out : RgbImage{};
}

}  // namespace

RgbImage kuwahara_filter(const RgbImage& image, const PainterlyFilterParams& params, ThreadBudget* pool,
                         const Cancel& cancel) {
  return filter_rows(image, params, pool, cancel,
                     [](auto n, auto&&... args) { return kuwahara_rows<n()>(args...); });
}

RgbImage anisotropic_kuwahara_filter(const RgbImage& image, const PainterlyFilterParams& params,
                                     ThreadBudget* pool, const Cancel& cancel) {
  return filter_rows(image, params, pool, cancel,
                     [](auto n, auto&&... args) { return anisotropic_rows<n()>(args...); });
}

}  // namespace inkray
