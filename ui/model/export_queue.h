// The editor's exports without a window: what the export dialog asks for, checked
// (format by extension, missing folders, files it would replace), and the queue that
// runs the exports one after another, each an ExportJob, exposing their state for
// the panels to draw.
#pragma once

#include "core/render/export_job.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace inkray {

// The dialog's fields, as the user left them.
struct ExportForm {
  std::string output;  // a relative path is taken from the scene's folder
  std::vector<bool> aovs = std::vector<bool>(kAovNames.size(), false);
  int spp = 256;
  float time_seconds = 0.f;                   // 0: none
  float noise_target = 0.f;                   // relative error (0.01 is 1%); 0: none
  bool denoise = false;                       // the image denoised, the raw one beside it
  bool lines_svg = false, lines_pdf = false;  // the lines as vectors beside it, <stem>.svg / .pdf
  int width = 0, height = 0;                  // 0: the scene's
  bool keep_viewport = false;                 // the viewport keeps one thread instead of pausing
};

struct ExportFormCheck {
  std::filesystem::path output;                 // absolute
  std::vector<std::filesystem::path> files;     // the image, its raw one when denoised, then its AOVs
  std::vector<std::filesystem::path> existing;  // of files, those Start would replace
  std::string format;                           // "PNG, 8-bit sRGB", ...; empty for an unknown extension
  std::string error;                            // why Start cannot run; empty when it can
};

// `scene_file` is the document's file, empty while it is unsaved.
ExportFormCheck check_export_form(const ExportForm& form, const std::filesystem::path& scene_file);
// The scene's folder and stem with ".png"; "render.png" in the working folder while unsaved.
std::filesystem::path default_export_path(const std::filesystem::path& scene_file);
// The request for a form that passed its check.
ExportRequest make_export_request(const ExportForm& form, const ExportFormCheck& check, SceneDesc scene);

enum class ExportState { queued, running, done, failed, cancelled };
inline constexpr std::array<const char*, 5> kExportStateNames = {"queued", "running", "done", "failed",
                                                                 "cancelled"};

struct ExportEntry {
  uint64_t id = 0;
  ExportRequest request;
  bool keep_viewport = false;
  ExportState state = ExportState::queued;
  ExportProgress progress;  // as of the last poll(); final once finished
  std::string error;
  std::vector<std::filesystem::path> written;
  std::unique_ptr<ExportJob> job;  // while running
};

class ExportQueue {
 public:
  // Queues an export; it starts at a poll() once the ones before it have finished.
  uint64_t add(ExportRequest request, bool keep_viewport);
  // Reads the running export's figures, collects it when done and starts the next.
  // Returns the ids of the exports that finished during this call.
  std::vector<uint64_t> poll();
  // A queued export never runs; a running one stops at once and writes nothing.
  void cancel(uint64_t id);
  void cancel_all();
  void clear_finished();

  const std::vector<ExportEntry>& entries() const { return entries_; }
  const ExportEntry* find(uint64_t id) const;
  const ExportEntry* running() const;
  int queued() const;
  // The running export asked for the viewport's threads.
  bool viewport_paused() const;

 private:
  std::vector<ExportEntry> entries_;
  uint64_t next_id_ = 1;
};

}  // namespace inkray
