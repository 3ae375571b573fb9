// Mesh surfaces: triangle picked by area, uniform barycentrics, and closest
// points found with Embree point queries (ties go to the lowest triangle index,
// so the answer does not depend on the BVH's traversal order).
#include "core/npr/strokes/mesh_surface.h"

#include "core/geometry/embree_device.h"
#include "core/math/hash.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <tuple>
#include <stdexcept>

namespace inkray {
namespace {

// Which part of a triangle a closest point lies on.
enum class Feature : uint8_t { interior, vertex_a, vertex_b, vertex_c, edge_ab, edge_ac, edge_bc };

struct Closest {
  Point3 q{0.f};
  float b1 = 0.f, b2 = 0.f;
  Feature feature = Feature::interior;
};

// Real-Time Collision Detection (Ericson), 5.1.5, with barycentrics kept.
Closest closest_on_triangle(const Point3& p, const Point3& a, const Point3& b, const Point3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.f && d2 <= 0.f) return {a, 0.f, 0.f, Feature::vertex_a};
  const Vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.f && d4 <= d3) return {b, 1.f, 0.f, Feature::vertex_b};
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.f && d1 >= 0.f && d3 <= 0.f) {
    const float v = d1 / (d1 - d3);
    return {a + v * ab, v, 0.f, Feature::edge_ab};
  }
  const Vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.f && d5 <= d6) return {c, 0.f, 1.f, Feature::vertex_c};
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.f && d2 >= 0.f && d6 <= 0.f) {
    const float w = d2 / (d2 - d6);
    return {a + w * ac, 0.f, w, Feature::edge_ac};
  }
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.f && d4 - d3 >= 0.f && d5 - d6 >= 0.f) {
    const float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + w * (c - b), 1.f - w, w, Feature::edge_bc};
  }
  const float denom = 1.f / (va + vb + vc);
  const float v = vb * denom, w = vc * denom;
  return {a + v * ab + w * ac, v, w, Feature::interior};
}

struct QueryState {
  const TriangleMesh* mesh = nullptr;
  Point3 p{0.f};
  float best_d2 = std::numeric_limits<float>::infinity();
  uint32_t tri = UINT32_MAX;
  Closest closest;
};

bool closest_point_callback(RTCPointQueryFunctionArguments* args) {
  auto* st = static_cast<QueryState*>(args->userPtr);
  const TriangleMesh& m = *st->mesh;
  const uint32_t tri = args->primID;
  const Closest c =
      closest_on_triangle(st->p, m.positions[m.indices[3 * tri]], m.positions[m.indices[3 * tri + 1]],
                          m.positions[m.indices[3 * tri + 2]]);
  const Vec3 delta = st->p - c.q;
  const float d2 = glm::dot(delta, delta);
  if (d2 > st->best_d2 || (d2 == st->best_d2 && tri > st->tri)) return false;
  st->best_d2 = d2;
  st->tri = tri;
  st->closest = c;
  const float r = std::sqrt(d2);
  if (r >= args->query->radius) return false;
  args->query->radius = r;
  return true;
}

Vec3 face_normal(const TriangleMesh& m, uint32_t tri) {
  const Point3& a = m.positions[m.indices[3 * tri]];
  const Vec3 n = glm::cross(m.positions[m.indices[3 * tri + 1]] - a, m.positions[m.indices[3 * tri + 2]] - a);
  const float len = glm::length(n);
  return len > 0.f ? n / len : Vec3(0.f, 0.f, 1.f);
}

std::vector<float> triangle_areas(const TriangleMesh& mesh) {
  std::vector<float> areas(mesh.triangle_count());
  for (size_t t = 0; t < areas.size(); ++t) areas[t] = mesh.triangle_area(t);
  return areas;
}

// Bits of MeshSurface::boundary_.
constexpr uint8_t kEdgeAb = 1, kEdgeBc = 2, kEdgeCa = 4, kVertexA = 8, kVertexB = 16, kVertexC = 32;

