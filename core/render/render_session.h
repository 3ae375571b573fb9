// RenderSession: owns the thread budget, the current compiled scene and the
// film, and renders progressive passes (one sample per pixel over tiles).
// A pass can be cancelled between tiles from any thread.
#pragma once

#include "core/base/parallel.h"
#include "core/film/film.h"
#include "core/npr/outlines/line_detector.h"
#include "core/npr/outlines/line_sampling.h"
#include "core/render/adaptive_sampling.h"
#include "core/world/render_scene.h"

#include <array>
#include <atomic>
#include <chrono>
#include <memory>
#include <optional>

namespace inkray {

struct RenderStats {
  uint32_t passes = 0;  // the pass the next render_pass renders (passes of the sample sequence so far)
  uint32_t spp = 0;     // samples per pixel in the film: passes since the film's first

  double elapsed_seconds = 0.0;  // time spent in passes since the scene was set
  double relative_error = 0.0;   // estimated from the half-buffers; 0 until two passes exist
  uint64_t rays = 0;
  uint64_t paths = 0;
  uint64_t nonfinite_samples = 0;
  // Adaptive sampling: tiles of the active window still taking samples, of how many.
  uint32_t active_tiles = 0, tiles = 0;
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
  void set_region(int x0, int y0, int x1, int y1) { set_region({x0, y0, x1, y1}); }
  void set_region(const PixelWindow& w) {
    region_ = w;
    reset_adaptive();
  }
  // Starts the region's accumulation again (stats from zero), keeping the film's
  // pixels outside it, and restricts passes to it.
  void restart_region(int x0, int y0, int x1, int y1);
  PixelWindow region() const { return region_; }
  // The film holds passes [first, next) of the sample sequence, and of pass `next`
  // the tiles marked in `tiles_done` (a render cut mid-pass), for the pixels of the
  // region; the next render_pass renders pass `next`, completing a cut one. What
  // adaptive line sampling decided in the passes before `next` is traced again
  // (only what the decisions read: the probes and the rays of pixels still
  // deciding) or counted, so every later pass traces what a render from pass 0
  // would. Call on a film fresh from set_scene, or loaded with load_film.
  // A slice of passes [A, B): continue_from(A, A), then B - A passes.
  // With `decided` (decide_lines of this scene and film size) and next at or after its
  // decided_at, nothing is traced again: the decisions are read from it.
  void continue_from(uint32_t first, uint32_t next, const std::vector<uint8_t>& tiles_done = {},
                     const LineDecisions* decided = nullptr);
  // Traces what adaptive line sampling's decisions read over the whole film, from pass
  // 0 until no pixel is deciding, and returns the decisions (line_sampling.h). The
  // film is untouched and the session stays ready to render from pass 0.
  LineDecisions decide_lines();
  // Adds a film of the region's size (a checkpoint read back) at the region's place.
  void load_film(const Film& window_film);
  uint32_t first_pass() const { return first_pass_; }
  // Tiles of the pass in progress already in the film (empty or all zero between passes).
  const std::vector<uint8_t>& tiles_done() const { return tiles_done_; }
  int divisor() const { return divisor_; }
  // Swaps in a scene that differs from the current one only in what is read when
  // the film is resolved (line colours, the painterly filter, render limits: the
  // resolve and limits stages): the samples accumulated so far stay.
  void update_scene(std::shared_ptr<const RenderScene> scene) { scene_ = std::move(scene); }
  // Adaptive sampling from the next pass on (adaptive_sampling.h). A tighter threshold,
  // or 0 (off), sets every tile sampling again, as do a new scene and a new region.
  void set_adaptive(const AdaptiveSampling& adaptive);
  const AdaptiveSampling& adaptive() const { return adaptive_; }
  // Every tile has stopped: more passes would add nothing.
  bool converged() const { return adaptive_.on() && stats_.passes > 0 && stats_.active_tiles == 0; }
  // Renders one pass; false when cancelled, leaving a partial pass in the film
  // that the next call completes (its finished tiles are not rendered again).
  bool render_pass();
  // Stops the pass in flight, or the next one if none is: a pass ends the cancel.
  void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
  // Withdraws a cancel no pass has ended yet: its reason was dealt with otherwise.
  void clear_cancel() { cancelled_.store(false, std::memory_order_relaxed); }

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
  // What render_tile decides about lines in pass `pass` of a tile, without the paths:
  // traces only the samples a decision reads.
  void replay_tile(int tile, uint32_t pass);
  // Pixels whose probes the region's line map reads, beyond the region itself:
  // in a probe pass they trace their probe's lines (only), as in a render of the
  // whole film. Calls f(x, y) for each in the tile.
  template <class F>
  void for_margin_pixels(int tile, uint32_t pass, F&& f) const;
  PixelWindow tile_window(int tile) const;
  TileGrid tile_grid() const { return {film_->width(), film_->height(), kTileSize}; }
  void reset_adaptive();   // every tile active
  void update_adaptive();  // after a pass
  int tile_count() const;
  PixelWindow active_window() const;  // the region, or the whole film
  // The lines of the sample (x, y, pass) alone, as render_tile finds them, given `count` rays.
  LineSample trace_lines_only(int x, int y, uint32_t pass, int count, uint64_t* rays) const;
  void finish_probes(uint32_t pass);
  // Replays decisions from pass 0 (line_pixels_ fresh) until `next` or until no pixel of
  // the active window is deciding; returns the pass it stopped at.
  uint32_t replay_decisions(uint32_t next);

  // A cleared film of this size from the spares when there is one, else a new one;
  // the film set before joins the spares. The viewport steps through the same few
  // sizes (its previews and the image) on every edit, and a new film of the full
  // image costs tens of milliseconds of page faults, which an edit arriving meanwhile
  // waits for.
  std::unique_ptr<Film> film_for(int width, int height, AovSet aovs, bool lines);
  static constexpr size_t kSpareFilms = 5;

  ThreadBudget pool_;
  std::shared_ptr<const RenderScene> scene_;
  std::unique_ptr<Film> film_;
  std::vector<std::unique_ptr<Film>> spare_films_;
  LineSetup lines_;                     // what the scene's outlines ask of every sample
  std::vector<LinePixel> line_pixels_;  // per film pixel: adaptive line sampling's state
  uint32_t first_pass_ = 0;
  RenderStats stats_;
  std::atomic<bool> cancelled_{false};
  std::vector<uint64_t> worker_rays_;  // one slot per worker: no shared counter on the hot path
  std::vector<uint8_t> tiles_done_;    // tiles of the pass in progress already in the film
  AdaptiveSampling adaptive_;
  std::vector<uint8_t> tile_active_;  // per tile: still taking samples
  int divisor_ = 1;
  PixelWindow region_;
};

}  // namespace inkray
