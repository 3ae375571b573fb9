// Edges by welded position in linear time after one sort of the vertices: half-edges
// are bucketed by their lower vertex (a counting sort), so matching them needs no
// hash table; patches are a union-find over the smooth edges.
#include "core/geometry/mesh_features.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>

namespace inkray {
namespace {

float angle_degrees(const Normal3& a, const Normal3& b) {
  if (a == Normal3(0.f) || b == Normal3(0.f)) return std::numeric_limits<float>::infinity();
  return glm::degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];  // path halving
    x = parent[x];
  }
  return x;
}

}  // namespace

std::vector<uint32_t> weld_positions(std::span<const Point3> positions) {
  struct Key {
    uint32_t x, y, z, vertex;
  };
  // Adding +0 turns -0 into +0: the two are equal positions with different bits.
  const auto bits = [](float f) { return std::bit_cast<uint32_t>(f + 0.f); };
  std::vector<Key> keys(positions.size());
  for (size_t v = 0; v < positions.size(); ++v)
    keys[v] = {bits(positions[v].x), bits(positions[v].y), bits(positions[v].z), uint32_t(v)};
  std::sort(keys.begin(), keys.end(), [](const Key& l, const Key& r) {
    if (l.x != r.x) return l.x < r.x;
    if (l.y != r.y) return l.y < r.y;
    return l.z < r.z;
  });
  std::vector<uint32_t> welded(positions.size());
  uint32_t id = 0;
  for (size_t i = 0; i < keys.size(); ++i) {
    if (i > 0 && (keys[i].x != keys[i - 1].x || keys[i].y != keys[i - 1].y || keys[i].z != keys[i - 1].z))
      ++id;
    welded[keys[i].vertex] = id;
  }
  return welded;
}

Normal3 facet_normal(const Point3& a, const Point3& b, const Point3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 n = glm::cross(e1, e2);
  const float len = glm::length(n);
  // The sine of the angle between the edges below float's resolution (or no edge at
  // all, or an overflow): the cross product's direction is rounding noise.
  if (!(len > 1e-6f * glm::length(e1) * glm::length(e2)) || !std::isfinite(len)) return Normal3(0.f);
  return n / len;
}

MeshFeatures find_feature_edges(std::span<const Point3> positions, std::span<const uint32_t> indices) {
  MeshFeatures out;
  const size_t triangles = indices.size() / 3;
  out.triangles = uint32_t(triangles);
  if (triangles == 0) return out;
  const std::vector<uint32_t> welded = weld_positions(positions);
  const size_t welded_count = size_t(*std::max_element(welded.begin(), welded.end())) + 1;

  // Half-edges bucketed by their lower welded vertex, each with its upper one.
  struct HalfEdge {
    uint32_t upper, id;
  };
  std::vector<uint32_t> start(welded_count + 1, 0);
  const auto ends = [&](size_t h) {
    const uint32_t p = welded[indices[h]], q = welded[indices[h - h % 3 + (h % 3 + 1) % 3]];
    return std::pair{std::min(p, q), std::max(p, q)};
  };
  for (size_t h = 0; h < 3 * triangles; ++h) {
    const auto [lo, hi] = ends(h);
    if (lo != hi) ++start[lo + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<HalfEdge> bucketed(start.back());
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (size_t h = 0; h < 3 * triangles; ++h) {
    const auto [lo, hi] = ends(h);
    if (lo != hi) bucketed[fill[lo]++] = {hi, uint32_t(h)};
  }
  fill = {};

  std::vector<Normal3> normals(triangles);
  for (size_t t = 0; t < triangles; ++t)
    normals[t] =
        facet_normal(positions[indices[3 * t]], positions[indices[3 * t + 1]], positions[indices[3 * t + 2]]);
  const auto add = [&](uint32_t a, uint32_t b) {
    if (a / 3 == b / 3) return;  // one triangle twice: a degenerate one folded on itself
    out.edges.push_back({a, b, angle_degrees(normals[a / 3], normals[b / 3])});
  };

  out.edges.reserve(3 * triangles / 2);
  for (size_t lo = 0; lo < welded_count; ++lo) {
    const auto first = bucketed.begin() + start[lo], last = bucketed.begin() + start[lo + 1];
    // Buckets are small (a vertex's valence): sorting each is linear overall.
    std::sort(first, last, [](const HalfEdge& l, const HalfEdge& r) {
      return l.upper != r.upper ? l.upper < r.upper : l.id < r.id;
    });
    for (auto group = first; group != last;) {
      auto end = group;
      while (end != last && end->upper == group->upper) ++end;
      const size_t n = size_t(end - group);
      if (n <= kMaxPairedFan) {
        for (auto i = group; i != end; ++i)
          for (auto j = i + 1; j != end; ++j) add(i->id, j->id);
      } else {
        for (auto i = group; i + 1 != end; ++i) add(i->id, (i + 1)->id);
      }
      group = end;
    }
  }
  return out;
}

std::vector<uint32_t> smooth_patches(const MeshFeatures& features, float threshold_degrees) {
  const uint32_t n = features.triangles;
  std::vector<uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const FeatureEdge& e : features.edges) {
    if (!(e.dihedral <= threshold_degrees)) continue;
    uint32_t a = find_root(parent, e.a / 3), b = find_root(parent, e.b / 3);
    if (a == b) continue;
    // The lower index becomes the root: no ranks to keep, and path halving keeps the
    // trees shallow.
    if (b < a) std::swap(a, b);
    parent[b] = a;
  }
  // Roots are the lowest triangle of their patch, so numbering roots in triangle
  // order numbers patches by their first triangle.
  std::vector<uint32_t> patch(n);
  uint32_t next = 0;
  for (uint32_t t = 0; t < n; ++t) {
    const uint32_t root = find_root(parent, t);
    patch[t] = root == t ? next++ : patch[root];
  }
  return patch;
}

}  // namespace inkray
