// The figures benchmarks print from repeated timings.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace inkray::bench {

// The middle value (the upper one of an even count): unlike the mean, one run slowed by
// the machine does not move it. 0 for no values.
inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// The median milliseconds of `runs` calls of f.
template <class F>
double median_ms(int runs, F&& f) {
  std::vector<double> times;
  for (int r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    times.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return median(times);
}

}  // namespace inkray::bench
