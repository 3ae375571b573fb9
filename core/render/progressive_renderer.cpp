#include "core/render/progressive_renderer.h"

#include "core/film/aov_display.h"
#include "core/film/denoise.h"  // denoise_aovs
#include "core/compiler/compile.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace inkray {
namespace {

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

// The region's film pixels, rounded outwards.
PixelWindow region_pixels(const RegionRect& region, const Film& film) {
  const int w = film.width(), h = film.height();
  return {int(std::floor(region.x0 * w)), int(std::floor(region.y0 * h)), int(std::ceil(region.x1 * w)),
          int(std::ceil(region.y1 * h))};
}

}  // namespace

ProgressiveRenderer::ProgressiveRenderer(int threads) : session_(threads) {
  worker_ = std::thread([this] { run(); });
}

template <class Change>
void ProgressiveRenderer::request(Pass pass, Change change) {
  {
    std::lock_guard lock(mutex_);
    change(requests_);
  }
  if (pass == Pass::cancelled) session_.cancel();
  wake_.notify_all();
}

ProgressiveRenderer::~ProgressiveRenderer() {
  request(Pass::cancelled, [&](Requests& r) {
    r.stop = true;
    superseded_.store(true);
  });
  worker_.join();
}

uint64_t ProgressiveRenderer::submit(const SceneDesc& scene) {
  uint64_t revision;
  request(Pass::cancelled, [&](Requests& r) {
    r.document = scene;
    revision = r.revision = ++revisions_;
    r.time = std::chrono::steady_clock::now();
    // Under the lock, so it cannot land after the worker took this very document.
    superseded_.store(true);
  });
  return revision;
}

// The pass in flight stops and resumes after the new encoding is published (its finished
// tiles are kept), so an exposure drag shows at once, not a pass later.
void ProgressiveRenderer::set_view(const ViewportView& view) {
  request(Pass::cancelled, [&](Requests& r) {
    r.view = view;
    r.view_changed = true;
  });
}

void ProgressiveRenderer::set_limits(const ViewportLimits& limits) {
  request(Pass::continues, [&](Requests& r) {
    r.limits = limits;
    r.view_changed = true;  // a raised limit lets a finished render continue
  });
}

void ProgressiveRenderer::set_region(const RegionRect& region) {
  request(Pass::cancelled, [&](Requests& r) {
    r.region = region;
    r.region_changed = true;
  });
}

void ProgressiveRenderer::set_paused(bool paused) {
  request(Pass::continues, [&](Requests& r) { r.paused = paused; });
}

