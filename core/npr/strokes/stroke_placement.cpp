// Blue-noise root placement by progressive dart throwing with a hash grid.
#include "core/npr/strokes/stroke_placement.h"

#include "core/base/parallel.h"
#include "core/math/hash.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace inkray {
namespace {

constexpr float kShrink = 0.95f;  // radius ratio between passes
constexpr uint32_t kPlacementStream = 0x9a7c3e11u;

// Candidates per root: more lets the radius stay larger; 6 keeps 100k roots
// well under a second. Very large counts trade spacing for memory.
size_t candidate_count(size_t count) { return count * (count > 2'000'000 ? 3 : 6); }

uint64_t mix64(uint64_t x) {  // splitmix64's finaliser
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Candidates binned in a uniform grid of cells at least twice any radius, so
// the roots within r of a candidate lie in the cells overlapping the cube of
// side 2r around it: at most two per axis, among the 27 around its own cell.
// Cells are grouped by parity class (cells of one class are never neighbours)
// and ordered along a Morton curve within it; candidates are stored in cell
// order, so the work on neighbouring cells touches neighbouring memory. The
// roots accepted in a cell are kept compacted at the front of its range.
class CandidateGrid {
 public:
  CandidateGrid(const std::vector<Point3>& points, float cell_size, const Cancel& cancel)
      : inv_cell_(1.f / cell_size) {
    const size_t m = points.size();
    std::vector<Coord> coords(m);
    parallel_for_chunks(
        m, 16384,
        [&](size_t begin, size_t end) {
          for (size_t i = begin; i < end; ++i) coords[i] = coord_of(points[i]);
        },
        cancel);
    // Distinct cells in order of first appearance, through a hash table.
    std::vector<Cell> found;
    std::vector<uint32_t> cell_of_candidate(m);
    rehash(found, 64);
    for (size_t i = 0; i < m; ++i) {
      const uint32_t c = find_or_add(found, coords[i]);
      cell_of_candidate[i] = c;
      ++found[c].end;  // a count for now
    }
    // Cells sorted by (class, Morton code); candidates scattered into cell
    // order, each cell's in index order.
    std::vector<uint32_t> by_curve(found.size());
    for (uint32_t c = 0; c < found.size(); ++c) by_curve[c] = c;
    std::vector<uint64_t> rank(found.size());
    for (uint32_t c = 0; c < found.size(); ++c)
      rank[c] = uint64_t(parity(found[c].at)) << 60 | morton(found[c].at);
    std::sort(by_curve.begin(), by_curve.end(), [&](uint32_t a, uint32_t b) { return rank[a] < rank[b]; });
    std::vector<uint32_t> renumber(found.size());
    cells_.resize(found.size());
    for (uint32_t k = 0; k < found.size(); ++k) {
      renumber[by_curve[k]] = k;
      cells_[k] = found[by_curve[k]];
      ++class_start_[parity(cells_[k].at) + 1];
    }
    for (int c = 1; c <= 8; ++c) class_start_[c] += class_start_[c - 1];
    uint32_t offset = 0;
    for (Cell& c : cells_) {
      const uint32_t n = c.end;
      c.begin = c.end = offset;
      offset += n;
    }
    index_.resize(m);
    position_.resize(m);
    for (uint32_t i = 0; i < m; ++i) {
      Cell& c = cells_[renumber[cell_of_candidate[i]]];
      index_[c.end] = i;
      position_[c.end++] = points[i];
    }
    rehash(cells_, slots_.size());
    // The 27 cells around each cell (kNone where there is none).
    around_.resize(27 * cells_.size());
    parallel_for_chunks(
        cells_.size(), 1024,
        [&](size_t begin, size_t end) {
          for (size_t c = begin; c < end; ++c) {
            const Coord at = cells_[c].at;
            for (int k = 0; k < 27; ++k)
              around_[27 * c + size_t(k)] =
                  find(cells_, {at.x + k / 9 - 1, at.y + k / 3 % 3 - 1, at.z + k % 3 - 1});
          }
        },
        cancel);
    roots_.resize(m);
  }

  size_t size() const { return index_.size(); }
  // Cells of parity class c (0..7) are [class_begin(c), class_end(c)).
  uint32_t class_begin(int c) const { return class_start_[c]; }
  uint32_t class_end(int c) const { return class_start_[c + 1]; }
  // Candidates of cell c are the slots [begin, end) of this grid's order.
  uint32_t begin(uint32_t c) const { return cells_[c].begin; }
  uint32_t end(uint32_t c) const { return cells_[c].end; }
  uint32_t index(size_t k) const { return index_[k]; }  // the candidate in slot k
  const Point3& position(size_t k) const { return position_[k]; }

  // Distance to the nearest accepted root among the cells overlapping the cube
  // p +- r around the candidate in slot k of cell c: exact when that root is
  // closer than r; infinity when none is found.
  float nearest(uint32_t c, size_t k, float r) const {
    const Point3& p = position_[k];
    const Coord at = cells_[c].at;
    const int x0 = int(cell_of(p.x - r) - at.x), x1 = int(cell_of(p.x + r) - at.x);
    const int y0 = int(cell_of(p.y - r) - at.y), y1 = int(cell_of(p.y + r) - at.y);
    const int z0 = int(cell_of(p.z - r) - at.z), z1 = int(cell_of(p.z + r) - at.z);
    float best = std::numeric_limits<float>::infinity();
    const uint32_t* around = &around_[27 * size_t(c)];
    for (int x = x0; x <= x1; ++x)
      for (int y = y0; y <= y1; ++y)
        for (int z = z0; z <= z1; ++z) {
          const uint32_t n = around[(x + 1) * 9 + (y + 1) * 3 + (z + 1)];
          if (n == kNone) continue;
          const Cell& cell = cells_[n];
          for (uint32_t a = cell.begin; a < cell.begin + cell.accepted; ++a) {
            const Vec3 d = roots_[a] - p;
            best = std::min(best, glm::dot(d, d));
          }
        }
    return std::sqrt(best);
  }

  // Accepts the candidate in slot k into its cell c. Only the task working on
  // c may call this.
  void accept(uint32_t c, size_t k) {
    Cell& cell = cells_[c];
    roots_[cell.begin + cell.accepted++] = position_[k];
  }

 private:
  static constexpr uint32_t kNone = ~0u;
  struct Coord {
    int64_t x, y, z;
    bool operator==(const Coord&) const = default;
  };
  struct Cell {
    Coord at;
    uint32_t begin, end;  // its candidates' slots, and its roots' in roots_
    uint32_t accepted;
  };

  // Clamped, so a surface absurdly large against its spacing (a scale keyed to 1e30 at
  // the rest frame) shares the outermost cells rather than overflowing the integer;
  // the neighbours' coordinates (one more either side) stay representable too.
  int64_t cell_of(float v) const {
    constexpr double kLimit = double(int64_t(1) << 60);
    const double cell = std::floor(double(v) * double(inv_cell_));
    if (!(cell > -kLimit)) return -int64_t(1) << 60;  // NaN too
    return int64_t(std::min(cell, kLimit));
  }
  Coord coord_of(const Point3& p) const { return {cell_of(p.x), cell_of(p.y), cell_of(p.z)}; }
  static uint64_t hash(const Coord& c) {
    return mix64(uint64_t(c.x) * 0x9e3779b97f4a7c15ULL ^ uint64_t(c.y) * 0xc2b2ae3d27d4eb4fULL ^
                 uint64_t(c.z));
  }
  // Cells whose coordinates agree in parity on every axis: neighbours never do.
  static uint32_t parity(const Coord& c) { return uint32_t((c.x & 1) << 2 | (c.y & 1) << 1 | (c.z & 1)); }
  // Interleaved low 20 bits of each coordinate.
  static uint64_t morton(const Coord& c) {
    uint64_t code = 0;
    for (int b = 0; b < 20; ++b)
      code |= (uint64_t(c.x >> b) & 1) << (3 * b + 2) | (uint64_t(c.y >> b) & 1) << (3 * b + 1) |
              (uint64_t(c.z >> b) & 1) << (3 * b);
    return code;
  }

  // A table of `slots` slots (a power of two) holding every cell of `cells`.
  void rehash(const std::vector<Cell>& cells, size_t slots) {
    slots_.assign(slots, kNone);
    mask_ = slots - 1;
    for (uint32_t c = 0; c < cells.size(); ++c) {
      size_t slot = size_t(hash(cells[c].at)) & mask_;
      while (slots_[slot] != kNone) slot = (slot + 1) & mask_;
      slots_[slot] = c;
    }
  }
  uint32_t find(const std::vector<Cell>& cells, const Coord& at) const {
    for (size_t slot = size_t(hash(at)) & mask_; slots_[slot] != kNone; slot = (slot + 1) & mask_)
      if (cells[slots_[slot]].at == at) return slots_[slot];
    return kNone;
  }
  uint32_t find_or_add(std::vector<Cell>& cells, const Coord& at) {
    size_t slot = size_t(hash(at)) & mask_;
    for (; slots_[slot] != kNone; slot = (slot + 1) & mask_)
      if (cells[slots_[slot]].at == at) return slots_[slot];
    const uint32_t c = slots_[slot] = uint32_t(cells.size());
    cells.push_back({at, 0, 0, 0});
    if (2 * cells.size() > slots_.size()) rehash(cells, 4 * slots_.size());
    return c;
  }

  float inv_cell_;
  std::vector<Cell> cells_;
  uint32_t class_start_[9] = {};
  std::vector<uint32_t> index_;   // slot -> candidate index
  std::vector<Point3> position_;  // slot -> candidate position
  std::vector<Point3> roots_;     // accepted roots, compacted per cell
  std::vector<uint32_t> around_;  // 27 per cell
  std::vector<uint32_t> slots_;
  size_t mask_ = 0;
};

}  // namespace

std::vector<SurfacePoint> place_roots(const StrokeSurface& surface, size_t count, uint32_t seed,
                                      PlacementStats* stats, const Cancel& cancel) {
  if (count == 0) return {};
  const uint32_t stream = hash_combine(seed, kPlacementStream);
  const size_t m = candidate_count(count);
  std::vector<Point3> candidates(m);
  parallel_for_chunks(
      m, 16384,
      [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) candidates[i] = surface.sample_position(stream, uint32_t(i));
      },
      cancel);
  if (cancel.requested()) return {};

