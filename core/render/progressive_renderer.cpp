#include "core/render/progressive_renderer.h"

#include "core/film/aov_display.h"
#include "core/film/denoise.h"
#include "core/film/resolve.h"
#include "core/compiler/compile.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace inkray {
namespace {

// The first preview is this much coarser than the image (per axis): 1/64 of
// the pixels, so it is ready within a UI frame or two even on one thread;
// each following stage halves it. A scene whose first preview takes longer than
// kFirstPreviewBudgetMs starts one step coarser from then on, down to
// kCoarsestPreviewDivisor, and one whose next step finer would take under half of it
// one step finer.
constexpr int kFirstPreviewDivisor = 8;
constexpr int kCoarsestPreviewDivisor = 32;
constexpr double kFirstPreviewBudgetMs = 8.0;

AovSet aovs_for(const ViewportView& view) {
  // The selection highlight reads object ids; the denoiser's features are always kept,
  // so turning it on denoises the samples taken so far.
  AovSet aovs = denoise_aovs();
  aovs.add(Aov::object_id);
  if (view.display >= 0 && view.display < int(kAovNames.size())) aovs.add(Aov(view.display));
  return aovs;
}

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

ProgressiveRenderer::ProgressiveRenderer(int threads) : session_(threads) {
  worker_ = std::thread([this] { run(); });
}

ProgressiveRenderer::~ProgressiveRenderer() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  superseded_.store(true);
  session_.cancel();
  wake_.notify_all();
  worker_.join();
}

uint64_t ProgressiveRenderer::submit(const SceneDesc& scene) {
  uint64_t revision;
  {
    std::lock_guard lock(mutex_);
    pending_ = scene;
    revision = pending_revision_ = ++revisions_;
    pending_time_ = std::chrono::steady_clock::now();
    // Under the lock, so it cannot land after the worker took this very document.
    superseded_.store(true);
  }
  session_.cancel();
  wake_.notify_all();
  return revision;
}

void ProgressiveRenderer::set_view(const ViewportView& view) {
  {
    std::lock_guard lock(mutex_);
    view_ = view;
    reencode_ = true;
  }
  // The pass in flight stops and resumes after the new encoding is published (its
  // finished tiles are kept), so an exposure drag shows at once, not a pass later.
  session_.cancel();
  wake_.notify_all();
}

void ProgressiveRenderer::set_limits(const ViewportLimits& limits) {
  {
    std::lock_guard lock(mutex_);
    limits_ = limits;
    reencode_ = true;  // a raised limit lets a finished render continue
  }
  wake_.notify_all();
}

void ProgressiveRenderer::set_region(const RegionRect& region) {
  {
    std::lock_guard lock(mutex_);
    region_ = region;
    restart_ = true;
  }
  session_.cancel();
  wake_.notify_all();
}

void ProgressiveRenderer::set_paused(bool paused) {
  {
    std::lock_guard lock(mutex_);
    paused_ = paused;
  }
  wake_.notify_all();
}

bool ProgressiveRenderer::paused() const {
  std::lock_guard lock(mutex_);
  return paused_;
}

uint64_t ProgressiveRenderer::generation() const {
  std::lock_guard lock(mutex_);
  return generation_;
}

bool ProgressiveRenderer::wait_for_generation(uint64_t after,
                                              std::chrono::steady_clock::time_point deadline) const {
  std::unique_lock lock(mutex_);
  return published_.wait_until(lock, deadline, [&] { return generation_ > after; });
}

std::shared_ptr<const ViewportSnapshot> ProgressiveRenderer::latest() const {
  std::lock_guard lock(mutex_);
  return latest_;
}

std::shared_ptr<const RenderScene> ProgressiveRenderer::scene() const {
  std::lock_guard lock(mutex_);
  return scene_;
}

std::vector<std::string> ProgressiveRenderer::take_messages() {
  std::lock_guard lock(mutex_);
  return std::exchange(messages_, {});
}

std::vector<std::string> ProgressiveRenderer::take_warnings() {
  std::lock_guard lock(mutex_);
  return std::exchange(warnings_, {});
}

