// ThreadBudget and parallel_for_chunks: every item once, worker indices in range
// and never shared by two bodies at once, and a budget's cap on its threads.
#include "core/base/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

namespace inkray {
namespace {

TEST(ThreadBudget, RunsEveryItemOnceWithAWorkerNoOtherBodyHolds) {
  ThreadBudget budget(0);
  ASSERT_GE(budget.size(), 1);
  std::vector<std::atomic<int>> runs(500);
  std::vector<std::atomic<int>> busy(size_t(budget.size()));
  std::atomic<bool> bad_worker{false}, shared{false};
  budget.parallel_for(int(runs.size()), [&](int item, int worker) {
    if (worker < 0 || worker >= budget.size()) {
      bad_worker = true;
      return;
    }
    if (busy[size_t(worker)].fetch_add(1) != 0) shared = true;
    std::this_thread::yield();
    runs[size_t(item)].fetch_add(1);
    busy[size_t(worker)].fetch_sub(1);
  });
  EXPECT_FALSE(bad_worker);
  EXPECT_FALSE(shared);
  for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
}

TEST(ThreadBudget, CapsTheThreadsOfWhatItRuns) {
  ThreadBudget one(1);
  EXPECT_EQ(one.size(), 1);
  EXPECT_EQ(ThreadBudget(100000).size(), ThreadBudget(0).size());
  // Chunks started from run() stay on the calling thread when the budget is one.
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> elsewhere{0};
  const int result = one.run([&] {
    parallel_for_chunks(10000, 10,
                        [&](size_t, size_t) { elsewhere += std::this_thread::get_id() != caller; });
    return 42;
  });
  EXPECT_EQ(result, 42);
  EXPECT_EQ(elsewhere.load(), 0);
}

TEST(ParallelForChunks, CoversTheRangeOnceInChunksOfAtMostGrain) {
  std::vector<std::atomic<int>> hits(10007);
  std::atomic<bool> too_big{false};
  parallel_for_chunks(hits.size(), 64, [&](size_t begin, size_t end) {
    if (end - begin > 64) too_big = true;
    for (size_t i = begin; i < end; ++i) hits[i].fetch_add(1);
  });
  EXPECT_FALSE(too_big);
  for (const auto& h : hits) EXPECT_EQ(h.load(), 1);
  int calls = 0;
  parallel_for_chunks(0, 8, [&](size_t, size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(ParallelForChunks, NoChunkStartsOnceCancelled) {
  std::atomic<bool> flag{true};
  std::atomic<int> calls{0};
  parallel_for_chunks(
      1000, 10, [&](size_t, size_t) { ++calls; }, Cancel(&flag));
  EXPECT_EQ(calls.load(), 0);
}

}  // namespace
}  // namespace inkray
