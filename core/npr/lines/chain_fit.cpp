// Smooth, simplify, spline (chain_fit.h).
#include "core/npr/lines/chain_fit.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

// Two passes of the [1 2 1] / 4 filter: the pixel grid's half-pixel steps go, a
// curve's radius hardly moves. Open paths keep their ends.
std::vector<Vec2> smooth(std::vector<Vec2> p, bool closed) {
  const size_t n = p.size();
  if (n < 3) return p;
  std::vector<Vec2> q(n);
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t i = 0; i < n; ++i) {
      if (!closed && (i == 0 || i + 1 == n)) {
        q[i] = p[i];
        continue;
      }
      q[i] = 0.25f * p[(i + n - 1) % n] + 0.5f * p[i] + 0.25f * p[(i + 1) % n];
    }
    std::swap(p, q);
  }
  return p;
}

float distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.f ? std::clamp(glm::dot(p - a, ab) / len2, 0.f, 1.f) : 0.f;
  return glm::length(p - (a + t * ab));
}

void simplify(const std::vector<Vec2>& p, size_t first, size_t last, float tolerance,
              std::vector<uint8_t>& keep) {
  // Iterative Douglas-Peucker: a long chain must not recurse as deep as it is long.
  std::vector<std::pair<size_t, size_t>> spans{{first, last}};
  while (!spans.empty()) {
    const auto [a, b] = spans.back();
    spans.pop_back();
    float worst = 0.f;
    size_t at = a;
    for (size_t i = a + 1; i < b; ++i) {
      const float d = distance_to_segment(p[i], p[a], p[b]);
      if (d > worst) worst = d, at = i;
    }
    if (worst > tolerance) {
      keep[at] = 1;
      spans.push_back({a, at});
      spans.push_back({at, b});
    }
  }
}

// Centripetal Catmull-Rom (alpha 1/2) between p1 and p2 at t in [0, 1].
Vec2 catmull_rom(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, float t) {
  auto knot = [](Vec2 a, Vec2 b) { return std::max(std::sqrt(glm::length(b - a)), 1e-4f); };
  const float t0 = 0.f, t1 = t0 + knot(p0, p1), t2 = t1 + knot(p1, p2), t3 = t2 + knot(p2, p3);
  const float u = t1 + t * (t2 - t1);
  const Vec2 a1 = ((t1 - u) * p0 + (u - t0) * p1) / (t1 - t0);
  const Vec2 a2 = ((t2 - u) * p1 + (u - t1) * p2) / (t2 - t1);
  const Vec2 a3 = ((t3 - u) * p2 + (u - t2) * p3) / (t3 - t2);
  const Vec2 b1 = ((t2 - u) * a1 + (u - t0) * a2) / (t2 - t0);
  const Vec2 b2 = ((t3 - u) * a2 + (u - t1) * a3) / (t3 - t1);
  return ((t2 - u) * b1 + (u - t1) * b2) / (t2 - t1);
}

}  // namespace

std::vector<ChainPoint> fit_chain(const std::vector<Vec2>& pixels, bool closed, float tolerance,
                                  float spacing) {
  std::vector<ChainPoint> out;
  if (pixels.size() < 2) return out;
  closed = closed && pixels.size() >= 4;
  const std::vector<Vec2> p = smooth(pixels, closed);
  const size_t n = p.size();
  std::vector<uint8_t> keep(n, 0);
  keep[0] = keep[n - 1] = 1;
  if (closed) {
    // A loop is simplified as two halves, split at the point farthest from its start.
    size_t far = 0;
    for (size_t i = 1; i < n; ++i)
      if (glm::length(p[i] - p[0]) > glm::length(p[far] - p[0])) far = i;
    keep[far] = 1;
    simplify(p, 0, far, tolerance, keep);
    simplify(p, far, n - 1, tolerance, keep);
  } else {
    simplify(p, 0, n - 1, tolerance, keep);
  }
  std::vector<Vec2> k;
  for (size_t i = 0; i < n; ++i)
    if (keep[i]) k.push_back(p[i]);
  if (closed && k.size() >= 2 && glm::length(k.back() - k.front()) < 1e-3f) k.pop_back();
  const size_t m = k.size();
  if (m < 2) return out;
  // Open ends continue straight past themselves, so the spline leaves them along the path.
  auto point = [&](long i) -> Vec2 {
    if (closed) return k[size_t((i % long(m) + long(m)) % long(m))];
    if (i < 0) return 2.f * k[0] - k[1];
    if (i >= long(m)) return 2.f * k[m - 1] - k[m - 2];
    return k[size_t(i)];
  };
  const long spans = closed ? long(m) : long(m) - 1;
  for (long s = 0; s < spans; ++s) {
    const Vec2 a = point(s), b = point(s + 1);
    const int steps = std::max(1, int(std::ceil(glm::length(b - a) / spacing)));
    for (int j = 0; j < steps; ++j)
      out.push_back({catmull_rom(point(s - 1), a, b, point(s + 2), float(j) / float(steps))});
  }
  if (!closed) out.push_back({k[m - 1]});
  return out;
}

}  // namespace inkray
