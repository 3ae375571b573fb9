// Chaining: thin, trace, join, fit, label (chain_builder.h).
#include "core/npr/lines/chain_builder.h"

#include "core/npr/lines/chain_fit.h"
#include "core/npr/lines/chain_shape.h"
#include "core/npr/lines/pixel_skeleton.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>

namespace inkray {
namespace {

// What the image says of the surface under a chain point: the nearest surface in
// a small window, since a silhouette's centre pixel may see the background behind it
// and the line belongs to the surface in front.
void label_point(const ChainSource& s, const std::vector<float>& type_opacity, ChainPoint& q, int* object,
                 int* material, int* path) {
  const int cx = std::clamp(int(std::floor(q.p.x)), 0, s.width - 1);
  const int cy = std::clamp(int(std::floor(q.p.y)), 0, s.height - 1);
  const size_t centre = size_t(cy) * size_t(s.width) + size_t(cx);
  float opacity = 0.f;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int x = cx + dx, y = cy + dy;
      if (x < 0 || y < 0 || x >= s.width || y >= s.height) continue;
      opacity = std::max(opacity, type_opacity[size_t(y) * size_t(s.width) + size_t(x)]);
    }
  q.opacity = opacity;
  size_t nearest = centre;
  if (!s.depth.empty()) {
    float best = 0.f;
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const int x = cx + dx, y = cy + dy;
        if (x < 0 || y < 0 || x >= s.width || y >= s.height) continue;
        const size_t i = size_t(y) * size_t(s.width) + size_t(x);
        const float d = s.depth[i];
        if (d > 0.f && (best == 0.f || d < best)) best = d, nearest = i;
      }
    q.depth = best;
  }
  *object = s.object.empty() ? -1 : s.object[nearest];
  *material = s.material.empty() ? -1 : s.material[nearest];
  *path = s.path.empty() ? int(LinePath::direct) : int(s.path[centre]);
  if (!s.light.empty()) q.light = s.light[centre];
}

// Bilinear opacity of the line type at p, between pixel centres.
float opacity_at(const ChainSource& s, const std::vector<float>& type_opacity, Vec2 p) {
  const float fx = p.x - 0.5f, fy = p.y - 0.5f;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const float tx = fx - float(x0), ty = fy - float(y0);
  auto at = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= s.width || y >= s.height) return 0.f;
    return type_opacity[size_t(y) * size_t(s.width) + size_t(x)];
  };
  return (1.f - ty) * ((1.f - tx) * at(x0, y0) + tx * at(x0 + 1, y0)) +
         ty * ((1.f - tx) * at(x0, y0 + 1) + tx * at(x0 + 1, y0 + 1));
}

// How far along `across` from p the line's middle lies: the centroid of the coverage
// within two pixels either side (what lies above a faint floor, so the background's
// faint specks do not pull it); none where nothing is covered.
std::optional<float> offset_across(const ChainSource& s, const std::vector<float>& type_opacity, Vec2 p,
                                   Vec2 across) {
  float sum = 0.f, moment = 0.f;
  for (float o = -2.f; o <= 2.f; o += 0.25f) {
    const float w = std::max(0.f, opacity_at(s, type_opacity, p + o * across) - 0.1f);
    sum += w, moment += w * o;
  }
  if (sum <= 0.f) return std::nullopt;
  return moment / sum;
}

// Thinning eats into a line's ends, and may hook its last pixels aside: an open
// chain stops short of where its line does. Each end follows the line on, along
// its ridge (re-centred across at every step), to the line's half-opacity edge,
// and stops a half width before it, where a line of that width ends: so a dash
// of 10 pixels is a chain of 10 pixels.
void extend_ends(const ChainSource& s, const std::vector<float>& type_opacity, Chain& c) {
  if (c.closed || c.points.size() < 3) return;
  const auto opacity = [&](Vec2 p) { return opacity_at(s, type_opacity, p); };
  constexpr float kHalf = 0.5f;  // the line's edge
  for (int end = 0; end < 2; ++end) {
    const size_t n = c.points.size(), k = std::min<size_t>(3, n - 1);
    const Vec2 tip = end == 0 ? c.points.front().p : c.points.back().p;
    const Vec2 back = end == 0 ? c.points[k].p : c.points[n - 1 - k].p;
    if (glm::length(tip - back) <= 0.f) continue;
    const Vec2 along = glm::normalize(tip - back);
    auto reach = [&](Vec2 from, Vec2 dir) {
      float d = 0.f;
      while (d < 8.f && opacity(from + (d + 0.1f) * dir) >= kHalf) d += 0.1f;
      return d;
    };
    const Vec2 across0(-along.y, along.x);
    const float half_width = 0.5f * (reach(tip, across0) + reach(tip, -across0));
    Vec2 pos = tip, dir = along;
    // Thinning takes no more than about a width off an end; and a line turning away
    // (the bar of a T seen from its stem) is another line.
    const int steps = int(std::ceil((3.f * half_width + 2.f) / 0.5f));
    for (int step = 0; step < steps; ++step) {
      const Vec2 ahead = pos + 0.5f * dir, across(-dir.y, dir.x);
      const std::optional<float> offset = offset_across(s, type_opacity, ahead, across);
      if (!offset) break;
      const Vec2 centred = ahead + *offset * across;
      if (opacity(centred) < kHalf) break;
      const Vec2 turned = glm::normalize(dir + glm::normalize(centred - pos));
      if (glm::dot(turned, along) < std::cos(float(M_PI) / 6.f)) break;
      dir = turned, pos = centred;
    }
    const Vec2 stop = pos + (reach(pos, dir) - half_width) * dir;
    if (glm::dot(stop - tip, along) <= 0.25f) continue;
    ChainPoint q = end == 0 ? c.points.front() : c.points.back();
    q.p = stop;
    if (end == 0)
      c.points.insert(c.points.begin(), q);
    else
      c.points.push_back(q);
  }
}

