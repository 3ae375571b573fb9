#include "ui/autosave.h"

#include "core/scene/json_io.h"

#include <fstream>
#include <sstream>

namespace inkray {

bool Autosave::tick(const SceneDesc& scene, const std::filesystem::path& original, uint64_t revision, bool dirty,
                    std::chrono::steady_clock::time_point now) {
  if (last_ == std::chrono::steady_clock::time_point{}) last_ = now;
  if (!dirty || revision == written_revision_ || now - last_ < interval_) return false;
  last_ = now;
  std::string error;
  if (!write(scene, original, &error)) return false;
  written_revision_ = revision;
  return true;
}

bool Autosave::write(const SceneDesc& scene, const std::filesystem::path& original, std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(file_.parent_path(), ec);
  if (!save_scene(scene, file_, error)) return false;
  // The origin note names the asset folder, so relative paths still resolve on restore.
  std::ofstream out(origin_file(), std::ios::trunc);
  out << original.string() << '\n' << scene.base_dir.string() << '\n';
  return bool(out);
}

void Autosave::clear() {
  std::error_code ec;
  std::filesystem::remove(file_, ec);
  std::filesystem::remove(origin_file(), ec);
  written_revision_ = 0;
}

std::optional<Recovery> Autosave::find(std::vector<std::string>* errors) const {
  std::ifstream in(file_);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  std::string original, base_dir;
  std::ifstream origin(origin_file());
  std::getline(origin, original);
  std::getline(origin, base_dir);
  SceneLoadResult loaded = parse_scene(text.str(), base_dir, file_.string());
  if (!loaded) {
    if (errors) *errors = std::move(loaded.errors);
    return std::nullopt;
  }
  return Recovery{std::move(*loaded.scene), original};
}

}  // namespace inkray
