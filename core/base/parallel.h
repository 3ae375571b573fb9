// The one parallel layer, on oneTBB: a ThreadBudget caps a render session (and
// whatever it runs) at its thread count; parallel_for_chunks serves code with no
// budget (stroke building, filters called alone) in whatever arena calls it.
#pragma once

#include "core/base/cancel.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <utility>

namespace inkray {

// A task arena of `size()` slots. Every arena draws its threads from TBB's one
// global worker pool, sized to the hardware, so an editor viewport, an export
// and a stroke rebuild running at once share the cores instead of each starting
// its own threads and oversubscribing them; a budget only caps how many of them
// its own work may occupy.
class ThreadBudget {
 public:
  // threads <= 0 means every hardware thread this process may run on, which is
  // also the most a budget gets: size() may be below `threads`.
  explicit ThreadBudget(int threads);
  ThreadBudget(const ThreadBudget&) = delete;
  ThreadBudget& operator=(const ThreadBudget&) = delete;

  int size() const { return size_; }

  // Calls body(item, worker) for every item in [0, count) and returns when all
  // are done. Items are handed out one at a time (a tile's cost varies a lot, so
  // larger chunks would leave threads idle at the end). `worker` is in
  // [0, size()) and no two bodies running at the same moment share it, so it can
  // index per-worker scratch.
  void parallel_for(int count, const std::function<void(int item, int worker)>& body);

  // Runs f inside the arena and returns its result: parallel work f starts (a
  // scene compile's stroke build, Embree's BVH build) stays within the budget.
  template <class F>
  decltype(auto) run(F&& f) {
    return arena_.execute(std::forward<F>(f));
  }

 private:
  int size_;
  tbb::task_arena arena_;
};

// Calls body(begin, end) over [0, count) in chunks of at most `grain` items, in
// the caller's arena (all hardware threads, or a ThreadBudget's when called from
// its run() or parallel_for); runs inline when one chunk covers everything.
// Chunk boundaries depend on scheduling, so a body must give the same result
// however [0, count) is cut. Once `cancel` is requested no further chunk starts
// (the output is then incomplete, and the caller, which checks cancel itself,
// throws it away).
template <class Body>
void parallel_for_chunks(size_t count, size_t grain, const Body& body, const Cancel& cancel = {}) {
  if (count == 0) return;
  grain = std::max<size_t>(grain, 1);
  if (count <= grain) {
    if (!cancel.requested()) body(size_t(0), count);
    return;
  }
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, count, grain),
      [&](const tbb::blocked_range<size_t>& r) {
        if (!cancel.requested()) body(r.begin(), r.end());
      },
      tbb::simple_partitioner());
}

// Calls row(y) for every y in [0, height), within `pool` when given, else in the
// caller's arena (whole-image filters: each row writes only its own pixels). True when
// every row ran; rows not yet started are skipped once `cancel` is requested.
template <class RowFn>
bool parallel_rows(int height, ThreadBudget* pool, const RowFn& row_fn, const Cancel& cancel = {}) {
  std::atomic<int> skipped{0};
  const auto row = [&](int y) {
    if (cancel.requested()) {
      skipped.fetch_add(1, std::memory_order_relaxed);
    } else {
      row_fn(y);
    }
  };
  if (pool) {
    pool->parallel_for(height, [&](int y, int) { row(y); });
  } else {
    parallel_for_chunks(size_t(std::max(height, 0)), 1, [&](size_t begin, size_t end) {
      for (size_t y = begin; y < end; ++y) row(int(y));
    });
  }
  return skipped.load() == 0;
}

}  // namespace inkray