// Adds to `on` the pixels of at least `low` opacity connected to it through such pixels.
void grow_into_faint(const ChainSource& s, const std::vector<float>& type_opacity, float low,
                     std::vector<uint32_t>& on) {
  std::vector<uint8_t> taken(type_opacity.size(), 0);
  for (uint32_t p : on) taken[p] = 1;
  std::vector<uint32_t> frontier = on;
  while (!frontier.empty()) {
    const uint32_t p = frontier.back();
    frontier.pop_back();
    const int px = int(p % uint32_t(s.width)), py = int(p / uint32_t(s.width));
    for (int y = std::max(py - 1, 0); y <= std::min(py + 1, s.height - 1); ++y)
      for (int x = std::max(px - 1, 0); x <= std::min(px + 1, s.width - 1); ++x) {
        const uint32_t q = uint32_t(y) * uint32_t(s.width) + uint32_t(x);
        if (taken[q] || type_opacity[q] < low) continue;
        taken[q] = 1;
        on.push_back(q);
        frontier.push_back(q);
      }
  }
}

// The skeleton lies on pixel centres, so as a line slides by less than a pixel its
// chain would stay, then jump. Each point moves across the line to the coverage's
// centroid there (sub-pixel, and continuous as the line moves), which is the line's
// middle for a line of any width.
void centre_on_ridge(const ChainSource& s, const std::vector<float>& type_opacity, Chain& c) {
  const size_t n = c.points.size();
  if (n < 3) return;
  std::vector<Vec2> moved(n);
  for (size_t i = 0; i < n; ++i) {
    const bool end = i == 0 || i + 1 == n;
    const Vec2 a = c.points[end && !c.closed ? (i == 0 ? 0 : i - 1) : (i + n - 1) % n].p;
    const Vec2 b = c.points[end && !c.closed ? (i == 0 ? 1 : i) : (i + 1) % n].p;
    moved[i] = c.points[i].p;
    if (glm::length(b - a) <= 0.f) continue;
    const Vec2 along = glm::normalize(b - a), across(-along.y, along.x);
    if (const auto offset = offset_across(s, type_opacity, c.points[i].p, across))
      moved[i] += std::clamp(*offset, -1.f, 1.f) * across;
  }
  for (size_t i = 0; i < n; ++i) c.points[i].p = moved[i];
}

// The value most points carry (-1 wins only where nothing else is seen).
int majority(const std::vector<int>& values) {
  std::unordered_map<int, int> counts;
  int best = -1, best_count = 0;
  for (int v : values) {
    const int c = ++counts[v];
    if (c > best_count || (c == best_count && best == -1)) best = v, best_count = c;
  }
  return best;
}

}  // namespace

std::vector<Chain> build_chains(const ChainSource& source, const ChainOptions& options) {
  std::vector<Chain> chains;
  if (source.width <= 0 || source.height <= 0) return chains;
  const size_t count = size_t(source.width) * size_t(source.height);
  std::vector<float> type_opacity(count, 0.f);
  PixelSkeleton skeleton(source.width, source.height);
  for (int t = 0; t < kLineTypeCount; ++t) {
    std::vector<uint32_t> on;
    for (size_t k = 0; k < source.pixels.size(); ++k) {
      const float o = source.opacity[k][size_t(t)];
      if (!(o > 0.f)) continue;
      type_opacity[source.pixels[k]] = o;
      if (o >= options.threshold) on.push_back(source.pixels[k]);
    }
    grow_into_faint(source, type_opacity, options.low_threshold, on);
    if (!on.empty()) {
      for (const PixelPath& traced : skeleton.trace(on, options.join_angle)) {
        Chain c;
        c.type = LineType(t);
        c.closed = traced.closed;
        c.ends_at_crossing = traced.ends_at_crossing;
        // Thinning may hook a line's last pixels aside; its ends come back along the
        // tangent of what is left (extend_ends).
        std::vector<Vec2> pixels = traced.pixels;
        if (!traced.closed && pixels.size() > 8) pixels = {pixels.begin() + 2, pixels.end() - 2};
        c.points = fit_chain(pixels, traced.closed, options.fit_tolerance, options.spacing);
        if (c.points.size() < 2) continue;
        centre_on_ridge(source, type_opacity, c);
        extend_ends(source, type_opacity, c);
        std::vector<int> objects, materials, paths;
        for (ChainPoint& q : c.points) {
          int object = -1, material = -1, path = 0;
          label_point(source, type_opacity, q, &object, &material, &path);
          objects.push_back(object), materials.push_back(material), paths.push_back(path);
        }
        c.object = majority(objects);
        c.material = majority(materials);
        c.path = LinePath(std::clamp(majority(paths), 0, kLinePathCount - 1));
        orient_chain(c);
        measure_curvature(c);
        chains.push_back(std::move(c));
      }
    }
    for (size_t k = 0; k < source.pixels.size(); ++k) type_opacity[source.pixels[k]] = 0.f;
  }
  return chains;
}

}  // namespace inkray