  const double spacing = std::sqrt(surface.area() / double(count));
  const float r0 = float(spacing);  // above what random darts reach (about 0.8 x spacing)
  // Cells of twice the largest radius: a query reaches into at most two cells
  // per axis, each holding a few roots.
  CandidateGrid grid(candidates, 2.f * r0, cancel);
  if (cancel.requested()) return {};
  candidates = {};
  // Per slot: the distance to its nearest root when last tested (a lower bound
  // that only shrinks), or -1 once accepted; and the pass that accepted it.
  std::vector<float> nearest(m, std::numeric_limits<float>::infinity());
  std::vector<uint16_t> pass_of(m, 0);
  size_t accepted = 0;
  float r = r0;
  uint16_t pass = 0;
  while (accepted < count && r >= 1e-3f * r0 && pass < 0xfffe) {
    ++pass;
    // A pass works through the eight parity classes in turn; within a class the
    // cells are apart, so they are worked on in parallel, each taking its own
    // candidates in index order. What is accepted does not depend on threads.
    for (int c = 0; c < 8 && accepted < count; ++c) {
      const uint32_t first = grid.class_begin(c), cells = grid.class_end(c) - first;
      std::atomic<size_t> added{0};
      parallel_for_chunks(
          cells, 64,
          [&](size_t begin, size_t end) {
            size_t local = 0;
            for (size_t j = begin; j < end; ++j) {
              const uint32_t cell = first + uint32_t(j);
              for (uint32_t k = grid.begin(cell); k != grid.end(cell); ++k) {
                if (nearest[k] < r) continue;  // accepted (-1), or a root is known to be closer
                const float d = grid.nearest(cell, k, r);
                if (d < r) {
                  nearest[k] = d;
                  continue;
                }
                grid.accept(cell, k);
                nearest[k] = -1.f;
                pass_of[k] = pass;
                ++local;
              }
            }
            added += local;
          },
          cancel);
      if (cancel.requested()) return {};
      accepted += added.load();
    }
    if (accepted < count) r *= kShrink;
  }

