// A parallel loop for building stroke geometry at compile time, when no render
// thread pool exists yet. Items write only their own outputs, so the result is
// the same at any thread count.
#pragma once

#include "core/base/cancel.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace inkray {

// Upper bound on the threads parallel_chunks uses; 0 means one per hardware
// thread. Benchmarks set it to measure scaling, tests to check that results do
// not depend on it.
inline std::atomic<unsigned> stroke_build_thread_limit{0};

inline unsigned stroke_build_threads() {
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const unsigned limit = stroke_build_thread_limit.load(std::memory_order_relaxed);
  return limit == 0 ? hardware : limit;
}

// Calls body(begin, end) over [0, count) in chunks of `grain`, on up to
// stroke_build_threads() threads; runs inline when there is a single chunk. Once
// `cancel` is requested no further chunk starts (the output is then incomplete, and
// the caller, which checks cancel itself, throws it away).
template <class Body> void parallel_chunks(size_t count, size_t grain, const Body& body, const Cancel& cancel = {}) {
  grain = std::max<size_t>(grain, 1);
  const size_t chunks = (count + grain - 1) / grain;
  const size_t threads = std::min<size_t>(chunks, stroke_build_threads());
  if (threads <= 1) {
    for (size_t c = 0; c < chunks && !cancel.requested(); ++c) body(c * grain, std::min(count, (c + 1) * grain));
    return;
  }
  std::atomic<size_t> next{0};
  const auto work = [&] {
    for (size_t c = next++; c < chunks && !cancel.requested(); c = next++)
      body(c * grain, std::min(count, (c + 1) * grain));
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}

}  // namespace inkray
