// RenderSession: owns the thread pool, the current compiled scene and the
// film, and renders progressive passes (one sample per pixel over tiles).
// A pass can be cancelled between tiles from any thread.
#pragma once

#include "core/film/film.h"
#include "core/render/thread_pool.h"
#include "core/scene/render_scene.h"

#include <atomic>
#include <chrono>
#include <memory>

namespace inkray {

struct RenderStats {
  uint32_t passes = 0;
  uint32_t spp = 0;
  double elapsed_seconds = 0.0;  // time spent in passes since the scene was set
  double relative_error = 0.0;   // estimated from the half-buffers; 0 until two passes exist
  uint64_t rays = 0;
  uint64_t paths = 0;
  uint64_t nonfinite_samples = 0;
};

class RenderSession {
 public:
  explicit RenderSession(int threads = 0);

  // Replaces the scene and restarts accumulation at the scene's resolution.
  void set_scene(std::shared_ptr<const RenderScene> scene, AovSet aovs = {});
  // Renders one pass; false when cancelled, leaving a partial pass in the film
  // (callers cancel to restart, which clears it).
  bool render_pass();
  void cancel() { cancelled_.store(true, std::memory_order_relaxed); }

  const Film& film() const { return *film_; }
  const RenderScene& scene() const { return *scene_; }
  const RenderStats& stats() const { return stats_; }
  int threads() const { return pool_.size(); }

  static constexpr int kTileSize = 16;

 private:
  void render_tile(int tile, int worker, uint32_t pass);

  ThreadPool pool_;
  std::shared_ptr<const RenderScene> scene_;
  std::unique_ptr<Film> film_;
  RenderStats stats_;
  std::atomic<bool> cancelled_{false};
  std::vector<uint64_t> worker_rays_;  // one slot per worker: no shared counter on the hot path
};

}  // namespace inkray
