#include "core/render/export_job.h"

#include "core/compiler/compile.h"
#include "core/film/denoise.h"
#include "core/io/output_set.h"
#include "core/render/render_outputs.h"
#include "core/render/render_session.h"

#include <tbb/info.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

namespace inkray {
namespace {

double seconds_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// Time to the first limit met, from the pass rate so far; -1 before a rate exists.
double eta_seconds(const ExportRequest& request, const RenderStats& s, int spp_target) {
  if (s.spp == 0 || s.elapsed_seconds <= 0.0) return -1.0;
  const double rate = double(s.spp) / s.elapsed_seconds;  // samples per second
  double eta = double(spp_target - int(s.spp)) / rate;
  if (request.time_seconds > 0.0) eta = std::min(eta, request.time_seconds - s.elapsed_seconds);
  if (request.noise_target > 0.0 && s.relative_error > 0.0) {
    // The error of a mean falls as 1/sqrt(samples).
    const double ratio = s.relative_error / request.noise_target;
    eta = std::min(eta, std::max(double(s.spp) * (ratio * ratio - 1.0), 0.0) / rate);
  }
  return std::max(eta, 0.0);
}

float fraction_done(const ExportRequest& request, const RenderStats& s, int spp_target) {
  double f = double(s.spp) / double(spp_target);
  if (request.time_seconds > 0.0) f = std::max(f, s.elapsed_seconds / request.time_seconds);
  if (request.noise_target > 0.0 && s.relative_error > 0.0) {
    const double ratio = request.noise_target / s.relative_error;
    f = std::max(f, ratio * ratio);
  }
  return float(std::clamp(f, 0.0, 1.0));
}

}  // namespace

int export_threads(bool viewport_keeps_rendering) {
  const int hardware = std::max(1, tbb::info::default_concurrency());
  return viewport_keeps_rendering ? std::max(1, hardware - 1) : hardware;
}

std::pair<int, int> export_resolution(const ExportRequest& request) {
  const int sw = std::max(request.scene.render.width, 1), sh = std::max(request.scene.render.height, 1);
  int w = request.width, h = request.height;
  if (w <= 0 && h <= 0) return {sw, sh};
  if (h <= 0) h = int(std::lround(double(w) * sh / sw));
  if (w <= 0) w = int(std::lround(double(h) * sw / sh));
  return {std::clamp(w, 1, 16384), std::clamp(h, 1, 16384)};
}

ExportJob::ExportJob(ExportRequest request) {
  thread_ = std::thread([this, r = std::move(request)]() mutable { run(std::move(r)); });
}

ExportJob::~ExportJob() {
  cancel();
  thread_.join();
}

void ExportJob::cancel() {
  cancelled_.store(true);
  std::lock_guard lock(mutex_);
  if (session_) session_->cancel();
}

ExportProgress ExportJob::progress() const {
  std::lock_guard lock(mutex_);
  ExportProgress p = progress_;
  const bool finished = p.phase == ExportPhase::finished;
  p.elapsed_seconds = seconds_between(start_, finished ? finished_ : std::chrono::steady_clock::now());
  return p;
}

std::string ExportJob::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

std::vector<std::filesystem::path> ExportJob::written() const {
  std::lock_guard lock(mutex_);
  return written_;
}

std::filesystem::path ExportJob::aov_path(const std::filesystem::path& output, Aov aov) {
  std::filesystem::path p = output;
  p.replace_filename(output.stem().string() + "_" + std::string(kAovNames[size_t(aov)]) +
                     output.extension().string());
  return p;
}

void ExportJob::after_pass(const ExportRequest& request, const RenderSession& session) {
  const RenderStats& s = session.stats();
  std::lock_guard lock(mutex_);
  progress_.spp = s.spp;
  progress_.render_seconds = s.elapsed_seconds;
  progress_.relative_error = s.relative_error;
  progress_.eta_seconds = eta_seconds(request, s, int(progress_.spp_target));
  // The noise share can fall back when the estimate wobbles; the bar does not.
  progress_.fraction = std::max(progress_.fraction, fraction_done(request, s, int(progress_.spp_target)));
}

void ExportJob::finish(std::string error) {
  std::lock_guard lock(mutex_);
  if (error.empty()) progress_.fraction = 1.f;
  error_ = std::move(error);
  progress_.phase = ExportPhase::finished;
  progress_.eta_seconds = 0.0;
  finished_ = std::chrono::steady_clock::now();
  done_.store(true);
}

void ExportJob::run(ExportRequest request) {
  // Output paths are checked before minutes of rendering, not after.
  std::vector<AovFile> aov_files;
  for (Aov a : request.aovs) aov_files.push_back({a, aov_path(request.output, a)});
  std::vector<PlannedOutput> planned = {{request.output.string(), request.output}};
  if (request.denoise)
    planned.push_back({raw_image_path(request.output).string(), raw_image_path(request.output)});
  for (const AovFile& a : aov_files) planned.push_back({a.file.string(), a.file});
  LineFiles line_files;
  if (request.lines_svg) line_files.svg = std::filesystem::path(request.output).replace_extension(".svg");
  if (request.lines_pdf) line_files.pdf = std::filesystem::path(request.output).replace_extension(".pdf");
  for (const auto& file : {line_files.svg, line_files.pdf})
    if (!file.empty()) planned.push_back({file.string(), file});
  if (std::string problem = check_outputs(planned); !problem.empty()) return finish(std::move(problem));
  std::tie(request.scene.render.width, request.scene.render.height) = export_resolution(request);
  const int spp = std::max(request.spp, 1);
  // The session first: the build (strokes, BVH) then stays within the export's
  // threads, leaving the rest to the editor's viewport.
  RenderSession session(request.threads);
  {
    std::lock_guard lock(mutex_);
    progress_.spp_target = uint32_t(spp);
    progress_.width = request.scene.render.width;
    progress_.height = request.scene.render.height;
    progress_.threads = session.threads();
  }
  CompileOptions options;
  options.cancel = Cancel(&cancelled_);  // a huge scene's build stops at Cancel too
  CompileResult compiled = session.pool().run([&] { return compile_scene(request.scene, options); });
  if (cancelled_.load()) return finish("cancelled");
  if (!compiled.scene)
    return finish(compiled.errors.empty() ? "the scene did not compile" : compiled.errors.front());
  AovSet aovs;
  for (Aov a : request.aovs) aovs.add(a);
  if (request.denoise) aovs.bits |= denoise_aovs().bits;
  session.set_scene(compiled.scene, aovs);
  session.set_adaptive({request.noise_target, 16});
  {
    std::lock_guard lock(mutex_);
    session_ = &session;  // so cancel() stops the pass in flight
    progress_.phase = ExportPhase::rendering;
  }
  while (!cancelled_.load() && session.render_pass()) {
    after_pass(request, session);
    const RenderStats& s = session.stats();
    if (int(s.spp) >= spp || noise_target_reached(s, request.noise_target) || session.converged()) break;
    if (request.time_seconds > 0.0 && s.elapsed_seconds >= request.time_seconds) break;
  }
  {
    std::lock_guard lock(mutex_);
    session_ = nullptr;
    progress_.phase = ExportPhase::writing;
  }
  if (cancelled_.load()) return finish("cancelled");
  // The image and its AOVs land together or not at all: a failed AOV leaves no image.
  std::optional<Denoised> denoised;
  if (request.denoise) {
    denoised = denoise(session.film(), &session.pool(), Cancel(&cancelled_));
    if (cancelled_.load()) return finish("cancelled");
    std::lock_guard lock(mutex_);
    progress_.denoised_error = denoised->relative_error;
  }
  std::string error;
  if (write_render_outputs(session, request.output, aov_files, &error, Cancel(&cancelled_), {},
                           denoised ? &denoised->image : nullptr, line_files) != OutputsWritten::all)
    return finish(cancelled_.load() ? "cancelled" : error);
  {
    std::lock_guard lock(mutex_);
    for (const auto& p : planned) written_.push_back(p.file);
  }
  finish({});
}

}  // namespace inkray
