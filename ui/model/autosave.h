// Crash recovery: every few minutes an unsaved document is written (atomically)
// to a recovery file, with a note of the file it came from. A clean exit or a
// save removes it, so a recovery file found at start-up means a crash.
#pragma once

#include "core/document/desc.h"

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace inkray {

struct Recovery {
  SceneDesc scene;
  std::filesystem::path original;  // the document's file; empty if it was never saved
};

class Autosave {
 public:
  Autosave(std::filesystem::path recovery_file, std::chrono::seconds interval)
      : file_(std::move(recovery_file)), interval_(interval) {}

  // Writes when the interval has passed and the document changed since the last write.
  // Returns true when it wrote.
  bool tick(const SceneDesc& scene, const std::filesystem::path& original, uint64_t revision, bool dirty,
            std::chrono::steady_clock::time_point now);
  bool write(const SceneDesc& scene, const std::filesystem::path& original, std::string* error);
  void clear();  // after a save or a clean exit

  // A recovery file left by a crash, if any and readable.
  std::optional<Recovery> find(std::vector<std::string>* errors = nullptr) const;
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path origin_file() const { return file_.string() + ".origin"; }

  std::filesystem::path file_;
  std::chrono::seconds interval_;
  std::chrono::steady_clock::time_point last_{};
  uint64_t written_revision_ = 0;
};

}  // namespace inkray