// Per triangle, which of its edges border no other triangle and which of its
// corners touch such an edge. Vertices at the same position count as one, so
// the seams of a mesh split for uvs or normals are not boundaries.
std::vector<uint8_t> boundary_flags(const TriangleMesh& m) {
  const size_t nv = m.vertex_count(), nt = m.triangle_count();
  std::vector<uint32_t> order(nv);
  for (uint32_t i = 0; i < nv; ++i) order[i] = i;
  // By bits, which order even NaNs.
  const auto key = [&](uint32_t i) {
    const Point3& p = m.positions[i];
    return std::make_tuple(std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y),
                           std::bit_cast<uint32_t>(p.z));
  };
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
  std::vector<uint32_t> weld(nv);
  uint32_t id = 0;
  for (size_t k = 0; k < nv; ++k) {
    if (k > 0 && key(order[k]) != key(order[k - 1])) ++id;
    weld[order[k]] = id;
  }
  const auto edge = [&](size_t t, int e) {
    const uint64_t a = weld[m.indices[3 * t + size_t(e)]], b = weld[m.indices[3 * t + size_t((e + 1) % 3)]];
    return std::min(a, b) << 32 | std::max(a, b);
  };
  std::vector<uint64_t> edges(3 * nt);
  for (size_t t = 0; t < nt; ++t)
    for (int e = 0; e < 3; ++e) edges[3 * t + size_t(e)] = edge(t, e);
  std::sort(edges.begin(), edges.end());
  std::vector<uint8_t> flags(nt, 0);
  std::vector<bool> on_boundary(size_t(id) + 1, false);
  for (size_t t = 0; t < nt; ++t)
    for (int e = 0; e < 3; ++e) {
      const uint64_t k = edge(t, e);
      const auto range = std::equal_range(edges.begin(), edges.end(), k);
      if (range.second - range.first != 1) continue;
      flags[t] |= uint8_t(kEdgeAb << e);
      on_boundary[size_t(k >> 32)] = on_boundary[size_t(k & 0xffffffffu)] = true;
    }
  for (size_t t = 0; t < nt; ++t)
    for (int c = 0; c < 3; ++c)
      if (on_boundary[weld[m.indices[3 * t + size_t(c)]]]) flags[t] |= uint8_t(kVertexA << c);
  return flags;
}

bool on_boundary(uint8_t flags, Feature f) {
  switch (f) {
    case Feature::interior:
      return false;
    case Feature::vertex_a:
      return flags & kVertexA;
    case Feature::vertex_b:
      return flags & kVertexB;
    case Feature::vertex_c:
      return flags & kVertexC;
    case Feature::edge_ab:
      return flags & kEdgeAb;
    case Feature::edge_bc:
      return flags & kEdgeBc;
    case Feature::edge_ac:
      return flags & kEdgeCa;
  }
  return false;
}

}  // namespace

struct MeshSurface::Bvh {
  RTCScene scene = nullptr;
  ~Bvh() {
    if (scene) rtcReleaseScene(scene);
  }
};

MeshSurface::MeshSurface(const TriangleMesh& mesh)
    : mesh_(&mesh),
      triangles_(triangle_areas(mesh)),
      boundary_(boundary_flags(mesh)),
      bvh_(std::make_unique<Bvh>()) {
  RTCDevice device = shared_embree_device();
  bvh_->scene = rtcNewScene(device);
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh.positions.data(), 0,
                             sizeof(Point3), mesh.vertex_count());
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices.data(), 0,
                             3 * sizeof(uint32_t), mesh.triangle_count());
  rtcCommitGeometry(geom);
  rtcAttachGeometry(bvh_->scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(bvh_->scene);
}

MeshSurface::~MeshSurface() = default;
MeshSurface::MeshSurface(MeshSurface&&) noexcept = default;
MeshSurface& MeshSurface::operator=(MeshSurface&&) noexcept = default;