void ProgressiveRenderer::run() {
  std::shared_ptr<const RenderScene> scene;  // what the session renders
  for (;;) {
    std::optional<SceneDesc> desc;
    bool restart = false, reencode = false, paused = false;
    ViewportView view;
    ViewportLimits limits;
    RegionRect region;
    uint64_t revision = 0;
    std::chrono::steady_clock::time_point revision_time;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || pending_ || restart_ || reencode_ || (active_ && !paused_); });
      if (stop_) return;
      desc = std::move(pending_);
      pending_.reset();
      superseded_.store(false);  // under the lock: a submit() after this sets it again
      revision = pending_revision_;
      revision_time = pending_time_;
      restart = std::exchange(restart_, false);
      reencode = std::exchange(reencode_, false);
      view = view_;
      limits = limits_;
      region = region_;
      paused = paused_;
    }
    bool keep_film = false;
    if (desc) {
      // The compiler redoes only what the edit touched (docs/architecture.md, "Stages"):
      // a camera move or a material edit costs no rebuild of the geometry.
      CompileOptions options;
      options.cancel = Cancel(&superseded_);
      options.stand_in_for_broken_graphs = true;   // one bad graph must not blank the viewport
      options.stand_in_for_missing_assets = true;  // nor a file that moved: it is drawn as a placeholder
      CompileResult compiled = session_.pool().run([&] { return compiler_.compile(*desc, options); });
      std::lock_guard lock(mutex_);
      if (compiled.cancelled) continue;  // the newer document is waiting
      if (!compiled.scene) {
        messages_.insert(messages_.end(), compiled.errors.begin(), compiled.errors.end());
        continue;  // the last good scene stays on screen
      }
      warnings_.insert(warnings_.end(), compiled.warnings.begin(), compiled.warnings.end());
      // Line colours, the painterly filter and render limits are read when the film
      // is resolved: the samples so far stay, and the image is composited again.
      keep_film =
          scene && !restart && compiled.changes.within({Stage::layout, Stage::resolve, Stage::limits});
      scene = scene_ = compiled.scene;
      revision_ = revision;
      revision_time_ = revision_time;
      if (!keep_film) restart = true;
    }
    if (!scene) continue;
    const bool region_only = restart && !desc;  // set_region() alone asked for it
    if (reencode && (aovs_for(view).bits & ~aovs_.bits) != 0) restart = true;
    if (restart && region_only && !region.empty() && session_.divisor() == 1 &&
        aovs_for(view).bits == aovs_.bits) {
      // A region over the full-resolution film: the pixels around it keep their samples.
      const int w = session_.film().width(), h = session_.film().height();
      session_.restart_region(int(std::floor(region.x0 * w)), int(std::floor(region.y0 * h)),
                              int(std::ceil(region.x1 * w)), int(std::ceil(region.y1 * h)));
      curve_.clear();
      ++accumulation_;
      base_current_ = false;
      active_ = true;
    } else if (restart) {
      aovs_ = aovs_for(view);
      curve_.clear();
      first_publish_ = true;
      const int divisor = region.empty() ? first_divisor_ : 1;
      session_.set_scene(scene, aovs_, divisor);
      ++accumulation_;
      base_current_ = false;
      const int w = session_.film().width(), h = session_.film().height();
      if (region.empty()) {
        session_.set_region(0, 0, 0, 0);
      } else {
        session_.set_region(int(std::floor(region.x0 * w)), int(std::floor(region.y0 * h)),
                            int(std::ceil(region.x1 * w)), int(std::ceil(region.y1 * h)));
      }
      active_ = true;
    } else if (keep_film) {
      session_.update_scene(scene);
      // A line edit composites the cached base again; a filter edit filters anew.
      if (!same_base(base_settings_, scene->settings)) base_current_ = false;
      resolved_current_ = false;
      active_ = true;
      if (session_.stats().passes > 0) publish_snapshot(scene, view, limits, false);
    } else if (reencode) {
      active_ = true;  // limits may have been raised; limits_reached() decides below
      if (session_.stats().passes > 0) publish_snapshot(scene, view, limits, false);
    }
    if (!active_ || paused) continue;
    const int divisor = session_.divisor();
    if (divisor == 1 && session_.stats().passes > 0 && limits_reached(limits)) {
      active_ = false;
      publish_snapshot(scene, view, limits, true);
      continue;
    }
    base_current_ = false;  // the pass adds samples, finished or not
    // Only the full-resolution film samples adaptively; each preview is one pass.
    session_.set_adaptive({divisor == 1 ? limits.noise_target : 0.0, 16});
    const auto pass_start = std::chrono::steady_clock::now();
    if (!session_.render_pass()) continue;  // cancelled: a newer request is waiting
    if (first_publish_ && divisor > 1) adapt_first_preview(divisor, ms_since(pass_start));
    const RenderStats& stats = session_.stats();
    if (divisor == 1) curve_.push_back({stats.elapsed_seconds, stats.relative_error});
    const bool done = divisor == 1 && limits_reached(limits);
    publish_snapshot(scene, view, limits, done);
    if (divisor > 1) {
      session_.set_scene(scene, aovs_, divisor / 2);
      ++accumulation_;
      base_current_ = false;
    } else if (done) {
      active_ = false;
    }
  }
}

