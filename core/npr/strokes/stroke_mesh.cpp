// Ribbon construction: a spine per stroke, rails of projected points across
// it, as few stations and columns as keep the ribbon within the tolerance of
// the surface, lifted by the offset and a bound on how far chords dip.
#include "core/npr/strokes/stroke_mesh.h"

#include "core/base/parallel.h"
#include "core/math/float_error.h"
#include "core/math/frame.h"
#include "core/math/hash.h"
#include "core/npr/strokes/stroke_growth.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace inkray {
namespace {

constexpr uint32_t kGrowthStream = 0x3c6ef372u;
// Strokes per block of output. Blocks are fixed by stroke index, so the mesh's
// layout does not depend on how the blocks were shared among threads.
constexpr size_t kBlock = 256;
static_assert(kMaxColumns == 4, "RibbonBuilder makes 1, 2 or 4 columns");

// tan(angle / 4) for the angle between unit vectors a and b, without trigonometry:
// with x = |a - b| and y = |a + b| (x^2 + y^2 = 4), the angle is 2 atan2(x, y)
// and tan(atan2(x, y) / 2) = x / (2 + y). Accurate at small angles.
float tan_quarter_angle(const Vec3& a, const Vec3& b) {
  return glm::length(a - b) / (2.f + glm::length(a + b));
}

// How far the straight edge between two surface points can pass below the
// surface: a circular arc through both with the angle between their normals has
// sagitta |ab| / 2 * tan(angle / 4); the surface's factor covers sharper folds.
// Angles are capped at 3 radians (tan(3 / 4)): a fold that sharp is an edge.
float chord_dip(const SurfacePoint& a, const SurfacePoint& b, float factor) {
  const float t = std::min(std::max(tan_quarter_angle(a.n, b.n), tan_quarter_angle(a.ng, b.ng)), 0.9315965f);
  return factor * 0.5f * glm::length(a.p - b.p) * t;
}

// The same for the smooth surface the shading normals describe: what more
// points across or along can reduce. A faceted mesh's folds (in ng) are not:
// a point more halves a chord across a fold, not its dip's square.
float follow_dip(const SurfacePoint& a, const SurfacePoint& b, float factor) {
  return factor * 0.5f * glm::length(a.p - b.p) * std::min(tan_quarter_angle(a.n, b.n), 0.9315965f);
}

float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

float distance_to_segment(const Point3& p, const Point3& a, const Point3& b) {
  const Vec3 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.f ? std::clamp(glm::dot(p - a, ab) / len2, 0.f, 1.f) : 0.f;
  return glm::length(p - (a + t * ab));
}

// Unit vector across the stroke at station j: perpendicular to the centreline
// and to the normal, so the ribbon starts out in the tangent plane.
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

// The output of a block of consecutive strokes, its indices local to it.
struct Block {
  std::vector<Point3> positions;
  std::vector<Normal3> normals;
  std::vector<Vec2> uvs;
  std::vector<uint8_t> fades;
  std::vector<uint32_t> indices;
  std::vector<uint32_t> vertex_counts, triangle_counts;  // per stroke
  float max_lift = 0.f;
};

// One stroke's points across and along before lifting: rails[j * (columns + 1) + c].
struct Rail {
  SurfacePoint sp;
  float u = 0.f;     // across the brush; a clipped point keeps the u of the point it collapsed onto
  float turn = 1.f;  // fade by how far the surface turned away from the centreline's normal
  bool clipped = false;
};

struct Scratch {
  StrokeSpine spine;
  std::vector<Vec3> across;
  std::vector<SurfacePoint> left, right, quarter_left, quarter_right;
  std::vector<Rail> rails;
  std::vector<size_t> kept;
  std::vector<float> dips;
};

struct RibbonBuilder {
  const StrokeSurface& surface;
  const StrokeEmitterDesc& emitter;
  float offset;
  uint32_t seed;

  // Points at `distance` on each side of every station (direct projections of
  // the tangent-plane offsets).
  void sides(const Scratch& s, float distance, std::vector<SurfacePoint>& left,
             std::vector<SurfacePoint>& right) const {
    const auto& st = s.spine.stations;
    left.resize(st.size());
    right.resize(st.size());
    for (size_t j = 0; j < st.size(); ++j) {
      left[j] = surface.project(st[j].p - distance * s.across[j], distance);
      right[j] = surface.project(st[j].p + distance * s.across[j], distance);
    }
  }

