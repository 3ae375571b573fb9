// Fans are found with a union-find over triangle corners: the two corners of each
// smooth edge's triangles at each of its ends are joined. Weights are corner angles,
// not areas or plain counts: a fan's normal then depends on the surface, not on how
// it was cut into triangles (a quad split into two or into eight thin triangles
// pulls the normal equally; area weights let large neighbours drown small ones).
#include "core/geometry/mesh_normals.h"

#include "core/geometry/mesh_features.h"

#include <cmath>
#include <numeric>

namespace inkray {
namespace {

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

void join(std::vector<uint32_t>& parent, uint32_t a, uint32_t b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

// The angle of a triangle at corner p, between the edges to q and r; 0 where undefined.
float corner_angle(const Point3& p, const Point3& q, const Point3& r) {
  const Vec3 e1 = q - p, e2 = r - p;
  const float angle = std::atan2(glm::length(glm::cross(e1, e2)), glm::dot(e1, e2));
  return std::isfinite(angle) ? angle : 0.f;
}

// A unit vector along v, or none when v has no usable direction.
bool unit(const Vec3& v, Normal3* out) {
  const float len = glm::length(v);
  if (!(len > 0.f) || !std::isfinite(len)) return false;
  *out = v / len;
  return std::isfinite(out->x) && std::isfinite(out->y) && std::isfinite(out->z);
}

}  // namespace

bool needs_auto_smooth(const TriangleMeshData& mesh, float smooth_angle_degrees) {
  return mesh.normals.empty() && smooth_angle_degrees > 0.f && !mesh.indices.empty();
}

TriangleMeshData auto_smooth(const TriangleMeshData& mesh, float smooth_angle_degrees) {
  if (!needs_auto_smooth(mesh, smooth_angle_degrees)) return mesh;
  const std::vector<Point3>& p = mesh.positions;
  const std::vector<uint32_t>& idx = mesh.indices;
  const size_t corners = idx.size() - idx.size() % 3;

  // Facet normals (zero for degenerate triangles), and each corner's weight.
  std::vector<Normal3> facets(corners / 3);
  std::vector<float> weight(corners, 0.f);
  for (size_t t = 0; t < corners / 3; ++t) {
    const Point3 &a = p[idx[3 * t]], &b = p[idx[3 * t + 1]], &c = p[idx[3 * t + 2]];
    facets[t] = facet_normal(a, b, c);
    if (facets[t] == Normal3(0.f)) continue;
    weight[3 * t] = corner_angle(a, b, c);
    weight[3 * t + 1] = corner_angle(b, c, a);
    weight[3 * t + 2] = corner_angle(c, a, b);
  }

  // Corners at one position join through every smooth edge around it. A degenerate
  // triangle's edges have an infinite angle: it joins nothing, so it never bridges two
  // fans that meet at a sharp edge.
  std::vector<uint32_t> fan(corners);
  std::iota(fan.begin(), fan.end(), 0u);
  const MeshFeatures features = find_feature_edges(p, std::span(idx.data(), corners));
  const auto next = [](uint32_t h) { return h - h % 3 + (h % 3 + 1) % 3; };
  for (const FeatureEdge& e : features.edges) {
    if (!(e.dihedral <= smooth_angle_degrees)) continue;
    // Half-edge a runs from corner e.a to next(e.a); b runs either way along it.
    if (p[idx[e.a]] == p[idx[e.b]]) {
      join(fan, e.a, e.b);
      join(fan, next(e.a), next(e.b));
    } else {
      join(fan, e.a, next(e.b));
      join(fan, next(e.a), e.b);
    }
  }
  std::vector<Vec3> sum(corners, Vec3(0.f));
  for (size_t c = 0; c < corners; ++c) sum[find_root(fan, uint32_t(c))] += weight[c] * facets[c / 3];

  // Corners grouped by vertex (a counting sort), so each vertex splits into one new
  // vertex per fan among its corners, in the order they first appear.
  std::vector<uint32_t> start(p.size() + 1, 0);
  for (size_t c = 0; c < corners; ++c) ++start[idx[c] + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<uint32_t> by_vertex(corners);
  {
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t c = 0; c < corners; ++c) by_vertex[fill[idx[c]]++] = uint32_t(c);
  }

  TriangleMeshData out;
  out.indices.resize(corners);
  out.positions.reserve(p.size());
  out.normals.reserve(p.size());
  if (!mesh.uvs.empty()) out.uvs.reserve(p.size());
  std::vector<uint32_t> vertex_of_fan(corners, UINT32_MAX), fan_owner(corners, UINT32_MAX);
  for (uint32_t v = 0; v < p.size(); ++v) {
    for (uint32_t i = start[v]; i < start[v + 1]; ++i) {
      const uint32_t c = by_vertex[i], root = find_root(fan, c);
      if (fan_owner[root] != v) {
        fan_owner[root] = v;
        vertex_of_fan[root] = uint32_t(out.positions.size());
        Normal3 n;
        // A fan of degenerate triangles only, or whose normals cancel (a sheet folded
        // flat at 180 degrees): its first triangle's normal, else any the vertex has.
        if (!unit(sum[root], &n) && !unit(facets[c / 3], &n)) {
          Vec3 around(0.f);
          for (uint32_t j = start[v]; j < start[v + 1]; ++j) around += facets[by_vertex[j] / 3];
          if (!unit(around, &n)) n = Normal3(0.f, 0.f, 1.f);
        }
        out.positions.push_back(p[v]);
        out.normals.push_back(n);
        if (!mesh.uvs.empty()) out.uvs.push_back(mesh.uvs[v]);
      }
      out.indices[c] = vertex_of_fan[root];
    }
  }
  return out;
}

}  // namespace inkray
