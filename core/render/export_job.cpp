#include "core/render/export_job.h"

#include "core/io/output_set.h"
#include "core/render/render_outputs.h"
#include "core/render/render_session.h"
#include "core/compiler/compile.h"

#include <algorithm>

namespace inkray {

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

void ExportJob::run(ExportRequest request) {
  const auto fail = [&](std::string message) {
    std::lock_guard lock(mutex_);
    error_ = std::move(message);
  };
  // Output paths are checked before minutes of rendering, not after.
  std::vector<AovFile> aov_files;
  for (Aov a : request.aovs) aov_files.push_back({a, aov_path(request.output, a)});
  std::vector<PlannedOutput> planned = {{request.output.string(), request.output}};
  for (const AovFile& a : aov_files) planned.push_back({a.file.string(), a.file});
  if (std::string problem = check_outputs(planned); !problem.empty()) {
    fail(std::move(problem));
    done_.store(true);
    return;
  }
  // The session first: the build (strokes, BVH) then stays within the export's
  // threads, leaving the rest to the editor's viewport.
  RenderSession session(request.threads);
  CompileOptions options;
  options.cancel = Cancel(&cancelled_);  // a huge scene's build stops at Cancel too
  CompileResult compiled = session.pool().run([&] { return compile_scene(request.scene, options); });
  if (!compiled.scene) {
    fail(compiled.errors.empty() ? "the scene did not compile" : compiled.errors.front());
    done_.store(true);
    return;
  }
  AovSet aovs;
  for (Aov a : request.aovs) aovs.add(a);
  session.set_scene(compiled.scene, aovs);
  {
    std::lock_guard lock(mutex_);
    session_ = &session;  // so cancel() stops the pass in flight
  }
  const int spp = std::max(request.spp, 1);
  while (int(session.stats().spp) < spp && !cancelled_.load()) {
    if (!session.render_pass()) break;
    float p = float(session.stats().spp) / float(spp);
    if (request.time_seconds > 0.0) {
      p = std::max(p, float(session.stats().elapsed_seconds / request.time_seconds));
      if (session.stats().elapsed_seconds >= request.time_seconds) break;
    }
    progress_.store(std::min(p, 1.f));
  }
  {
    std::lock_guard lock(mutex_);
    session_ = nullptr;
  }
  if (cancelled_.load()) {
    fail("cancelled");
    done_.store(true);
    return;
  }
  // The image and its AOVs land together or not at all: a failed AOV leaves no image.
  std::string error;
  if (write_render_outputs(session, request.output, aov_files, &error, Cancel(&cancelled_)) != OutputsWritten::all) {
    fail(error);
  } else {
    std::lock_guard lock(mutex_);
    for (const auto& p : planned) written_.push_back(p.file);
  }
  progress_.store(1.f);
  done_.store(true);
}

}  // namespace inkray
