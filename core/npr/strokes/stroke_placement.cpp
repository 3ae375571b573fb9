// Blue-noise root placement by progressive dart throwing with a hash grid.
#include "core/npr/strokes/stroke_placement.h"

#include "core/base/parallel.h"
#include "core/math/hash.h"

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

// Uniform grid over space, stored sparsely: cells are found through an open-
// addressing table, points of a cell through a linked list. Distinct cells that
// share a packed key merely share a list; distances are always checked exactly.
class HashGrid {
 public:
  HashGrid(float cell, size_t capacity) : inv_cell_(1.f / cell) {
    size_t slots = 16;
    while (slots < 2 * capacity) slots <<= 1;
    slots_.assign(slots, Slot{});
    mask_ = slots - 1;
    points_.reserve(capacity);
    next_.reserve(capacity);
  }

  void insert(const Point3& p) {
    const uint64_t k = key(cell_of(p.x), cell_of(p.y), cell_of(p.z));
    Slot& slot = slots_[slot_of(k)];
    slot.key = k;
    next_.push_back(slot.head);
    slot.head = int32_t(points_.size());
    points_.push_back(p);
  }

  // Distance to the nearest point among the cells that overlap the cube p +- r:
  // exact when that nearest point is closer than r; infinity when none is found.
  float nearest(const Point3& p, float r) const {
    float best = std::numeric_limits<float>::infinity();
    const int64_t x0 = cell_of(p.x - r), x1 = cell_of(p.x + r);
    const int64_t y0 = cell_of(p.y - r), y1 = cell_of(p.y + r);
    const int64_t z0 = cell_of(p.z - r), z1 = cell_of(p.z + r);
    for (int64_t x = x0; x <= x1; ++x)
      for (int64_t y = y0; y <= y1; ++y)
        for (int64_t z = z0; z <= z1; ++z) {
          for (int32_t i = slots_[slot_of(key(x, y, z))].head; i >= 0; i = next_[size_t(i)]) {
            const Vec3 d = points_[size_t(i)] - p;
            best = std::min(best, glm::dot(d, d));
          }
        }
    return std::sqrt(best);
  }

 private:
  static constexpr uint64_t kEmpty = ~0ULL;

  int64_t cell_of(float v) const { return int64_t(std::floor(double(v) * double(inv_cell_))); }
  static uint64_t key(int64_t x, int64_t y, int64_t z) {
    constexpr uint64_t m = (1ULL << 21) - 1;
    return ((uint64_t(x) & m) << 42) | ((uint64_t(y) & m) << 21) | (uint64_t(z) & m);
  }
  // The key's slot, or the empty slot where it would go (whose list is empty).
  // At most `capacity` cells are ever stored in twice as many slots, so a probe ends.
  size_t slot_of(uint64_t k) const {
    size_t slot = size_t(mix64(k)) & mask_;
    while (slots_[slot].key != k && slots_[slot].key != kEmpty) slot = (slot + 1) & mask_;
    return slot;
  }

  float inv_cell_;
  size_t mask_ = 0;
  // Key and list head side by side: a probe touches one cache line.
  struct Slot {
    uint64_t key = kEmpty;
    int32_t head = -1;
  };
  std::vector<Slot> slots_;
  std::vector<Point3> points_;
  std::vector<int32_t> next_;
};

}  // namespace

std::vector<SurfacePoint> place_roots(const StrokeSurface& surface, size_t count, uint32_t seed,
                                      PlacementStats* stats, const Cancel& cancel) {
  if (count == 0) return {};
  const uint32_t stream = hash_combine(seed, kPlacementStream);
  const size_t m = candidate_count(count);
  std::vector<Point3> candidates(m);
  parallel_for_chunks(m, 16384, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) candidates[i] = surface.sample(stream, uint32_t(i)).p;
  }, cancel);

  const double spacing = std::sqrt(surface.area() / double(count));
  const float r0 = float(spacing);  // above what random darts reach (about 0.8 x spacing)
  // Grid cells no smaller than any radius, so a query touches at most 2 x 2 x 2 cells.
  HashGrid grid(r0, count);
  // Per candidate: the distance to its nearest root when last tested (a lower
  // bound that only shrinks), or -1 once accepted.
  std::vector<float> nearest(m, std::numeric_limits<float>::infinity());
  std::vector<uint32_t> accepted;
  accepted.reserve(count);
  float r = r0;
  while (accepted.size() < count) {
    if (cancel.requested()) return {};
    // Once the radius is negligible, the remaining candidates are taken in order.
    const bool take_all = r < 1e-3f * r0;
    for (size_t i = 0; i < m && accepted.size() < count; ++i) {
      if ((i & 0xffff) == 0 && cancel.requested()) return {};
      if (nearest[i] < 0.f || (!take_all && nearest[i] < r)) continue;
      if (!take_all) {
        const float d = grid.nearest(candidates[i], r);
        if (d < r) {
          nearest[i] = d;
          continue;
        }
      }
      grid.insert(candidates[i]);
      nearest[i] = -1.f;
      accepted.push_back(uint32_t(i));
    }
    if (accepted.size() < count) r *= kShrink;
  }

  std::vector<SurfacePoint> roots(count);
  parallel_for_chunks(count, 8192, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) roots[i] = surface.sample(stream, accepted[i]);
  }, cancel);
  if (cancel.requested()) return {};
  if (stats) *stats = {spacing, double(r < 1e-3f * r0 ? 0.f : r), m};
  return roots;
}

}  // namespace inkray
