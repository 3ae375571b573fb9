#include "ui/model/scene_loader.h"

#include <utility>

namespace inkray {

SceneLoader::~SceneLoader() {
  cancel();
  join();
}

void SceneLoader::join() {
  if (worker_.joinable()) worker_.join();
}

void SceneLoader::start(std::filesystem::path file) {
  cancel();
  join();
  result_.reset();
  cancel_.store(false);
  finished_.store(false);
  file_ = std::move(file);
  started_ = std::chrono::steady_clock::now();
  worker_ = std::thread([this, file = file_] {
    result_ = load_scene(file, ReadFor::editing, Cancel(&cancel_));
    finished_.store(true, std::memory_order_release);
  });
}

double SceneLoader::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

std::optional<SceneLoadResult> SceneLoader::take() {
  if (!worker_.joinable() || !finished_.load(std::memory_order_acquire)) return std::nullopt;
  join();
  return std::exchange(result_, std::nullopt);
}

}  // namespace inkray
