#include "core/render/thread_pool.h"

#include <algorithm>

namespace inkray {

ThreadPool::ThreadPool(int threads) {
  if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
  for (int i = 0; i < threads; ++i) workers_.emplace_back([this, i] { worker_loop(i); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (auto& t : workers_) t.join();
}

void ThreadPool::parallel_for(int count, const std::function<void(int, int)>& body) {
  if (count <= 0) return;
  std::unique_lock lock(mutex_);
  body_ = &body;
  count_ = count;
  next_.store(0, std::memory_order_relaxed);
  active_ = int(workers_.size());
  ++generation_;
  wake_.notify_all();
  done_.wait(lock, [this] { return active_ == 0; });
  body_ = nullptr;
}

void ThreadPool::worker_loop(int worker) {
  uint64_t seen = 0;
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
    if (stop_) return;
    seen = generation_;
    const auto* body = body_;
    const int count = count_;
    lock.unlock();
    for (int item; (item = next_.fetch_add(1, std::memory_order_relaxed)) < count;) (*body)(item, worker);
    lock.lock();
    if (--active_ == 0) done_.notify_all();
  }
}

}  // namespace inkray
