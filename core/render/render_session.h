// RenderSession: owns the thread budget, the current compiled scene and the
// film, and renders progressive passes (one sample per pixel over tiles).
// A pass can be cancelled between tiles from any thread.
#pragma once

#include "core/base/parallel.h"
#include "core/film/film.h"
#include "core/npr/outlines/line_detector.h"
#include "core/world/render_scene.h"

#include <array>
#include <atomic>
#include <chrono>
#include <memory>
#include <optional>

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

// A progressive render's noise limit: the half-buffer estimate is too rough over the
// first few passes to stop on, so it counts from the fourth. 0: no limit.
inline bool noise_target_reached(const RenderStats& s, double target) {
  return target > 0.0 && s.passes >= 4 && s.relative_error > 0.0 && s.relative_error <= target;
}

class RenderSession {
 public:
  explicit RenderSession(int threads = 0);

  // Replaces the scene and restarts accumulation at the scene's resolution, or
  // at 1/divisor of it (an editor's preview: each film pixel then covers
  // divisor x divisor image pixels, and the camera still sees the whole frame).
  void set_scene(std::shared_ptr<const RenderScene> scene, AovSet aovs = {}, int divisor = 1);
  // Restricts passes to film pixels in [x0,x1) x [y0,y1) (a render region);
  // an empty rectangle means the whole film. Pixels outside keep their sums.
  void set_region(int x0, int y0, int x1, int y1) { region_ = {x0, y0, x1, y1}; }
  // Starts the region's accumulation again (stats from zero), keeping the film's
  // pixels outside it, and restricts passes to it.
  void restart_region(int x0, int y0, int x1, int y1) {
    film_->clear_region(x0, y0, x1, y1);
    stats_ = {};
    tiles_done_.clear();
    near_line_.clear();
    set_region(x0, y0, x1, y1);
  }
  int divisor() const { return divisor_; }
  // Swaps in a scene that differs from the current one only in what is read when
  // the film is resolved (line colours, the painterly filter, render limits: the
  // resolve and limits stages): the samples accumulated so far stay.
  void update_scene(std::shared_ptr<const RenderScene> scene) { scene_ = std::move(scene); }
  // Renders one pass; false when cancelled, leaving a partial pass in the film
  // that the next call completes (its finished tiles are not rendered again).
  bool render_pass();
  void cancel() { cancelled_.store(true, std::memory_order_relaxed); }

  const Film& film() const { return *film_; }
  const RenderScene& scene() const { return *scene_; }
  const RenderStats& stats() const { return stats_; }
  int threads() const { return pool_.size(); }
  // For work between passes (resolving the film) and for work that should stay
  // within this session's threads (run() a compile); never while a pass runs.
  ThreadBudget& pool() { return pool_; }

  static constexpr int kTileSize = 16;

 private:
  void render_tile(int tile, int worker, uint32_t pass);
  // Before the map exists every pixel counts as near a line.
  bool near_line(int x, int y) const {
    return near_line_.empty() || near_line_[size_t(y) * size_t(film_->width()) + size_t(x)];
  }

  ThreadBudget pool_;
  std::shared_ptr<const RenderScene> scene_;
  std::unique_ptr<Film> film_;
  LineSetup lines_;  // what the scene's outlines ask of every sample
  std::vector<uint8_t> near_line_;  // per film pixel, from the passes done (line_sampling.h)
  RenderStats stats_;
  std::atomic<bool> cancelled_{false};
  std::vector<uint64_t> worker_rays_;  // one slot per worker: no shared counter on the hot path
  std::vector<uint8_t> tiles_done_;  // tiles of the pass in progress already in the film
  int divisor_ = 1;
  std::array<int, 4> region_{0, 0, 0, 0};
};

}  // namespace inkray