  // The accepted candidates, by pass and then index; the last pass may have
  // accepted more than needed: its highest indices give way (dropping roots
  // never brings two closer). Should the radius have become negligible, the
  // remaining candidates are taken in index order.
  std::vector<uint64_t> taken;  // (pass, candidate index)
  taken.reserve(accepted);
  for (size_t k = 0; k < m; ++k)
    if (pass_of[k]) taken.push_back(uint64_t(pass_of[k]) << 32 | grid.index(k));
  std::sort(taken.begin(), taken.end());
  if (taken.size() > count) taken.resize(count);
  if (taken.size() < count) {
    std::vector<uint32_t> rest;
    for (size_t k = 0; k < m; ++k)
      if (!pass_of[k]) rest.push_back(grid.index(k));
    std::sort(rest.begin(), rest.end());
    for (size_t k = 0; taken.size() < count; ++k) taken.push_back(rest[k]);
  }
  // Painting order: later strokes lie on top. A hash of the candidate orders
  // them, so no pass or region is painted over another as a whole.
  for (uint64_t& t : taken) t = uint64_t(hash_combine(stream, uint32_t(t), 0x51ed2701u)) << 32 | uint32_t(t);
  std::sort(taken.begin(), taken.end());

  std::vector<SurfacePoint> roots(count);
  parallel_for_chunks(
      count, 8192,
      [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) roots[i] = surface.sample(stream, uint32_t(taken[i]));
      },
      cancel);
  if (cancel.requested()) return {};
  if (stats) *stats = {spacing, double(accepted >= count ? r : 0.f), m};
  return roots;
}

}  // namespace inkray
