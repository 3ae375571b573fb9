// Ribbon construction: a centreline per stroke, two projected side vertices
// per station, lifted by the offset and a bound on how far chords dip.
#include "core/npr/strokes/stroke_mesh.h"

#include "core/base/parallel.h"
#include "core/math/float_error.h"
#include "core/math/frame.h"
#include "core/math/hash.h"
#include "core/npr/strokes/stroke_growth.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace inkray {
namespace {

constexpr uint32_t kGrowthStream = 0x3c6ef372u;

// tan(angle / 4) for the angle between unit vectors a and b, without trigonometry:
// with x = |a - b| and y = |a + b| (x^2 + y^2 = 4), the angle is 2 atan2(x, y)
// and tan(atan2(x, y) / 2) = x / (2 + y). Accurate at small angles.
float tan_quarter_angle(const Vec3& a, const Vec3& b) { return glm::length(a - b) / (2.f + glm::length(a + b)); }

// How far the straight edge between two surface points can pass below the
// surface: a circular arc through both with the angle between their normals has
// sagitta |ab| / 2 * tan(angle / 4); the surface's factor covers sharper folds.
// Angles are capped at 3 radians (tan(3 / 4)): a fold that sharp is an edge.
float chord_dip(const SurfacePoint& a, const SurfacePoint& b, float factor) {
  const float t = std::min(std::max(tan_quarter_angle(a.n, b.n), tan_quarter_angle(a.ng, b.ng)), 0.9315965f);
  return factor * 0.5f * glm::length(a.p - b.p) * t;
}

// Unit vector across the stroke at station j: perpendicular to the centreline
// and to the normal, so the ribbon lies in the tangent plane.
Vec3 across(const std::vector<SurfacePoint>& st, size_t j) {
  const Point3 ahead = j + 1 < st.size() ? st[j + 1].p : st[j].p;
  const Point3 behind = j > 0 ? st[j - 1].p : st[j].p;
  const Normal3& n = st[j].n;
  Vec3 along = ahead - behind;
  along -= n * glm::dot(n, along);
  const float len = glm::length(along);
  along = len > 0.f ? along / len : Frame::from_z(n).x;
  return glm::normalize(glm::cross(along, n));
}

struct RibbonWriter {
  const StrokeSurface& surface;
  const StrokeEmitterDesc& emitter;
  float offset;
  uint32_t seed;
  TriangleMesh& mesh;

  // Writes stroke i; returns the largest lift it used.
  float write(uint32_t i, const SurfacePoint& root, const Color& color, std::vector<SurfacePoint>& stations,
              std::vector<SurfacePoint>& sides, std::vector<float>& dips) const {
    const StrokeShape shape = draw_stroke_shape(emitter, seed, i);
    const int segments = std::max(emitter.segments, 1);
    grow_stroke(surface, root, emitter.flow, shape, segments, &stations);
    const size_t n_st = stations.size(), n_vert = 2 * n_st;
    sides.resize(n_vert);
    for (size_t j = 0; j < n_st; ++j) {
      const Vec3 half = 0.5f * shape.width * across(stations, j);
      const float near = glm::length(half);
      sides[2 * j] = surface.project(stations[j].p - half, near);
      sides[2 * j + 1] = surface.project(stations[j].p + half, near);
    }
    // Dip of each quad between stations j and j + 1 over its five edges.
    const float factor = surface.chord_dip_factor();
    dips.assign(n_st, 0.f);
    for (size_t j = 0; j + 1 < n_st; ++j) {
      const SurfacePoint &a0 = sides[2 * j], &b0 = sides[2 * j + 1], &a1 = sides[2 * j + 2], &b1 = sides[2 * j + 3];
      dips[j] = std::max({chord_dip(a0, b0, factor), chord_dip(a1, b1, factor), chord_dip(a0, a1, factor),
                          chord_dip(b0, b1, factor), chord_dip(b0, a1, factor)});
    }
    const float base = offset * (1.f + float(shape.layer) / float(kStrokeLayers));
    const size_t v0 = size_t(i) * n_vert;
    float max_lift = 0.f;
    for (size_t k = 0; k < n_vert; ++k) {
      const size_t j = k / 2;
      const float lift = base + std::max(dips[j], j > 0 ? dips[j - 1] : 0.f);
      max_lift = std::max(max_lift, lift);
      mesh.positions[v0 + k] = sides[k].p + lift * sides[k].n;
      mesh.normals[v0 + k] = sides[k].n;
      mesh.uvs[v0 + k] = Vec2(float(k % 2), float(j) / float(segments));
      mesh.colors[v0 + k] = color;
    }
    // Left a_j = 2j, right b_j = 2j + 1; (a_j, b_j, a_j+1) and (b_j, b_j+1, a_j+1)
    // wind so that cross(edge, edge) points along the normal.
    uint32_t* idx = &mesh.indices[size_t(i) * 6 * size_t(segments)];
    for (uint32_t j = 0; j < uint32_t(segments); ++j) {
      const uint32_t a = uint32_t(v0) + 2 * j, b = a + 1, a1 = a + 2, b1 = a + 3;
      const uint32_t tri[6] = {a, b, a1, b, b1, a1};
      std::copy(tri, tri + 6, idx + 6 * j);
    }
    return max_lift;
  }
};

}  // namespace

float stroke_offset(const StrokeSurface& surface, const StrokeEmitterDesc& e) {
  if (e.offset > 0.f) return e.offset;
  const float mean_width = 0.5f * (e.width_min + e.width_max);
  const float from_size = std::min(1e-4f * surface.size(), 0.05f * mean_width);
  const float from_rounding = 256.f * gamma_bound(8) * surface.magnitude();
  return std::max({from_size, from_rounding, std::numeric_limits<float>::min()});
}

StrokeGeometry build_stroke_mesh(const StrokeSurface& surface, std::span<const SurfacePoint> roots,
                                 std::span<const Color> colors, const StrokeEmitterDesc& emitter,
                                 const Cancel& cancel) {
  StrokeGeometry out;
  out.offset = stroke_offset(surface, emitter);
  const size_t count = roots.size();
  const size_t segments = size_t(std::max(emitter.segments, 1));
  const size_t per_stroke = 2 * (segments + 1);
  TriangleMesh& mesh = out.mesh;
  mesh.positions.assign(count * per_stroke + 1, Point3(0.f));  // + Embree's padding element
  mesh.normals.resize(count * per_stroke);
  mesh.uvs.resize(count * per_stroke);
  mesh.colors.resize(count * per_stroke);
  mesh.indices.resize(count * 6 * segments);
  const RibbonWriter writer{surface, emitter, out.offset, hash_combine(uint32_t(emitter.seed), kGrowthStream), mesh};
  std::atomic<float> max_lift{0.f};
  parallel_for_chunks(count, 2048, [&](size_t begin, size_t end) {
    std::vector<SurfacePoint> stations, sides;
    std::vector<float> dips;
    float local = 0.f;
    for (size_t i = begin; i < end; ++i)
      local = std::max(local, writer.write(uint32_t(i), roots[i], colors[i], stations, sides, dips));
    float seen = max_lift.load();
    while (local > seen && !max_lift.compare_exchange_weak(seen, local)) {
    }
  }, cancel);
  out.max_lift = max_lift.load();
  return out;
}

}  // namespace inkray
