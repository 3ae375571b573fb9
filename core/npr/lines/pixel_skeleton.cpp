// Thinning, tracing and joining of one line type's pixels (pixel_skeleton.h).
#include "core/npr/lines/pixel_skeleton.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numeric>

namespace inkray {
namespace {

// Neighbour bits in ring order: N, NE, E, SE, S, SW, W, NW.
constexpr std::array<int, 8> kDx = {0, 1, 1, 1, 0, -1, -1, -1};
constexpr std::array<int, 8> kDy = {-1, -1, 0, 1, 1, 1, 0, -1};
constexpr int bit(int k) { return 1 << k; }

// Zhang-Suen's conditions for removing a pixel in its first (step 0) or second
// sub-iteration, from its neighbours alone: 2..6 neighbours, one run of them round
// the ring, and not the last link on the side the step erodes.
constexpr bool zhang_suen_removes(int n, int step) {
  const int count = std::popcount(unsigned(n));
  if (count < 2 || count > 6) return false;
  int runs = 0;
  for (int k = 0; k < 8; ++k) runs += !(n & bit(k)) && (n & bit((k + 1) % 8));
  if (runs != 1) return false;
  const bool north = n & bit(0), east = n & bit(2), south = n & bit(4), west = n & bit(6);
  if (step == 0) return !(north && east && south) && !(east && south && west);
  return !(north && east && west) && !(north && south && west);
}

// Whether the set neighbours stay one 8-connected group without the pixel: two ring
// neighbours touch when consecutive, and two edge neighbours a corner apart (N and
// E) touch diagonally.
constexpr bool neighbours_connected(int n) {
  std::array<int, 8> group{};
  for (int k = 0; k < 8; ++k) group[size_t(k)] = k;
  auto find = [&](int k) {
    while (group[size_t(k)] != k) k = group[size_t(k)];
    return k;
  };
  auto join = [&](int a, int b) {
    if ((n & bit(a)) && (n & bit(b))) group[size_t(find(a))] = find(b);
  };
  for (int k = 0; k < 8; ++k) join(k, (k + 1) % 8);
  for (int k = 0; k < 8; k += 2) join(k, (k + 2) % 8);
  int groups = 0;
  for (int k = 0; k < 8; ++k) groups += (n & bit(k)) && find(k) == k;
  return groups == 1;
}

// A staircase's corner pixel: two edge neighbours at right angles that already
// touch diagonally, so the pixel only thickens the path and makes a false crossing.
constexpr bool is_stair_corner(int n) {
  const bool north = n & bit(0), east = n & bit(2), south = n & bit(4), west = n & bit(6);
  const bool corner = (north && east) || (east && south) || (south && west) || (west && north);
  return corner && std::popcount(unsigned(n)) >= 2 && neighbours_connected(n);
}

template <typename F>
constexpr std::array<bool, 256> table(F f) {
  std::array<bool, 256> t{};
  for (int n = 0; n < 256; ++n) t[size_t(n)] = f(n);
  return t;
}
constexpr auto kRemoveStep0 = table([](int n) { return zhang_suen_removes(n, 0); });
constexpr auto kRemoveStep1 = table([](int n) { return zhang_suen_removes(n, 1); });
constexpr auto kStairCorner = table(is_stair_corner);

struct Segment {
  std::vector<uint32_t> pixels;
  std::array<int, 2> cluster{-1, -1};  // the crossing each end lies in; -1: a free end
  bool closed = false;
};

}  // namespace

PixelSkeleton::PixelSkeleton(int width, int height)
    : width_(width), height_(height), mask_(size_t(width) * size_t(height), 0) {}

int PixelSkeleton::neighbours(uint32_t i) const {
  const int x = int(i % uint32_t(width_)), y = int(i / uint32_t(width_));
  int n = 0;
  for (int k = 0; k < 8; ++k) {
    const int nx = x + kDx[size_t(k)], ny = y + kDy[size_t(k)];
    if (nx < 0 || ny < 0 || nx >= width_ || ny >= height_) continue;
    if (mask_[size_t(ny) * size_t(width_) + size_t(nx)]) n |= bit(k);
  }
  return n;
}

void PixelSkeleton::thin(std::vector<uint32_t>& on) {
  std::vector<uint32_t> removed;
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto* removes : {&kRemoveStep0, &kRemoveStep1}) {
      removed.clear();
      for (uint32_t i : on)
        if ((*removes)[size_t(neighbours(i))]) removed.push_back(i);
      for (uint32_t i : removed) mask_[i] = 0;
      changed |= !removed.empty();
      std::erase_if(on, [&](uint32_t i) { return !mask_[i]; });
    }
  }
}

