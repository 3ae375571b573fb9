// The figures benchmarks print from repeated timings.
#pragma once

#include <algorithm>
#include <vector>

namespace inkray::bench {

// The middle value (the upper one of an even count): unlike the mean, one run slowed by
// the machine does not move it. 0 for no values.
inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace inkray::bench
