// The hand's wobble.
#include "core/npr/lines/stroke_jitter.h"

#include "core/math/hash.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace inkray {
namespace {

constexpr float kKeyCellPx = 4.f;

glm::ivec2 cell_of(Vec2 p) {
  return glm::ivec2(int(std::floor(p.x / kKeyCellPx)), int(std::floor(p.y / kKeyCellPx)));
}

// Row first, then column, then the exact position where the cells are the same.
bool comes_first(Vec2 a, Vec2 b) {
  const glm::ivec2 ca = cell_of(a), cb = cell_of(b);
  return std::tie(ca.y, ca.x, a.y, a.x) <= std::tie(cb.y, cb.x, b.y, b.x);
}

float lattice(uint32_t seed, int i) { return u32_to_unit_float(hash_combine(seed, uint32_t(i))) * 2.f - 1.f; }

}  // namespace

float value_noise(uint32_t seed, float x, int period) {
  const float cell = std::floor(x);
  const float f = x - cell;
  int i0 = int(cell), i1 = i0 + 1;
  if (period > 0) i0 = ((i0 % period) + period) % period, i1 = (i0 + 1) % period;
  const float t = f * f * f * (f * (f * 6.f - 15.f) + 10.f);
  const float a = lattice(seed, i0), b = lattice(seed, i1);
  return a + (b - a) * t;
}

uint32_t chain_key(const Chain& chain) {
  Vec2 lo(0.f), hi(0.f);
  if (!chain.points.empty()) lo = hi = chain.points.front().p;
  for (const ChainPoint& q : chain.points) lo = glm::min(lo, q.p), hi = glm::max(hi, q.p);
  const glm::ivec2 a = cell_of(lo), b = cell_of(hi);
  const uint32_t kind = hash_combine(uint32_t(chain.type), uint32_t(chain.path));
  return hash_combine(hash_combine(kind, uint32_t(a.x), uint32_t(a.y)), uint32_t(b.x), uint32_t(b.y));
}

void jitter_points(std::vector<ChainPoint>& points, bool closed, uint32_t seed, float amplitude,
                   float wavelength) {
  const int n = int(points.size());
  if (n < 2 || amplitude == 0.f || !(wavelength > 0.f)) return;
  std::vector<float> s(size_t(n), 0.f);
  for (int i = 1; i < n; ++i)
    s[size_t(i)] = s[size_t(i - 1)] + glm::length(points[size_t(i)].p - points[size_t(i - 1)].p);
  const float length = s.back() + (closed ? glm::length(points.front().p - points.back().p) : 0.f);
  if (!(length > 0.f)) return;

  // Where the noise starts and which way it runs.
  float origin = 0.f, sign = 1.f;
  int period = 0;
  float cells_per_px = 1.f / wavelength;
  if (closed) {
    int top = 0;
    float twice_area = 0.f;
    for (int i = 0; i < n; ++i) {
      const Vec2 p = points[size_t(i)].p, next = points[size_t((i + 1) % n)].p;
      const Vec2 t = points[size_t(top)].p;
      if (std::tie(p.y, p.x) < std::tie(t.y, t.x)) top = i;
      twice_area += p.x * next.y - next.x * p.y;
    }
    origin = s[size_t(top)];
    sign = twice_area >= 0.f ? 1.f : -1.f;
    // A whole number of wavelengths round the loop, so the noise meets itself.
    period = std::max(1, int(std::lround(length / wavelength)));
    cells_per_px = float(period) / length;
  } else if (!comes_first(points.front().p, points.back().p)) {
    origin = length, sign = -1.f;
  }

  std::vector<Vec2> moved(points.size());
  for (int i = 0; i < n; ++i) {
    float along = sign * (s[size_t(i)] - origin);
    if (closed) along = std::fmod(std::fmod(along, length) + length, length);
    const int before = closed ? (i + n - 1) % n : std::max(i - 1, 0);
    const int after = closed ? (i + 1) % n : std::min(i + 1, n - 1);
    const Vec2 tangent = points[size_t(after)].p - points[size_t(before)].p;
    const float t_len = glm::length(tangent);
    const Vec2 normal = t_len > 0.f ? Vec2(-tangent.y, tangent.x) / t_len : Vec2(0.f);
    const float offset = amplitude * value_noise(seed, along * cells_per_px, period);
    moved[size_t(i)] = points[size_t(i)].p + normal * (sign * offset);
  }
  for (int i = 0; i < n; ++i) points[size_t(i)].p = moved[size_t(i)];
}

}  // namespace inkray
