// Final renders: passes until the sample count or the time limit. A pass can take
// long (a closed white room at 1024 bounces, an 8K image), so the time limit also
// stops a pass in flight.
#include "core/render/batch_render.h"

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace inkray {
namespace {

// Cancels the session's passes once the time limit passes, until stopped.
class PassDeadline {
 public:
  PassDeadline(RenderSession& session, double seconds) {
    if (seconds <= 0.0) return;
    deadline_ =
        std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                               std::chrono::duration<double>(seconds));
    watcher_ = std::thread([this, &session] {
      std::unique_lock lock(mutex_);
      if (!wake_.wait_until(lock, deadline_, [this] { return stopped_; })) session.cancel();
    });
  }
  // Also checked between passes: a cancel that lands between two passes is cleared by
  // the next one's start, so the watcher alone could miss it.
  bool passed() const { return std::chrono::steady_clock::now() >= deadline_; }
  ~PassDeadline() {
    {
      std::lock_guard lock(mutex_);
      stopped_ = true;
    }
    wake_.notify_all();
    if (watcher_.joinable()) watcher_.join();
  }

 private:
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopped_ = false;
  std::chrono::steady_clock::time_point deadline_ = std::chrono::steady_clock::time_point::max();
  std::thread watcher_;
};

}  // namespace

std::vector<PassRecord> render_batch(RenderSession& session, const BatchLimits& limits,
                                     const std::function<void(const RenderStats&)>& on_pass) {
  std::vector<PassRecord> history;
  // Passes stop at the limit even mid-pass. The tiles a cut pass finished keep their
  // sample: the film counts samples per pixel, so every pixel's mean stays right.
  PassDeadline deadline(session, limits.time_seconds);
  while (int(session.stats().spp) < limits.spp && !deadline.passed() && !session.converged()) {
    if (!session.render_pass()) break;
    const RenderStats& s = session.stats();
    history.push_back({s.passes, s.spp, s.elapsed_seconds, s.relative_error});
    if (on_pass) on_pass(s);
  }
  return history;
}

}  // namespace inkray
