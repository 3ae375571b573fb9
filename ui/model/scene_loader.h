// Opening a scene file off the UI thread: a scene of hundreds of thousands of objects
// takes seconds to read, and meanwhile the editor keeps drawing, shows how long it has
// been and can cancel (docs/architecture.md, "Long work and cancellation").
#pragma once

#include "core/document/json_io.h"

#include <atomic>
#include <chrono>
#include <filesystem>
#include <optional>
#include <thread>

namespace inkray {

class SceneLoader {
 public:
  SceneLoader() = default;
  ~SceneLoader();  // cancels and waits
  SceneLoader(const SceneLoader&) = delete;
  SceneLoader& operator=(const SceneLoader&) = delete;

  // Reads the file for editing on a worker thread; a read in flight is cancelled first.
  void start(std::filesystem::path file);
  void cancel() { cancel_.store(true); }
  bool busy() const { return worker_.joinable() && !finished_.load(); }
  const std::filesystem::path& file() const { return file_; }
  double seconds() const;

  // The finished read, once (result.cancelled when it was cancelled); nullopt while
  // reading or when there is nothing new.
  std::optional<SceneLoadResult> take();

 private:
  void join();

  std::filesystem::path file_;
  std::chrono::steady_clock::time_point started_;
  std::atomic<bool> cancel_{false}, finished_{false};
  std::optional<SceneLoadResult> result_;  // written by the worker before finished_
  std::thread worker_;
};

}  // namespace inkray