void PixelSkeleton::remove_staircases(std::vector<uint32_t>& on) {
  // One pass in scan order, each removal seen by the next test, so of two corners
  // that make each other redundant only one goes.
  for (uint32_t i : on)
    if (kStairCorner[size_t(neighbours(i))]) mask_[i] = 0;
  std::erase_if(on, [&](uint32_t i) { return !mask_[i]; });
}

std::vector<PixelPath> PixelSkeleton::trace(const std::vector<uint32_t>& input, float join_angle) {
  std::vector<uint32_t> on = input;
  std::sort(on.begin(), on.end());
  for (uint32_t i : on) mask_[i] = 1;
  thin(on);
  remove_staircases(on);

  const auto at = [&](uint32_t i, int k) {
    const int x = int(i % uint32_t(width_)) + kDx[size_t(k)], y = int(i / uint32_t(width_)) + kDy[size_t(k)];
    return uint32_t(y) * uint32_t(width_) + uint32_t(x);
  };
  // Degrees, and crossings as clusters of touching pixels of three or more neighbours.
  std::vector<int> degree(on.size()), cluster(on.size(), -1);
  const auto index_of = [&](uint32_t p) {
    return size_t(std::lower_bound(on.begin(), on.end(), p) - on.begin());
  };
  for (size_t k = 0; k < on.size(); ++k) degree[k] = std::popcount(unsigned(neighbours(on[k])));
  int clusters = 0;
  for (size_t k = 0; k < on.size(); ++k) {
    if (degree[k] < 3 || cluster[k] >= 0) continue;
    std::vector<size_t> stack{k};
    cluster[k] = clusters;
    while (!stack.empty()) {
      const size_t c = stack.back();
      stack.pop_back();
      const int n = neighbours(on[c]);
      for (int d = 0; d < 8; ++d) {
        if (!(n & bit(d))) continue;
        const size_t q = index_of(at(on[c], d));
        if (degree[q] >= 3 && cluster[q] < 0) cluster[q] = clusters, stack.push_back(q);
      }
    }
    ++clusters;
  }

  // Segments between ends and crossings, then loops with neither.
  std::vector<uint8_t> visited(on.size(), 0);
  std::vector<Segment> segments;
  const auto is_node = [&](size_t k) { return degree[k] != 2; };
  // The first neighbour of `cur` other than `prev` that `open` accepts; on.size() if none.
  const auto step = [&](size_t cur, size_t prev, const auto& open) {
    const int m = neighbours(on[cur]);
    for (int e = 0; e < 8; ++e) {
      if (!(m & bit(e))) continue;
      const size_t r = index_of(at(on[cur], e));
      if (r != prev && open(r)) return r;
    }
    return on.size();
  };
  for (size_t s = 0; s < on.size(); ++s) {
    if (!is_node(s) || degree[s] == 0) continue;
    const int n = neighbours(on[s]);
    for (int d = 0; d < 8; ++d) {
      if (!(n & bit(d))) continue;
      size_t q = index_of(at(on[s], d));
      if (is_node(q)) {
        // Two nodes side by side: a link only between different crossings or ends.
        const bool same_crossing = cluster[s] >= 0 && cluster[s] == cluster[q];
        if (!same_crossing && s < q) segments.push_back({{on[s], on[q]}, {cluster[s], cluster[q]}});
        continue;
      }
      if (visited[q]) continue;
      Segment seg{{on[s], on[q]}, {cluster[s], -1}};
      visited[q] = 1;
      size_t prev = s, cur = q;
      for (;;) {
        const size_t next = step(cur, prev, [&](size_t r) { return is_node(r) || !visited[r]; });
        if (next == on.size()) break;
        seg.pixels.push_back(on[next]);
        if (is_node(next)) {
          seg.cluster[1] = cluster[next];
          break;
        }
        visited[next] = 1;
        prev = cur, cur = next;
      }
      segments.push_back(std::move(seg));
    }
  }
  for (size_t s = 0; s < on.size(); ++s) {
    if (is_node(s) || visited[s]) continue;
    Segment loop{{on[s]}, {-1, -1}, true};
    visited[s] = 1;
    size_t prev = on.size(), cur = s;
    for (;;) {
      const size_t next = step(cur, prev, [&](size_t r) { return !visited[r] && !is_node(r); });
      if (next == on.size()) break;
      loop.pixels.push_back(on[next]);
      visited[next] = 1;
      prev = cur, cur = next;
    }
    segments.push_back(std::move(loop));
  }
  // Spurs: a pixel or two from a crossing to a free end, left where thinning met a
  // line's end or a blunt corner.
  std::erase_if(segments, [](const Segment& g) {
    return !g.closed && g.pixels.size() <= 3 && ((g.cluster[0] >= 0) != (g.cluster[1] >= 0));
  });

  // Through each crossing, pair the ends that continue each other most nearly straight.
  const auto pos = [&](uint32_t p) {
    return Vec2(float(p % uint32_t(width_)) + 0.5f, float(p / uint32_t(width_)) + 0.5f);
  };
  const auto inward = [&](const Segment& g, int end) {
    const size_t n = g.pixels.size(), back = std::min<size_t>(6, n - 1);
    const Vec2 tip = pos(end == 0 ? g.pixels.front() : g.pixels.back());
    const Vec2 from = pos(end == 0 ? g.pixels[back] : g.pixels[n - 1 - back]);
    const Vec2 d = tip - from;
    return glm::length(d) > 0.f ? glm::normalize(d) : Vec2(0.f);
  };
  std::vector<std::array<std::pair<int, int>, 2>> link(segments.size(), {{{-1, 0}, {-1, 0}}});
  {
    auto ends = std::vector<std::vector<std::pair<int, int>>>(size_t(clusters));
    for (size_t g = 0; g < segments.size(); ++g)
      for (int e = 0; e < 2; ++e)
        if (!segments[g].closed && segments[g].cluster[size_t(e)] >= 0)
          ends[size_t(segments[g].cluster[size_t(e)])].push_back({int(g), e});
    const float max_turn = std::cos(join_angle * float(M_PI) / 180.f);
    for (const auto& here : ends) {
      struct Pair {
        float straightness;
        size_t a, b;
      };
      std::vector<Pair> pairs;
      for (size_t a = 0; a < here.size(); ++a)
        for (size_t b = a + 1; b < here.size(); ++b) {
          const float s = -glm::dot(inward(segments[size_t(here[a].first)], here[a].second),
                                    inward(segments[size_t(here[b].first)], here[b].second));
          if (s > max_turn) pairs.push_back({s, a, b});
        }
      std::sort(pairs.begin(), pairs.end(),
                [](const Pair& x, const Pair& y) { return x.straightness > y.straightness; });
      std::vector<uint8_t> paired(here.size(), 0);
      for (const Pair& p : pairs) {
        if (paired[p.a] || paired[p.b]) continue;
        paired[p.a] = paired[p.b] = 1;
        const auto [ga, ea] = here[p.a];
        const auto [gb, eb] = here[p.b];
        link[size_t(ga)][size_t(ea)] = {gb, eb};
        link[size_t(gb)][size_t(eb)] = {ga, ea};
      }
    }
  }

  // Walk the links: from unlinked ends first, then what is left is joined in loops.
  std::vector<PixelPath> paths;
  std::vector<uint8_t> used(segments.size(), 0);
  const auto walk = [&](int g, int enter, bool loop) {
    PixelPath path;
    path.closed = loop;
    path.ends_at_crossing[0] = segments[size_t(g)].cluster[size_t(enter)] >= 0;
    while (g >= 0 && !used[size_t(g)]) {
      used[size_t(g)] = 1;
      const Segment& seg = segments[size_t(g)];
      path.closed = path.closed || seg.closed;
      std::vector<uint32_t> px = seg.pixels;
      if (enter == 1) std::reverse(px.begin(), px.end());
      for (uint32_t p : px) {
        const Vec2 v = pos(p);
        if (path.pixels.empty() || path.pixels.back() != v) path.pixels.push_back(v);
      }
      path.ends_at_crossing[1] = seg.cluster[size_t(1 - enter)] >= 0;
      const auto [next, next_end] = link[size_t(g)][size_t(1 - enter)];
      g = next, enter = next_end;
    }
    if (path.closed) path.ends_at_crossing = {false, false};
    if (path.closed && path.pixels.size() > 1 && path.pixels.front() == path.pixels.back())
      path.pixels.pop_back();
    if (path.pixels.size() >= 2) paths.push_back(std::move(path));
  };
  for (size_t g = 0; g < segments.size(); ++g)
    for (int e = 0; e < 2; ++e)
      if (!used[g] && !segments[g].closed && link[g][size_t(e)].first < 0) walk(int(g), e, false);
  for (size_t g = 0; g < segments.size(); ++g)
    if (!used[g]) walk(int(g), 0, true);

  for (uint32_t i : on) mask_[i] = 0;
  return paths;
}

}  // namespace inkray
