// ProgressiveRenderer: the editor's background renderer. A worker thread owns
// a RenderSession; submit() hands it a new document, which it compiles,
// previews at coarse resolutions, then refines at full resolution until a
// sample, time or noise limit. After every pass it publishes an immutable
// snapshot; the UI polls generation() and never waits for a pass. What the
// worker does next is decided by a ViewportSchedule, and the film's image is kept
// by a ViewportResolver (docs/architecture.md, "The viewport loop").
#pragma once

#include "core/film/film.h"
#include "core/film/resolve.h"
#include "core/render/display_encode.h"
#include "core/compiler/compile.h"
#include "core/render/render_session.h"
#include "core/render/viewport_resolver.h"
#include "core/render/viewport_schedule.h"
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
  // Waits until the worker sleeps for want of a request (paused, or finished, with any
  // pass in flight landed) or the deadline comes; true when it does.
  bool wait_until_idle(std::chrono::steady_clock::time_point deadline) const;
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
  // The UI's requests, written under mutex_ and taken by the worker when it waits.
  struct Requests {
    std::optional<SceneDesc> document;
    uint64_t revision = 0;                       // the document's
    std::chrono::steady_clock::time_point time;  // when it was submitted
    ViewportView view;
    ViewportLimits limits;
    RegionRect region;
    bool paused = false, stop = false, region_changed = false, view_changed = false;
  };

  // What a request does to the pass in flight: lets it finish, or stops it early.
  enum class Pass { continues, cancelled };
  // Changes requests_ under mutex_ with `change`, then wakes the worker.
  template <class Change>
  void request(Pass pass, Change change);

  // The worker: asks the schedule for the next piece of work and does it.
  void run();
  void execute(const ViewportWork& work);
  ViewportRequests take(bool wake_to_render);
  CompileOutcome compile();
  void restart(const ViewportWork& work);
  std::optional<double> render_pass(const ViewportWork& work);  // its time in ms; none when cancelled
  // False when cut short: a newer document is waiting.
  bool publish_snapshot(bool finished);
  ViewportFilm film_state() const;

  RenderSession session_;
  // Set when a newer document arrives (or the renderer stops): the compile and the
  // painterly filter in flight give up, so an edit shows within a frame or two even
  // after an edit that takes seconds to build.
  std::atomic<bool> superseded_{false};
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  mutable std::condition_variable published_;
  mutable std::condition_variable idle_;
  std::thread worker_;

  // Shared with the UI under mutex_.
  Requests requests_;
  uint64_t revisions_ = 0;
  std::vector<std::string> messages_, warnings_;
  std::shared_ptr<const ViewportSnapshot> latest_;
  std::shared_ptr<const RenderScene> scene_;  // written by the worker only
  uint64_t generation_ = 0;
  bool sleeping_ = false;  // the worker waits in take() with nothing to do

  // Worker-only state.
  Requests taken_;          // the requests as the worker last took them
  SceneCompiler compiler_;  // keeps what it built between the documents of its edits
  ViewportSchedule schedule_;
  ViewportResolver resolver_;
  uint64_t revision_ = 0;  // of the scene rendered, and when it was submitted
  std::chrono::steady_clock::time_point revision_time_;
  AovSet aovs_;  // the film's
  std::vector<ErrorSample> curve_;
};

}  // namespace inkray
