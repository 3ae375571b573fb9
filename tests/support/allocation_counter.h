// Counts the bytes this thread allocates through operator new while a
// CountAllocations lives: the price of a copy, measured rather than estimated
// (tests/support/allocation_counter.cpp replaces the global operator new).
#pragma once

#include <cstddef>

namespace inkray::testing {

class CountAllocations {
 public:
  CountAllocations();
  ~CountAllocations();
  CountAllocations(const CountAllocations&) = delete;
  CountAllocations& operator=(const CountAllocations&) = delete;

  std::size_t bytes() const;  // allocated on this thread since construction

 private:
  std::size_t start_;
  bool outer_;  // counting was off before: it is turned off again at the end
};

}  // namespace inkray::testing
