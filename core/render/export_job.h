// A final render of a document in the background: checks the output paths, compiles
// it, renders to its sample or time limit on its own session, and writes the image
// (PNG, PFM or EXR by extension) and any AOVs beside it, all of them or none
// (core/io/output_set.h). The caller polls progress().
#pragma once

#include "core/film/film.h"
#include "core/document/desc.h"

#include <atomic>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace inkray {

class RenderSession;

struct ExportRequest {
  SceneDesc scene;
  std::filesystem::path output;
  int spp = 256;
  double time_seconds = 0.0;  // 0: none
  std::vector<Aov> aovs;      // written as "<stem>_<aov><ext>"
  int threads = 0;
};

class ExportJob {
 public:
  explicit ExportJob(ExportRequest request);
  ~ExportJob();  // cancels and joins
  ExportJob(const ExportJob&) = delete;
  ExportJob& operator=(const ExportJob&) = delete;

  float progress() const { return progress_.load(); }  // 0..1
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

  std::atomic<float> progress_{0.f};
  std::atomic<bool> done_{false}, cancelled_{false};
  mutable std::mutex mutex_;
  std::string error_;
  std::vector<std::filesystem::path> written_;
  RenderSession* session_ = nullptr;  // while rendering, under mutex_
  std::thread thread_;
};

}  // namespace inkray
