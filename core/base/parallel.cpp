// ThreadBudget: a task arena whose slot index is the worker index.
#include "core/base/parallel.h"

#include <tbb/info.h>

#include <algorithm>

namespace inkray {
namespace {

// TBB's pool has one thread per hardware thread: a larger arena could never fill
// its slots (and TBB prints a warning on creating one).
int budget_size(int threads) {
  const int hardware = std::max(1, tbb::info::default_concurrency());
  return threads > 0 ? std::min(threads, hardware) : hardware;
}

}  // namespace

// One slot is reserved for the calling thread, which works on the loop while it waits.
ThreadBudget::ThreadBudget(int threads) : size_(budget_size(threads)), arena_(size_, 1) {}

void ThreadBudget::parallel_for(int count, const std::function<void(int, int)>& body) {
  if (count <= 0) return;
  arena_.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<int>(0, count, 1),
        [&](const tbb::blocked_range<int>& r) {
          const int worker = tbb::this_task_arena::current_thread_index();
          // Isolated: should a body start parallel work of its own, its thread waits
          // on that work alone instead of picking up another item under the same
          // worker index while this one is half done.
          tbb::this_task_arena::isolate([&] {
            for (int item = r.begin(); item < r.end(); ++item) body(item, worker);
          });
        },
        tbb::simple_partitioner());
  });
}

}  // namespace inkray