  // Cells across: 1 (the sides alone), 2 (with the centreline) or 4 (and the
  // quarter lines), the fewest whose chords across, and the diagonals from a
  // cell's right edge on one row to its left edge on the next, dip less than
  // `tolerance` below the smooth surface; but a point more only where it helps
  // as curvature does (the half chords dip at most half as deep), not across
  // a fold. A side that does not land needs the centreline to clip against.
  int columns(const Scratch& s, float h, float tolerance, float factor) const {
    const auto& st = s.spine.stations;
    bool all_land = true;
    float full = 0.f, half = 0.f;
    for (size_t j = 0; j < st.size(); ++j) {
      const bool l = step_lands(st[j], s.left[j], h), r = step_lands(st[j], s.right[j], h);
      all_land = all_land && l && r;
      if (l && r) full = std::max(full, follow_dip(s.left[j], s.right[j], factor));
      if (l) half = std::max(half, follow_dip(s.left[j], st[j], factor));
      if (r) half = std::max(half, follow_dip(st[j], s.right[j], factor));
      if (j + 1 == st.size()) continue;
      full = std::max(full, follow_dip(s.right[j], s.left[j + 1], factor));
      half = std::max(
          {half, follow_dip(st[j], s.left[j + 1], factor), follow_dip(s.right[j], st[j + 1], factor)});
    }
    const bool halving_helps = half <= 0.5f * full;
    if (all_land && (full <= tolerance || !halving_helps)) return 1;
    return half <= tolerance || !halving_helps ? 2 : kMaxColumns;
  }

  // Fills s.rails for `cols` columns: each side is a chain of points outward
  // from the centreline; from the first that does not land on, the chain's
  // points collapse onto the last that did (a cut, with zero area beyond it).
  void fill_rails(Scratch& s, int cols, float h) const {
    const auto& st = s.spine.stations;
    const size_t per = size_t(cols) + 1;
    s.rails.assign(st.size() * per, Rail{});
    for (size_t j = 0; j < st.size(); ++j) {
      Rail* row = &s.rails[j * per];
      if (cols == 1) {
        row[0] = {s.left[j], 0.f, 1.f, false};
        row[1] = {s.right[j], 1.f, 1.f, false};
      } else {
        const int mid = cols / 2;
        row[mid] = {st[j], 0.5f, 1.f, false};
        for (int side = -1; side <= 1; side += 2) {
          const SurfacePoint* chain[2] = {cols == 4 ? &(side < 0 ? s.quarter_left : s.quarter_right)[j]
                                                    : &(side < 0 ? s.left : s.right)[j],
                                          &(side < 0 ? s.left : s.right)[j]};
          const float step = h / float(mid);
          Rail last = row[mid];
          for (int k = 1; k <= mid; ++k) {
            Rail& r = row[mid + side * k];
            const SurfacePoint& p = *chain[k - 1];
            if (!last.clipped && step_lands(last.sp, p, step)) {
              r = {p, 0.5f + float(side) * 0.5f * float(k) / float(mid), 1.f, false};
            } else {
              r = last;
              r.clipped = true;
            }
            last = r;
          }
        }
      }
      // A brush cannot wrap around a surface: past 60 degrees from the
      // centreline's normal the ribbon fades, and is gone at 90.
      for (size_t c = 0; c < per; ++c) row[c].turn = smoothstep(0.f, 0.5f, glm::dot(st[j].n, row[c].sp.n));
    }
  }

  // Whether stations strictly between kept a and b can be dropped: every rail
  // point there stays within `tolerance` of the chord that replaces it, the
  // chord dips no deeper below the smooth surface, and nothing about clipping
  // or fading changes.
  bool can_drop(const Scratch& s, size_t a, size_t b, size_t per, float tolerance, float factor) const {
    for (size_t c = 0; c < per; ++c) {
      const Rail &ra = s.rails[a * per + c], &rb = s.rails[b * per + c];
      if (ra.clipped != rb.clipped || follow_dip(ra.sp, rb.sp, factor) > tolerance) return false;
      if (c > 0 && follow_dip(s.rails[a * per + c].sp, s.rails[b * per + c - 1].sp, factor) > tolerance)
        return false;  // the cell's diagonal
      for (size_t k = a + 1; k < b; ++k) {
        const Rail& rk = s.rails[k * per + c];
        if (rk.clipped != ra.clipped || std::abs(rk.turn - ra.turn) > 0.02f ||
            std::abs(rk.turn - rb.turn) > 0.02f)
          return false;
        if (distance_to_segment(rk.sp.p, ra.sp.p, rb.sp.p) > tolerance) return false;
      }
    }
    return true;
  }

