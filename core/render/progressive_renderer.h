// ProgressiveRenderer: the editor's background renderer. A worker thread owns
// a RenderSession; submit() hands it a new document, which it compiles,
// previews at 1/4 and 1/2 resolution, then refines at full resolution until a
// sample, time or noise limit. After every pass it publishes an immutable
// snapshot; the UI polls generation() and never waits for a pass.
#pragma once

#include "core/film/film.h"
#include "core/film/resolve.h"
#include "core/render/display_encode.h"
#include "core/compiler/compile.h"
#include "core/render/render_session.h"
#include "core/document/desc.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace inkray {

// ViewportView::display values below the AOV indices.
inline constexpr int kDisplayFinal = -1;
inline constexpr int kDisplayNoise = -2;  // Film::resolve_noise(), per-pixel relative error

struct ViewportView {
  int display = kDisplayFinal;  // kDisplayFinal, kDisplayNoise, else an Aov (index into kAovNames)
  DisplayEncoding encoding;
  int highlight_object = -1;  // SceneDesc object index outlined in the viewport
  std::array<uint8_t, 3> highlight_rgb{255, 160, 40};
  std::array<uint8_t, 3> highlight_rim{24, 14, 0};  // just outside the object: two colours, unlike an outline
  // The final image denoised (core/film/denoise.h). The viewport's film always keeps
  // the denoiser's features, so turning it on denoises the samples already taken.
  bool denoise = false;
  bool operator==(const ViewportView&) const = default;
};

struct ViewportLimits {
  int spp = 64;
  double time_seconds = 0.0;  // 0: none
  // Stop when the estimated relative error is below; 0: none. Tiles below it stop
  // taking samples before that (adaptive sampling, core/render/adaptive_sampling.h).
  double noise_target = 0.0;
};

// A render region in fractions of the image, [x0,x1) x [y0,y1); empty is the whole image.
struct RegionRect {
  float x0 = 0.f, y0 = 0.f, x1 = 0.f, y1 = 0.f;
  bool empty() const { return !(x1 > x0 && y1 > y0); }
};

struct ErrorSample {
  double seconds = 0.0;
  double relative_error = 0.0;
};

struct ViewportSnapshot {
  int width = 0, height = 0;  // of rgba, which is the film: image resolution / divisor
  int divisor = 1;
  std::vector<uint8_t> rgba;
  RenderStats stats;
  std::vector<ErrorSample> error_curve;  // full-resolution passes of this revision
  bool finished = false;                 // a limit was reached; the worker idles
  uint64_t revision = 0;                 // the submit() this image shows
  // Which accumulation of samples this image shows: it changes whenever the film
  // restarts (a preview, a new document that needs new samples), and stays across
  // edits that re-composite the samples already taken (docs/architecture.md, "Stages").
  uint64_t accumulation = 0;
  double submit_to_publish_ms = 0.0;  // latency from that submit() to this snapshot
  // The final image is denoised: from the film at `denoised_spp` (the denoiser runs
  // again only when its cost is small beside the passes since), with this estimated
  // relative error (Denoised::relative_error); stats.relative_error stays the raw one.
  bool denoised = false;
  uint32_t denoised_spp = 0;
  double denoised_error = 0.0;
};

class ProgressiveRenderer {
 public:
  explicit ProgressiveRenderer(int threads = 0);
  ~ProgressiveRenderer();
  ProgressiveRenderer(const ProgressiveRenderer&) = delete;
  ProgressiveRenderer& operator=(const ProgressiveRenderer&) = delete;

  // A new document: cancels the pass in flight and restarts from a preview.
  // Returns the revision that snapshots of this document will carry.
  uint64_t submit(const SceneDesc& scene);
  // Re-encodes, compositing the lines again; re-renders only for a missing AOV.
  void set_view(const ViewportView& view);
  void set_limits(const ViewportLimits& limits);
  void set_region(const RegionRect& region);  // restarts at full resolution inside the region
  void set_paused(bool paused);
  bool paused() const;

