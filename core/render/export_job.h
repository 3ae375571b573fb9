// A final render of a document in the background: checks the output paths, compiles
// it, renders on its own session until a sample, time or noise limit, and writes the
// image (PNG, PFM or EXR by extension) and any AOVs beside it, all of them or none
// (core/io/output_set.h). The caller polls progress(), which never waits for a pass.
#pragma once

#include "core/document/desc.h"
#include "core/film/film.h"

#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace inkray {

class RenderSession;

struct ExportRequest {
  SceneDesc scene;
  std::filesystem::path output;
  int spp = 256;              // at least 1: the sample cap even with a time or noise limit
  double time_seconds = 0.0;  // 0: none
  // Stop when the estimated relative error falls below; 0: none. Tiles below it stop
  // taking samples before that (adaptive sampling, core/render/adaptive_sampling.h).
  double noise_target = 0.0;
  bool denoise = false;   // the image is denoised; the raw one is written as <stem>_raw<ext>
  std::vector<Aov> aovs;  // written as "<stem>_<aov><ext>"
  // The lines as vectors (render_outputs.h, LineFiles), written as "<stem>.svg" / "<stem>.pdf".
  bool lines_svg = false, lines_pdf = false;
  int threads = 0;  // 0: every hardware thread (export_threads())
  // The export's resolution, leaving the document alone; 0 keeps the scene's. With one
  // side set, the other follows the scene's aspect.
  int width = 0, height = 0;
};

// Threads for an export: every hardware thread, or all but one when the editor's
// viewport keeps rendering beside it.
int export_threads(bool viewport_keeps_rendering);

// The resolution an export renders at (request.width/height applied to the scene's).
std::pair<int, int> export_resolution(const ExportRequest& request);

enum class ExportPhase { compiling, rendering, writing, finished };

// What the UI shows of a running export. Every figure only grows while rendering,
// except the error estimate and the time left.
struct ExportProgress {
  ExportPhase phase = ExportPhase::compiling;
  uint32_t spp = 0, spp_target = 0;
  double elapsed_seconds = 0.0;  // since the job started, compiling included
  double render_seconds = 0.0;   // in passes, at the last pass's end
  // Until the first limit is met: from the pass rate for samples and the noise target
  // (error falls as 1/sqrt(spp)), the time left for a time limit. Negative: unknown yet.
  double eta_seconds = -1.0;
  double relative_error = 0.0;  // estimated from the half-buffers; 0 before two passes
  double denoised_error = 0.0;  // the denoised image's estimate, once it is denoised
  float fraction = 0.f;         // 0..1, the furthest limit's share reached
  int width = 0, height = 0, threads = 0;
};

class ExportJob {
 public:
  explicit ExportJob(ExportRequest request);
  ~ExportJob();  // cancels and joins
  ExportJob(const ExportJob&) = delete;
  ExportJob& operator=(const ExportJob&) = delete;

  ExportProgress progress() const;
  bool done() const { return done_.load(); }
  // Stops the build, the pass in flight (one pass of a deep scene can take a minute)
  // and the painterly filter; nothing is written.
  void cancel();
  // After done(): empty on success, else why it failed. Also lists the files written.
  std::string error() const;
  std::vector<std::filesystem::path> written() const;

  static std::filesystem::path aov_path(const std::filesystem::path& output, Aov aov);

 private:
  void run(ExportRequest request);
  void after_pass(const ExportRequest& request, const RenderSession& session);
  void finish(std::string error);

  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::atomic<bool> done_{false}, cancelled_{false};
  // Held only to copy a few numbers in or out, never across a pass, so a UI thread
  // polling progress() does not wait for the renderer.
  mutable std::mutex mutex_;
  ExportProgress progress_;
  std::chrono::steady_clock::time_point finished_;
  std::string error_;
  std::vector<std::filesystem::path> written_;
  RenderSession* session_ = nullptr;  // while rendering, under mutex_
  std::thread thread_;
};

}  // namespace inkray