  void build(uint32_t i, const SurfacePoint& root, Scratch& s, Block& out) const {
    const StrokeShape shape = draw_stroke_shape(emitter, seed, i);
    const int segments = std::max(emitter.segments, 1);
    grow_stroke(surface, root, emitter.flow, shape, segments, &s.spine);
    const auto& st = s.spine.stations;
    const size_t n = st.size();
    if (n < 2) {  // not one step landed: nothing of the stroke lies on the surface
      out.vertex_counts.push_back(0);
      out.triangle_counts.push_back(0);
      return;
    }
    const float w = shape.width, h = 0.5f * w;
    const float tolerance = std::max(kFollowTolerance * w, offset);
    const float factor = surface.chord_dip_factor();
    s.across.resize(n);
    for (size_t j = 0; j < n; ++j) s.across[j] = across(st, j);
    sides(s, h, s.left, s.right);
    const int cols = columns(s, h, tolerance, factor);
    if (cols == 4) sides(s, 0.5f * h, s.quarter_left, s.quarter_right);
    fill_rails(s, cols, h);
    const size_t per = size_t(cols) + 1;

    // Stations along: greedily the fewest that keep every rail within tolerance.
    s.kept.assign(1, 0);
    for (size_t b = 2; b < n; ++b)
      if (!can_drop(s, s.kept.back(), b, per, tolerance, factor)) s.kept.push_back(b - 1);
    s.kept.push_back(n - 1);
    const size_t rows = s.kept.size();
    const auto rail = [&](size_t row, size_t c) -> const Rail& { return s.rails[s.kept[row] * per + c]; };

    // Dip of each cell over its five edges (the diagonal b-a1 included); a
    // vertex is lifted by its layer's offset and the deepest dip around it.
    s.dips.assign((rows - 1) * size_t(cols), 0.f);
    for (size_t r = 0; r + 1 < rows; ++r)
      for (size_t c = 0; c < size_t(cols); ++c) {
        const SurfacePoint &a0 = rail(r, c).sp, &b0 = rail(r, c + 1).sp, &a1 = rail(r + 1, c).sp,
                           &b1 = rail(r + 1, c + 1).sp;
        s.dips[r * size_t(cols) + c] =
            std::max({chord_dip(a0, b0, factor), chord_dip(a1, b1, factor), chord_dip(a0, a1, factor),
                      chord_dip(b0, b1, factor), chord_dip(b0, a1, factor)});
      }
    const float base = offset;
    const uint32_t v0 = uint32_t(out.positions.size());
    for (size_t r = 0; r < rows; ++r) {
      const bool cut_end = (r == 0 && s.spine.cut_tail) || (r + 1 == rows && s.spine.cut_tip);
      for (size_t c = 0; c < per; ++c) {
        float dip = 0.f;
        for (size_t rr = r > 0 ? r - 1 : 0; rr <= std::min(r, rows - 2); ++rr)
          for (size_t cc = c > 0 ? c - 1 : 0; cc <= std::min(c, size_t(cols) - 1); ++cc)
            dip = std::max(dip, s.dips[rr * size_t(cols) + cc]);
        const float lift = base + dip;
        out.max_lift = std::max(out.max_lift, lift);
        const Rail& p = rail(r, c);
        // A part of the ribbon standing off the surface further than a
        // fraction of its width is a sheet: it fades (docs/strokes.md).
        const float standoff = smoothstep(kFadeEnd * w, kFadeStart * w, dip);
        const float fade = cut_end ? 0.f : standoff * p.turn;
        out.positions.push_back(p.sp.p + lift * p.sp.n);
        out.normals.push_back(p.sp.n);
        out.uvs.push_back(Vec2(p.u, s.spine.v[s.kept[r]]));
        out.fades.push_back(uint8_t(std::lround(std::clamp(fade, 0.f, 1.f) * 255.f)));
      }
    }
    // Left a = (r, c), right b = (r, c + 1); (a, b, a1) and (b, b1, a1) wind so
    // that cross(edge, edge) points along the normal. Cells cut away on both
    // rows (zero area) are left out.
    uint32_t triangles = 0;
    const int mid = cols / 2;
    for (size_t r = 0; r + 1 < rows; ++r)
      for (size_t c = 0; c < size_t(cols); ++c) {
        const size_t outer = int(c) < mid ? c : c + 1;  // the column that collapses first
        if (cols > 1 && rail(r, outer).clipped && rail(r + 1, outer).clipped) continue;
        const uint32_t a = v0 + uint32_t(r * per + c), b = a + 1, a1 = a + uint32_t(per), b1 = a1 + 1;
        out.indices.insert(out.indices.end(), {a, b, a1, b, b1, a1});
        triangles += 2;
      }
    out.vertex_counts.push_back(uint32_t(rows * per));
    out.triangle_counts.push_back(triangles);
  }
};

AlphaTriangle alpha_triangle(const Block& b, const uint32_t* corner, uint8_t pick) {
  AlphaTriangle t;
  for (int k = 0; k < 3; ++k) {
    t.u[k] = alpha_coordinate(b.uvs[corner[k]].x);
    t.v[k] = alpha_coordinate(b.uvs[corner[k]].y);
    t.fade[k] = b.fades[corner[k]];
  }
  t.pick = pick;
  return t;
}

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
  const uint32_t seed = hash_combine(uint32_t(emitter.seed), kGrowthStream);
  const RibbonBuilder builder{surface, emitter, out.offset, seed};
  const size_t blocks = (count + kBlock - 1) / kBlock;
  std::vector<Block> parts(blocks);
  parallel_for_chunks(
      blocks, 1,
      [&](size_t begin, size_t end) {
        Scratch scratch;
        for (size_t b = begin; b < end; ++b) {
          Block& part = parts[b];
          const size_t last = std::min(count, (b + 1) * kBlock);
          for (size_t i = b * kBlock; i < last; ++i) builder.build(uint32_t(i), roots[i], scratch, part);
        }
      },
      cancel);
  if (cancel.requested()) return out;