  uint64_t generation() const;  // increments with every published snapshot
  // Waits until the generation passes `after` or the deadline comes; true for a
  // new snapshot. Lets a UI without vsync draw an image as soon as it exists.
  bool wait_for_generation(uint64_t after, std::chrono::steady_clock::time_point deadline) const;
  std::shared_ptr<const ViewportSnapshot> latest() const;
  // The newest compiled scene (for picking on the UI thread; it is immutable).
  std::shared_ptr<const RenderScene> scene() const;
  // Compile errors since the last call: the newest document did not render.
  std::vector<std::string> take_messages();
  // Compile warnings since the last call: it renders, with stand-ins (a broken graph, a
  // missing file) drawn where they are.
  std::vector<std::string> take_warnings();
  int threads() const { return session_.threads(); }

 private:
  void run();
  void publish_snapshot(const std::shared_ptr<const RenderScene>& scene, const ViewportView& view,
                        const ViewportLimits& limits, bool finished);
  bool limits_reached(const ViewportLimits& limits) const;
  // After a document's first preview, which took `ms` at `divisor`: the divisor the
  // next document's first preview starts at (kFirstPreviewBudgetMs).
  void adapt_first_preview(int divisor, double ms);
  // The film's mean radiance as the final image starts from: denoised when the view asks.
  RgbImage final_radiance(const ViewportView& view, bool finished, const Cancel& cancel);

  RenderSession session_;
  // Set when a newer document arrives (or the renderer stops): the compile and the
  // painterly filter in flight give up, so an edit shows within a frame or two even
  // after an edit that takes seconds to build.
  std::atomic<bool> superseded_{false};
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  mutable std::condition_variable published_;
  std::thread worker_;

  // Written by the UI under mutex_, read by the worker at its next step.
  std::optional<SceneDesc> pending_;
  uint64_t pending_revision_ = 0;
  std::chrono::steady_clock::time_point pending_time_;
  ViewportView view_;
  ViewportLimits limits_;
  RegionRect region_;
  bool paused_ = false, stop_ = false, reencode_ = false, restart_ = false;
  uint64_t revisions_ = 0;
  std::vector<std::string> messages_, warnings_;
  std::shared_ptr<const ViewportSnapshot> latest_;
  std::shared_ptr<const RenderScene> scene_;
  uint64_t generation_ = 0;

  // Worker-only state.
  SceneCompiler compiler_;  // keeps what it built between the documents of its edits
  uint64_t revision_ = 0;
  std::chrono::steady_clock::time_point revision_time_;
  bool first_publish_ = true, active_ = false;
  int first_divisor_ = 8;  // the first preview's: kFirstPreviewDivisor, then adapt_first_preview's
  uint64_t accumulation_ = 0;
  // The film's image without lines (mean and painterly filter) and its lines,
  // while no sample changed since, and the settings it was filtered with: an edit
  // of lines only keeps it. `resolved_` is it with the lines composited for
  // `resolved_for_` (empty without lines): lines are composited in display space,
  // so a new exposure or view transform composites them again over the same base
  // (core/film/resolve.h), without filtering again.
  RgbImage base_;
  bool base_denoised_ = false;
  // The last denoised radiance, of accumulation `denoised_accumulation_` at
  // `denoised_spp_`, and what denoising it cost.
  RgbImage denoised_;
  uint64_t denoised_accumulation_ = ~uint64_t(0);
  uint32_t denoised_spp_ = 0;
  double denoised_error_ = 0.0, denoise_seconds_ = 0.0;
  std::chrono::steady_clock::time_point denoised_at_;
  FilmLines lines_;
  RenderSettings base_settings_;
  bool base_current_ = false;
  RgbImage resolved_;
  DisplayEncoding resolved_for_;
  bool resolved_current_ = false;
  AovSet aovs_;
  std::vector<ErrorSample> curve_;
};

}  // namespace inkray
