// Mesh edges come from find_feature_edges (which pairs the triangles at each edge,
// welded by position) and the half-edges it leaves unpaired (open boundaries); a
// sphere's contour is worked out in its own space, where it is round: an affine map
// keeps tangency, so the circle of tangent points there maps onto the contour.
#include "core/npr/lines/surface_edges.h"

#include "core/geometry/mesh_features.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <utility>

namespace inkray {
namespace {

constexpr uint32_t type_bit(LineType t) { return 1u << uint32_t(t); }

// A sphere's contour takes at least this many chords, and at most this many however
// large it stands on the image (a chord then strays from the circle by well under a
// pixel, and the part off the image is clipped anyway).
constexpr int kFewestChords = 16;
constexpr int kMostChords = 4096;

// An edge of a mesh: the half-edges that found it (half_b none at an open boundary), and
// the joints at the start and end of half_a.
struct MeshEdge {
  uint32_t half_a = 0, half_b = UINT32_MAX;
  LineType type = LineType::crease;
  uint32_t from = 0, to = 0;
  std::pair<uint32_t, uint32_t> key() const { return std::minmax(from, to); }
};

uint32_t next_corner(uint32_t half) { return half - half % 3 + (half % 3 + 1) % 3; }

// Which way each triangle faces `eye`: 1 towards it, -1 away, 0 degenerate.
std::vector<int8_t> facing(const TriangleMesh& mesh, const Point3& eye) {
  std::vector<int8_t> out(mesh.triangle_count());
  for (size_t t = 0; t < out.size(); ++t) {
    const Point3& a = mesh.positions[mesh.indices[3 * t]];
    const Normal3 n =
        facet_normal(a, mesh.positions[mesh.indices[3 * t + 1]], mesh.positions[mesh.indices[3 * t + 2]]);
    out[t] = n == Normal3(0.f) ? 0 : glm::dot(n, eye - a) > 0.f ? 1 : -1;
  }
  return out;
}

// The silhouette and crease edges of one mesh; returns the joints its edges use.
uint32_t add_mesh_edges(const TriangleMesh& mesh, uint32_t object, const Point3& eye, uint32_t types,
                        float crease_cos, uint32_t joint_base, std::vector<SurfaceEdge>& out) {
  const std::span<const Point3> positions(mesh.positions.data(), mesh.vertex_count());
  if (mesh.triangle_count() == 0 || positions.empty()) return 0;
  const MeshFeatures features = find_feature_edges(positions, mesh.indices);
  const std::vector<int8_t> faces = facing(mesh, eye);
  const bool silhouettes = types & type_bit(LineType::silhouette),
             creases = types & type_bit(LineType::crease);

  std::vector<MeshEdge> edges;
  std::vector<bool> paired(mesh.indices.size(), false);
  for (const FeatureEdge& e : features.edges) {
    paired[e.a] = paired[e.b] = true;
    const int8_t fa = faces[e.a / 3], fb = faces[e.b / 3];
    if (silhouettes && fa != 0 && fb != 0 && fa != fb) {
      edges.push_back({e.a, e.b, LineType::silhouette});
    } else if (creases && std::isfinite(e.dihedral) && std::cos(glm::radians(e.dihedral)) < crease_cos) {
      edges.push_back({e.a, e.b, LineType::crease});
    }
  }
  if (creases) {
    for (uint32_t h = 0; h < uint32_t(mesh.indices.size()); ++h)
      if (!paired[h] && faces[h / 3] != 0 &&
          positions[mesh.indices[h]] != positions[mesh.indices[next_corner(h)]])
        edges.push_back({h, UINT32_MAX, LineType::crease});
  }
  if (edges.empty()) return 0;
  // Joints are the edges' ends welded by position (vertices split for normals or uvs
  // are one joint), found among these ends only: far fewer than the mesh's vertices.
  std::vector<Point3> ends(2 * edges.size());
  for (size_t i = 0; i < edges.size(); ++i) {
    ends[2 * i] = positions[mesh.indices[edges[i].half_a]];
    ends[2 * i + 1] = positions[mesh.indices[next_corner(edges[i].half_a)]];
  }
  const std::vector<uint32_t> joint = weld_positions(ends);
  for (size_t i = 0; i < edges.size(); ++i) edges[i].from = joint[2 * i], edges[i].to = joint[2 * i + 1];
  // Where three or more triangles meet at an edge it was found once per pair: the
  // first of each, a silhouette before a crease, stands for it.
  std::sort(edges.begin(), edges.end(), [](const MeshEdge& l, const MeshEdge& r) {
    if (l.key() != r.key()) return l.key() < r.key();
    if (l.type != r.type) return l.type == LineType::silhouette;
    return l.half_a < r.half_a;
  });
  edges.erase(std::unique(edges.begin(), edges.end(),
                          [](const MeshEdge& l, const MeshEdge& r) { return l.key() == r.key(); }),
              edges.end());
  for (const MeshEdge& e : edges) {
    SurfaceEdge s;
    s.a = positions[mesh.indices[e.half_a]];
    s.b = positions[mesh.indices[next_corner(e.half_a)]];
    s.joint_a = joint_base + e.from;
    s.joint_b = joint_base + e.to;
    s.object = object;
    s.type = e.type;
    s.faces = {e.half_a / 3, e.half_b == UINT32_MAX ? kNoFace : e.half_b / 3};
    out.push_back(s);
  }
  return *std::max_element(joint.begin(), joint.end()) + 1;
}

// A sphere's contour seen from `eye`, as a loop of chords about `spacing_px` long on
// the image; returns the joints it uses (none when the eye is inside).
uint32_t add_sphere_contour(const Sphere& sphere, const Camera& camera, uint32_t object, const Point3& eye,
                            float spacing_px, uint32_t joint_base, std::vector<SurfaceEdge>& out) {
  // In the sphere's own space: the tangent points from the eye form a circle about
  // the axis to the eye, nearer the eye than the centre.
  const glm::dvec3 e(sphere.to_world.inv * glm::vec4(eye, 1.f)), c(sphere.center);
  const double r = sphere.radius;
  const glm::dvec3 axis = e - c;
  const double distance = glm::length(axis);
  if (!(r > 0.0) || !(distance > r * (1.0 + 1e-4)) || !std::isfinite(distance)) return 0;
  const glm::dvec3 n = axis / distance;
  const double k = r / distance;
  const glm::dvec3 centre = c + (k * r) * n;
  const double radius = r * std::sqrt(1.0 - k * k);
  const glm::dvec3 u =
      glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
  const glm::dvec3 v = glm::cross(n, u);
  const auto at = [&](double angle) {
    const glm::dvec3 p = centre + radius * (std::cos(angle) * u + std::sin(angle) * v);
    return sphere.to_world.point(Point3(p));
  };
  // Its length on the image, from a coarse loop; one that reaches behind the camera
  // is as long as it may be.
  constexpr int kProbes = 64;
  float length = 0.f;
  Vec2 last{0.f};
  bool behind = false;
  for (int i = 0; i <= kProbes && !behind; ++i) {
    Vec2 film;
    behind = !camera.project(at(2.0 * std::numbers::pi * i / kProbes), &film);
    if (i > 0) length += glm::length(film - last);
    last = film;
  }
  const int chords = behind ? kMostChords
                            : std::clamp(int(std::ceil(std::min(length / spacing_px, float(kMostChords)))),
                                         kFewestChords, kMostChords);
  Point3 start = at(0.0), from = start;
  for (int i = 0; i < chords; ++i) {
    const Point3 to = i + 1 == chords ? start : at(2.0 * std::numbers::pi * (i + 1) / chords);
    SurfaceEdge s;
    s.a = from;
    s.b = to;
    s.joint_a = joint_base + uint32_t(i);
    s.joint_b = joint_base + uint32_t((i + 1) % chords);
    s.object = object;
    s.type = LineType::silhouette;
    s.own_object_hides = false;
    out.push_back(s);
    from = to;
  }
  return uint32_t(chords);
}

}  // namespace

SurfaceEdges surface_edges(const RenderScene& scene, const Point3& eye, uint32_t types, float spacing_px) {
  SurfaceEdges out;
  types &= type_bit(LineType::silhouette) | type_bit(LineType::crease);
  if (!types) return out;
  const World& world = *scene.world;
  uint32_t& joints = out.joints;
  for (uint32_t i = 0; i < uint32_t(world.objects.size()) && i < world.geometry.shape_count(); ++i) {
    if (world.objects[i].lines.exclude) continue;
    const AlphaMask* mask = world.geometry.alpha_mask(i);
    if (mask && mask->paint) continue;
    const Shape& shape = world.geometry.shape(i);
    if (const auto* mesh = std::get_if<TriangleMesh>(&shape)) {
      joints += add_mesh_edges(*mesh, i, eye, types, scene.lines.crease_cos, joints, out.edges);
    } else if (types & type_bit(LineType::silhouette)) {
      joints +=
          add_sphere_contour(std::get<Sphere>(shape), scene.camera, i, eye, spacing_px, joints, out.edges);
    }
  }
  return out;
}

}  // namespace inkray
