#include "ui/model/export_queue.h"

#include "core/image/image_io.h"
#include "core/render/render_outputs.h"

#include <algorithm>

namespace inkray {
namespace {

namespace fs = std::filesystem;

std::string format_name(ImageFormat format) {
  switch (format) {
    case ImageFormat::png:
      return "PNG, 8-bit sRGB";
    case ImageFormat::exr:
      return "OpenEXR, 32-bit float, linear";
    case ImageFormat::pfm:
      return "PFM, 32-bit float, linear";
    case ImageFormat::unknown:
      break;
  }
  return {};
}

}  // namespace

fs::path default_export_path(const fs::path& scene_file) {
  std::error_code ec;
  if (scene_file.empty()) return fs::absolute("render.png", ec);
  fs::path out = scene_file;
  out.replace_extension(".png");
  return fs::absolute(out, ec);
}

ExportFormCheck check_export_form(const ExportForm& form, const fs::path& scene_file) {
  ExportFormCheck c;
  if (form.output.empty()) {
    c.error = "choose an output file";
    return c;
  }
  std::error_code ec;
  fs::path out = form.output;
  if (out.is_relative()) out = (scene_file.empty() ? fs::current_path(ec) : scene_file.parent_path()) / out;
  c.output = fs::absolute(out, ec).lexically_normal();
  c.format = format_name(image_format_of(c.output));
  const std::string name = c.output.filename().string();
  if (c.format.empty()) {
    c.error = name + ": the extension must be .png, .exr or .pfm";
    return c;
  }
  if (!fs::is_directory(c.output.parent_path(), ec)) {
    c.error = c.output.parent_path().string() + ": no such folder";
    return c;
  }
  c.files = {c.output};
  if (form.denoise) c.files.push_back(raw_image_path(c.output));
  for (size_t i = 0; i < form.aovs.size() && i < kAovNames.size(); ++i)
    if (form.aovs[i]) c.files.push_back(ExportJob::aov_path(c.output, Aov(i)));
  for (const fs::path& f : c.files) {
    if (fs::is_directory(f, ec)) {
      c.error = f.string() + " is a folder";
      return c;
    }
    if (fs::exists(f, ec)) c.existing.push_back(f);
  }
  if (form.spp < 1)
    c.error = "samples: at least 1";
  else if (form.time_seconds < 0.f)
    c.error = "time limit: 0 (none) or more seconds";
  else if (form.noise_target < 0.f || form.noise_target >= 1.f)
    c.error = "noise target: 0 (none) or a relative error below 100%";
  else if (form.width < 0 || form.width > 16384 || form.height < 0 || form.height > 16384)
    c.error = "resolution: 1 to 16384 pixels a side";
  return c;
}

ExportRequest make_export_request(const ExportForm& form, const ExportFormCheck& check, SceneDesc scene) {
  ExportRequest r;
  r.scene = std::move(scene);
  r.output = check.output;
  r.spp = form.spp;
  r.time_seconds = form.time_seconds;
  r.noise_target = form.noise_target;
  r.denoise = form.denoise;
  r.lines_svg = form.lines_svg;
  r.lines_pdf = form.lines_pdf;
  for (size_t i = 0; i < form.aovs.size() && i < kAovNames.size(); ++i)
    if (form.aovs[i]) r.aovs.push_back(Aov(i));
  r.threads = export_threads(form.keep_viewport);
  r.width = form.width;
  r.height = form.height;
  return r;
}

uint64_t ExportQueue::add(ExportRequest request, bool keep_viewport) {
  ExportEntry e;
  e.id = next_id_++;
  e.request = std::move(request);
  e.keep_viewport = keep_viewport;
  entries_.push_back(std::move(e));
  return entries_.back().id;
}

std::vector<uint64_t> ExportQueue::poll() {
  std::vector<uint64_t> finished;
  for (ExportEntry& e : entries_) {
    if (e.state != ExportState::running) continue;
    // done() first: a job seen done has published its final figures, which a progress
    // read before it could miss if the job finished in between.
    const bool done = e.job->done();
    e.progress = e.job->progress();
    if (!done) return finished;  // one at a time: the rest waits
    e.error = e.job->error();
    e.written = e.job->written();
    e.state = e.error.empty()          ? ExportState::done
              : e.error == "cancelled" ? ExportState::cancelled
                                       : ExportState::failed;
    e.job.reset();
    finished.push_back(e.id);
  }
  const auto next = std::find_if(entries_.begin(), entries_.end(),
                                 [](const ExportEntry& e) { return e.state == ExportState::queued; });
  if (next != entries_.end()) {
    next->state = ExportState::running;
    next->job = std::make_unique<ExportJob>(next->request);
    next->progress = next->job->progress();
  }
  return finished;
}

void ExportQueue::cancel(uint64_t id) {
  for (ExportEntry& e : entries_) {
    if (e.id != id) continue;
    if (e.state == ExportState::queued) {
      e.state = ExportState::cancelled;
      e.error = "cancelled";
    } else if (e.state == ExportState::running) {
      e.job->cancel();  // the next poll() collects it
    }
  }
}

void ExportQueue::cancel_all() {
  for (const ExportEntry& e : entries_) cancel(e.id);
}

void ExportQueue::clear_finished() {
  std::erase_if(entries_, [](const ExportEntry& e) {
    return e.state != ExportState::queued && e.state != ExportState::running;
  });
}

const ExportEntry* ExportQueue::find(uint64_t id) const {
  for (const ExportEntry& e : entries_)
    if (e.id == id) return &e;
  return nullptr;
}

const ExportEntry* ExportQueue::running() const {
  for (const ExportEntry& e : entries_)
    if (e.state == ExportState::running) return &e;
  return nullptr;
}

int ExportQueue::queued() const {
  return int(std::count_if(entries_.begin(), entries_.end(),
                           [](const ExportEntry& e) { return e.state == ExportState::queued; }));
}

bool ExportQueue::viewport_paused() const {
  const ExportEntry* e = running();
  return e && !e->keep_viewport;
}

}  // namespace inkray