void ProgressiveRenderer::adapt_first_preview(int divisor, double ms) {
  if (ms > kFirstPreviewBudgetMs && divisor < kCoarsestPreviewDivisor) {
    first_divisor_ = divisor * 2;
  } else if (4.0 * ms < 0.5 * kFirstPreviewBudgetMs && divisor > kFirstPreviewDivisor) {
    // One step finer has four times the pixels: taken only while that stays well within
    // the budget, so the divisor does not swing between two steps.
    first_divisor_ = divisor / 2;
  }
}

bool ProgressiveRenderer::limits_reached(const ViewportLimits& limits) const {
  const RenderStats& s = session_.stats();
  if (limits.spp > 0 && int(s.spp) >= limits.spp) return true;
  if (limits.time_seconds > 0.0 && s.elapsed_seconds >= limits.time_seconds) return true;
  return noise_target_reached(s, limits.noise_target) || session_.converged();
}

RgbImage ProgressiveRenderer::final_radiance(const ViewportView& view, bool finished, const Cancel& cancel) {
  const Film& film = session_.film();
  if (!view.denoise || film.width() == 0) return film.resolve();
  // Denoising again costs a few passes' time at most: once its cost is small beside
  // the time since, at a new accumulation, and when the render finishes.
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - denoised_at_).count();
  const bool due = denoised_accumulation_ != accumulation_ || finished ||
                   (session_.stats().spp != denoised_spp_ && since >= std::max(0.5, 4.0 * denoise_seconds_));
  if (due) {
    Denoised d = denoise(film, &session_.pool(), cancel);
    if (d.image.pixels.empty()) return {};
    denoised_ = std::move(d.image);
    denoised_error_ = d.relative_error;
    denoised_accumulation_ = accumulation_;
    denoised_spp_ = session_.stats().spp;
    denoise_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - now).count();
    denoised_at_ = std::chrono::steady_clock::now();
  }
  return denoised_;
}

void ProgressiveRenderer::publish_snapshot(const std::shared_ptr<const RenderScene>& scene,
                                           const ViewportView& view, const ViewportLimits&, bool finished) {
  const Film& film = session_.film();
  auto snap = std::make_shared<ViewportSnapshot>();
  if (view.display >= 0 && film.aovs().has(Aov(view.display))) {
    const Aov aov = Aov(view.display);
    snap->rgba = encode_display(aov_for_display(aov, film.resolve_aov(aov)), DisplayEncoding{});
  } else if (view.display == kDisplayNoise) {
    // Raw, so grey is proportional to the error (white = 100 % at 0 EV); the
    // exposure slider still applies to make small errors visible.
    snap->rgba =
        encode_display(film.resolve_noise(), DisplayEncoding{view.encoding.exposure, ViewTransform::raw});
  } else {
    if (base_denoised_ != view.denoise) base_current_ = false;
    if (!base_current_) {
      const Cancel cancel(&superseded_);
      RgbImage radiance = final_radiance(view, finished, cancel);
      if (radiance.pixels.empty()) return;  // cut short: the newer document is waiting
      base_ = resolve_base(std::move(radiance), scene->settings, film.height(), &session_.pool(), cancel);
      if (base_.pixels.empty()) return;
      base_denoised_ = view.denoise;
      lines_ = gather_lines(film);
      base_settings_ = scene->settings;
      base_current_ = true;
      resolved_current_ = false;
    }
    if (!film.has_lines()) {
      resolved_ = {};
    } else if (!resolved_current_ || !(resolved_for_ == view.encoding)) {
      resolved_ = base_;  // reuses its pixels' storage
      composite_lines(lines_, scene->outlines, view.encoding, resolved_);
      resolved_for_ = view.encoding;
      resolved_current_ = true;
    }
    snap->rgba = encode_display(film.has_lines() ? resolved_ : base_, view.encoding);
  }
  if (view.highlight_object >= 0 && film.aovs().has(Aov::object_id)) {
    // Previews are magnified, so their 1-pixel line is already thick on screen.
    paint_highlight(snap->rgba, film.resolve_aov(Aov::object_id), view.highlight_object, view.highlight_rgb,
                    session_.divisor() == 1 ? 2 : 1, view.highlight_rim);
  }
  snap->width = film.width();
  snap->height = film.height();
  snap->divisor = session_.divisor();
  snap->stats = session_.stats();
  snap->error_curve = curve_;
  snap->finished = finished;
  snap->accumulation = accumulation_;
  snap->denoised = view.denoise && view.display == kDisplayFinal;
  if (snap->denoised) {
    snap->denoised_spp = denoised_spp_;
    snap->denoised_error = denoised_error_;
  }
  {
    std::lock_guard lock(mutex_);
    snap->revision = revision_;
    snap->submit_to_publish_ms = ms_since(revision_time_);
    first_publish_ = false;
    latest_ = std::move(snap);
    ++generation_;
  }
  published_.notify_all();
}

}  // namespace inkray