SurfacePoint MeshSurface::at(uint32_t tri, float b1, float b2) const {
  const TriangleMesh& m = *mesh_;
  const uint32_t i0 = m.indices[3 * tri], i1 = m.indices[3 * tri + 1], i2 = m.indices[3 * tri + 2];
  const float b0 = 1.f - b1 - b2;
  SurfacePoint sp;
  sp.prim = tri;
  sp.p = b0 * m.positions[i0] + b1 * m.positions[i1] + b2 * m.positions[i2];
  const MeshShading shading = interpolate_shading(m, tri, b1, b2, face_normal(m, tri));
  sp.ng = shading.ng;
  sp.n = shading.ns;
  sp.uv = shading.uv;
  sp.color = shading.color;
  return sp;
}

void MeshSurface::sample_triangle(uint32_t seed, uint32_t index, uint32_t* tri, float* b1, float* b2) const {
  const auto u = [&](uint32_t dim) { return u32_to_unit_float(hash_combine(seed, index, dim)); };
  float pmf = 0.f;
  *tri = uint32_t(triangles_.sample(u(0), &pmf));
  // Uniform over the triangle (pbrt-v4's square-root warp).
  const float s = std::sqrt(u(1)), t = u(2);
  *b1 = s * t;
  *b2 = 1.f - s;
}

SurfacePoint MeshSurface::sample(uint32_t seed, uint32_t index) const {
  uint32_t tri = 0;
  float b1 = 0.f, b2 = 0.f;
  sample_triangle(seed, index, &tri, &b1, &b2);
  return at(tri, b1, b2);
}

Point3 MeshSurface::sample_position(uint32_t seed, uint32_t index) const {
  uint32_t tri = 0;
  float b1 = 0.f, b2 = 0.f;
  sample_triangle(seed, index, &tri, &b1, &b2);
  const TriangleMesh& m = *mesh_;
  return (1.f - b1 - b2) * m.positions[m.indices[3 * tri]] + b1 * m.positions[m.indices[3 * tri + 1]] +
         b2 * m.positions[m.indices[3 * tri + 2]];
}

SurfacePoint MeshSurface::project(const Point3& p, float near) const {
  QueryState st;
  st.mesh = mesh_;
  st.p = p;
  const auto query_within = [&](float radius) {
    RTCPointQuery query{};
    query.x = p.x;
    query.y = p.y;
    query.z = p.z;
    query.time = 0.f;
    query.radius = radius;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(bvh_->scene, &query, &context, closest_point_callback, &st);
  };
  // Every triangle closer than the closest one's distance is visited either way,
  // so a bounded query finds the same triangle. The margin covers the rounding of
  // the caller's distance; should nothing lie within it, search everywhere.
  if (near < kInfinity) query_within(1.5f * near + 1e-6f * (std::abs(p.x) + std::abs(p.y) + std::abs(p.z)));
  if (st.tri == UINT32_MAX) query_within(kInfinity);
  if (st.tri == UINT32_MAX) throw std::logic_error("MeshSurface::project: empty mesh");
  SurfacePoint sp = at(st.tri, st.closest.b1, st.closest.b2);
  sp.p = st.closest.q;
  const float dist = std::sqrt(st.best_d2);
  const bool off_facet =
      st.closest.feature != Feature::interior && dist > 1e-4f * std::sqrt(mesh_->triangle_area(st.tri));
  if (off_facet && on_boundary(boundary_[st.tri], st.closest.feature)) {
    sp.boundary = true;  // past the edge of an open mesh: there is no surface to round over
    return sp;
  }
  if (off_facet && mesh_->normals.empty()) {
    // Past a flat-shaded edge: the direction to p is the normal of the surface
    // rounded over that edge, between the facets that meet there.
    Vec3 n = (p - sp.p) / dist;
    // From inside, the direction points in: turn it out. Not by its sign alone:
    // a point straight out from the other facet at the edge is perpendicular to
    // this one's normal, and rounding would pick either side.
    if (glm::dot(n, sp.ng) < -1e-3f) n = -n;
    sp.n = n;
  }
  return sp;
}

}  // namespace inkray
