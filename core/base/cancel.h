// A request to stop long work early: a flag another thread sets (the editor's next
// edit, its Cancel button), a deadline (the CLI's --time), or both. Loops that can
// run for seconds (compiling, growing strokes, painterly filters) check it between
// chunks, so a stop takes effect within milliseconds; see docs/architecture.md.
#pragma once

#include <atomic>
#include <chrono>

namespace inkray {

class Cancel {
 public:
  using Clock = std::chrono::steady_clock;

  Cancel() = default;  // never requested
  explicit Cancel(const std::atomic<bool>* flag, Clock::time_point deadline = Clock::time_point::max())
      : flag_(flag), deadline_(deadline) {}
  static Cancel at(Clock::time_point deadline) { return Cancel(nullptr, deadline); }

  bool requested() const {
    if (flag_ && flag_->load(std::memory_order_relaxed)) return true;
    return deadline_ != Clock::time_point::max() && Clock::now() >= deadline_;
  }
  bool has_deadline() const { return deadline_ != Clock::time_point::max(); }

 private:
  const std::atomic<bool>* flag_ = nullptr;
  Clock::time_point deadline_ = Clock::time_point::max();
};

}  // namespace inkray
