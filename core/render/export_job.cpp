#include "core/render/export_job.h"

#include "core/film/aov_display.h"
#include "core/film/resolve.h"
#include "core/image/image_io.h"
#include "core/render/render_session.h"
#include "core/scene/compile.h"

#include <algorithm>

namespace inkray {

ExportJob::ExportJob(ExportRequest request) {
  thread_ = std::thread([this, r = std::move(request)]() mutable { run(std::move(r)); });
}

ExportJob::~ExportJob() {
  cancel();
  thread_.join();
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
  CompileResult compiled = compile_scene(request.scene);
  if (!compiled.scene) {
    fail(compiled.errors.empty() ? "the scene did not compile" : compiled.errors.front());
    done_.store(true);
    return;
  }
  AovSet aovs;
  for (Aov a : request.aovs) aovs.add(a);
  RenderSession session(request.threads);
  session.set_scene(compiled.scene, aovs);
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
  if (cancelled_.load()) {
    fail("cancelled");
    done_.store(true);
    return;
  }
  std::string error;
  if (!write_image(request.output, resolve_final(session.film(), session.scene(), &session.pool()), &error)) {
    fail(error);
  } else {
    std::lock_guard lock(mutex_);
    written_.push_back(request.output);
  }
  for (Aov a : request.aovs) {
    RgbImage img = session.film().resolve_aov(a);
    const std::filesystem::path file = aov_path(request.output, a);
    if (image_format_of(file) == ImageFormat::png) img = aov_for_display(a, img);
    if (!write_image(file, img, &error)) {
      fail(error);
    } else {
      std::lock_guard lock(mutex_);
      written_.push_back(file);
    }
  }
  progress_.store(1.f);
  done_.store(true);
}

}  // namespace inkray