  // Where each block goes, then every block copied there in parallel.
  std::vector<size_t> vertex_base(blocks + 1, 0), triangle_base(blocks + 1, 0);
  for (size_t b = 0; b < blocks; ++b) {
    vertex_base[b + 1] = vertex_base[b] + parts[b].positions.size();
    triangle_base[b + 1] = triangle_base[b] + parts[b].indices.size() / 3;
    out.max_lift = std::max(out.max_lift, parts[b].max_lift);
  }
  const size_t vertices = vertex_base[blocks], triangles = triangle_base[blocks];
  TriangleMesh& mesh = out.mesh;
  mesh.positions.assign(vertices + 1, Point3(0.f));  // + Embree's padding element
  mesh.normals.resize(vertices);
  mesh.uvs.resize(vertices);
  mesh.colors.resize(vertices);
  mesh.indices.resize(3 * triangles);
  out.alpha.resize(triangles);
  out.first_vertex.resize(count + 1);
  out.first_vertex[count] = uint32_t(vertices);
  parallel_for_chunks(blocks, 4, [&](size_t begin, size_t end) {
    for (size_t b = begin; b < end; ++b) {
      Block& part = parts[b];
      const size_t vb = vertex_base[b], tb = triangle_base[b];
      std::copy(part.positions.begin(), part.positions.end(), mesh.positions.begin() + std::ptrdiff_t(vb));
      std::copy(part.normals.begin(), part.normals.end(), mesh.normals.begin() + std::ptrdiff_t(vb));
      std::copy(part.uvs.begin(), part.uvs.end(), mesh.uvs.begin() + std::ptrdiff_t(vb));
      size_t v = 0, t = 0;
      for (size_t k = 0; k < part.vertex_counts.size(); ++k) {
        const size_t i = b * kBlock + k;
        out.first_vertex[i] = uint32_t(vb + v);
        std::fill_n(mesh.colors.begin() + std::ptrdiff_t(vb + v), part.vertex_counts[k], colors[i]);
        const uint8_t pick = uint8_t(hash_combine(seed, uint32_t(i), 5u) >> 24);
        for (uint32_t e = 0; e < part.triangle_counts[k]; ++e, ++t) {
          const uint32_t* corner = &part.indices[3 * t];
          out.alpha[tb + t] = alpha_triangle(part, corner, pick);
          for (int c = 0; c < 3; ++c) mesh.indices[3 * (tb + t) + size_t(c)] = uint32_t(vb) + corner[c];
        }
        v += part.vertex_counts[k];
      }
      part = Block{};  // its memory back before the BVH is built
    }
  });
  return out;
}

}  // namespace inkray