bool ProgressiveRenderer::paused() const {
  std::lock_guard lock(mutex_);
  return requests_.paused;
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

bool ProgressiveRenderer::wait_until_idle(std::chrono::steady_clock::time_point deadline) const {
  std::unique_lock lock(mutex_);
  return idle_.wait_until(lock, deadline, [&] { return sleeping_; });
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
  for (;;) {
    const ViewportWork work = schedule_.next(film_state());
    if (work.kind == ViewportWork::Kind::stop) return;
    execute(work);
  }
}

void ProgressiveRenderer::execute(const ViewportWork& work) {
  switch (work.kind) {
    case ViewportWork::Kind::wait:
      return schedule_.taken(take(work.wake_to_render));
    case ViewportWork::Kind::stop:
      return;
    case ViewportWork::Kind::compile:
      return schedule_.compiled(compile());
    case ViewportWork::Kind::restart:
    case ViewportWork::Kind::restart_region:
    case ViewportWork::Kind::refine:
      return restart(work);
    case ViewportWork::Kind::keep_film:
      session_.update_scene(scene_);
      return resolver_.invalidate(ResolveChange::resolve_settings);
    case ViewportWork::Kind::pass:
      return schedule_.passed(render_pass(work));
    case ViewportWork::Kind::publish:
      return schedule_.published(publish_snapshot(work.finished));
  }
}

ViewportRequests ProgressiveRenderer::take(bool wake_to_render) {
  std::unique_lock lock(mutex_);
  Requests& r = requests_;
  const auto has_work = [&] {
    return r.stop || r.document || r.region_changed || r.view_changed || (wake_to_render && !r.paused);
  };
  if (!has_work()) {
    sleeping_ = true;
    idle_.notify_all();
    wake_.wait(lock, has_work);
    sleeping_ = false;
  }
  if (r.stop) return {.stop = true};
  superseded_.store(false);  // under the lock: a submit() after this sets it again
  // The cancels of the requests taken here have done their work; a request after this
  // cancels again, and stops the next pass even before it begins.
  session_.clear_cancel();
  std::optional<SceneDesc> document = std::exchange(r.document, std::nullopt);
  taken_ = r;
  taken_.document = std::move(document);
  r.region_changed = r.view_changed = false;
  const AovSet need = aovs_for(taken_.view);
  return {.document = bool(taken_.document),
          .region_changed = taken_.region_changed,
          .view_changed = taken_.view_changed,
          .paused = taken_.paused,
          .region_empty = taken_.region.empty(),
          .aovs = (need.bits & ~aovs_.bits) != 0 ? FilmAovs::missing
                  : need.bits == aovs_.bits      ? FilmAovs::same
                                                 : FilmAovs::fewer,
          .limits = taken_.limits};
}

CompileOutcome ProgressiveRenderer::compile() {
  // The compiler redoes only what the edit touched (docs/architecture.md, "Stages"):
  // a camera move or a material edit costs no rebuild of the geometry.
  CompileOptions options;
  options.cancel = Cancel(&superseded_);
  options.stand_in_for_broken_graphs = true;   // one bad graph must not blank the viewport
  options.stand_in_for_missing_assets = true;  // nor a file that moved: a stand-in draws it
  CompileResult compiled = session_.pool().run([&] { return compiler_.compile(*taken_.document, options); });
  taken_.document.reset();
  std::lock_guard lock(mutex_);
  if (compiled.cancelled) return CompileOutcome::cancelled;  // the newer document is waiting
  if (!compiled.scene) {
    messages_.insert(messages_.end(), compiled.errors.begin(), compiled.errors.end());
    return CompileOutcome::failed;  // the last good scene stays on screen
  }
  warnings_.insert(warnings_.end(), compiled.warnings.begin(), compiled.warnings.end());
  scene_ = compiled.scene;
  revision_ = taken_.revision;
  revision_time_ = taken_.time;
  return compiled.changes.within({Stage::layout, Stage::resolve, Stage::limits})
             ? CompileOutcome::resolve_only
             : CompileOutcome::new_scene;
}

void ProgressiveRenderer::restart(const ViewportWork& work) {
  resolver_.invalidate(ResolveChange::new_samples);
  if (work.kind == ViewportWork::Kind::refine) {
    session_.set_scene(scene_, aovs_, work.divisor);
    return;
  }
  curve_.clear();
  if (work.kind == ViewportWork::Kind::restart_region) {
    const PixelWindow w = region_pixels(taken_.region, session_.film());
    session_.restart_region(w.x0, w.y0, w.x1, w.y1);
    return;
  }
  aovs_ = aovs_for(taken_.view);
  session_.set_scene(scene_, aovs_, work.divisor);
  session_.set_region(taken_.region.empty() ? PixelWindow{} : region_pixels(taken_.region, session_.film()));
}

std::optional<double> ProgressiveRenderer::render_pass(const ViewportWork& work) {
  resolver_.invalidate(ResolveChange::new_samples);  // the pass adds samples, finished or not
  session_.set_adaptive({work.noise_target, 16});
  const auto start = std::chrono::steady_clock::now();
  if (!session_.render_pass()) return std::nullopt;  // cancelled: a newer request is waiting
  const double ms = ms_since(start);
  const RenderStats& stats = session_.stats();
  if (work.divisor == 1) curve_.push_back({stats.elapsed_seconds, stats.relative_error});
  return ms;
}

ViewportFilm ProgressiveRenderer::film_state() const {
  return {session_.divisor(), session_.stats(), session_.converged()};
}

bool ProgressiveRenderer::publish_snapshot(bool finished) {
  const Film& film = session_.film();
  const ViewportView& view = taken_.view;
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
    const FilmProgress progress{schedule_.accumulation(), session_.stats().spp, finished};
    const RgbImage* image = resolver_.resolve(film, session_.scene(), view.encoding, view.denoise, progress,
                                              session_.pool(), Cancel(&superseded_));
    if (!image) return false;  // cut short: the newer document is waiting
    snap->rgba = encode_display(*image, view.encoding);
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
  snap->accumulation = schedule_.accumulation();
  snap->denoised = view.denoise && view.display == kDisplayFinal;
  if (snap->denoised) {
    snap->denoised_spp = resolver_.denoised_spp();
    snap->denoised_error = resolver_.denoised_error();
  }
  {
    std::lock_guard lock(mutex_);
    snap->revision = revision_;
    snap->submit_to_publish_ms = ms_since(revision_time_);
    latest_ = std::move(snap);
    ++generation_;
  }
  published_.notify_all();
  return true;
}

}  // namespace inkray
