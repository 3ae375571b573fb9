#include "core/geometry/triangle_mesh.h"

#include <cmath>

namespace inkray {

float TriangleMesh::triangle_area(size_t tri) const {
  const Point3& a = positions[indices[3 * tri]];
  const Point3& b = positions[indices[3 * tri + 1]];
  const Point3& c = positions[indices[3 * tri + 2]];
  return 0.5f * glm::length(glm::cross(b - a, c - a));
}

MeshShading interpolate_shading(const TriangleMesh& mesh, uint32_t tri, float b1, float b2,
                                const Normal3& ng) {
  const uint32_t i0 = mesh.indices[3 * size_t(tri)], i1 = mesh.indices[3 * size_t(tri) + 1],
                 i2 = mesh.indices[3 * size_t(tri) + 2];
  const float b0 = 1.f - b1 - b2;
  MeshShading s;
  s.ng = ng;
  s.ns = ng;
  if (!mesh.normals.empty()) {
    const Vec3 ns = b0 * mesh.normals[i0] + b1 * mesh.normals[i1] + b2 * mesh.normals[i2];
    const float ns_len = glm::length(ns);
    if (ns_len > 0.f) {
      s.ns = ns / ns_len;
      // Keep the geometric normal on the side the shading normal says is outside.
      if (glm::dot(s.ng, s.ns) < 0.f) s.ng = -s.ng;
    }
  }
  s.uv = mesh.uvs.empty() ? Vec2(b1, b2) : b0 * mesh.uvs[i0] + b1 * mesh.uvs[i1] + b2 * mesh.uvs[i2];
  if (!mesh.colors.empty()) s.color = b0 * mesh.colors[i0] + b1 * mesh.colors[i1] + b2 * mesh.colors[i2];
  return s;
}

TriangleMesh make_mesh(std::vector<Point3> positions, std::vector<Normal3> normals, std::vector<Vec2> uvs,
                       std::vector<uint32_t> indices, const Transform& to_world) {
  TriangleMesh mesh;
  if (!to_world.is_identity()) {
    for (Point3& p : positions) p = to_world.point(p);
    for (Normal3& n : normals) n = glm::normalize(to_world.normal(n));
  }
  mesh.positions = std::move(positions);
  mesh.positions.push_back(Point3(0.f));
  mesh.normals = std::move(normals);
  mesh.uvs = std::move(uvs);
  mesh.indices = std::move(indices);
  return mesh;
}

TriangleMesh transformed(const TriangleMesh& mesh, const Transform& to_world) {
  TriangleMesh out = mesh;
  for (size_t v = 0; v < out.vertex_count(); ++v) out.positions[v] = to_world.point(out.positions[v]);
  for (Normal3& n : out.normals) n = glm::normalize(to_world.normal(n));
  return out;
}

TriangleMesh make_quad(const Point3& corner, const Vec3& edge_u, const Vec3& edge_v,
                       const Transform& to_world) {
  std::vector<Point3> p = {corner, corner + edge_u, corner + edge_u + edge_v, corner + edge_v};
  std::vector<Vec2> uv = {{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}, {0.f, 1.f}};
  return make_mesh(std::move(p), {}, std::move(uv), {0, 1, 2, 0, 2, 3}, to_world);
}

TriangleMesh make_box(const Point3& lo, const Point3& hi, const Transform& to_world) {
  const Vec3 dx(hi.x - lo.x, 0.f, 0.f), dy(0.f, hi.y - lo.y, 0.f), dz(0.f, 0.f, hi.z - lo.z);
  // Each face: corner and two edges ordered so cross(edge_u, edge_v) points outward.
  const Point3 corners[6] = {lo, lo, lo, hi, hi, hi};
  const Vec3 edges_u[6] = {dy, dz, dx, -dy, -dz, -dx};
  const Vec3 edges_v[6] = {dx, dy, dz, -dz, -dx, -dy};
  std::vector<Point3> p;
  std::vector<Vec2> uv;
  std::vector<uint32_t> idx;
  for (int f = 0; f < 6; ++f) {
    const uint32_t base = uint32_t(p.size());
    p.insert(p.end(), {corners[f], corners[f] + edges_u[f], corners[f] + edges_u[f] + edges_v[f],
                       corners[f] + edges_v[f]});
    uv.insert(uv.end(), {{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}, {0.f, 1.f}});
    idx.insert(idx.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return make_mesh(std::move(p), {}, std::move(uv), std::move(idx), to_world);
}

TriangleMesh make_uv_sphere(const Point3& center, float radius, int rings, int segments,
                            const Transform& to_world) {
  std::vector<Point3> p;
  std::vector<Normal3> n;
  std::vector<Vec2> uv;
  std::vector<uint32_t> idx;
  for (int r = 0; r <= rings; ++r) {
    const float theta = kPi * float(r) / float(rings);
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2.f * kPi * float(s) / float(segments);
      const Vec3 dir(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      p.push_back(center + radius * dir);
      n.push_back(dir);
      uv.push_back({float(s) / float(segments), float(r) / float(rings)});
    }
  }
  // Weld the seam (phi = 2 pi) and the poles to single vertices so the mesh is
  // watertight: sin/cos of 0 and 2 pi differ in the last bits.
  std::vector<uint32_t> remap(p.size());
  for (size_t i = 0; i < p.size(); ++i) {
    remap[i] = uint32_t(i);
    const int r = int(i) / (segments + 1), s = int(i) % (segments + 1);
    if (s == segments) remap[i] = uint32_t(r * (segments + 1));
    if (r == 0) remap[i] = 0;
    if (r == rings) remap[i] = uint32_t(rings * (segments + 1));
  }
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const uint32_t a = remap[r * (segments + 1) + s], b = remap[r * (segments + 1) + s + 1];
      const uint32_t c = remap[(r + 1) * (segments + 1) + s], d = remap[(r + 1) * (segments + 1) + s + 1];
      // Outward winding: cross(c - a, b - a) points away from the centre.
      if (r != 0) idx.insert(idx.end(), {a, b, c});
      if (r != rings - 1) idx.insert(idx.end(), {b, d, c});
    }
  }
  return make_mesh(std::move(p), std::move(n), std::move(uv), std::move(idx), to_world);
}

}  // namespace inkray
