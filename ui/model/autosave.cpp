// The editor's crash-recovery file and its origin note, both replaced atomically.
#include "ui/model/autosave.h"

#include "core/io/atomic_file.h"
#include "core/document/json_io.h"

#include <fstream>
#include <sstream>

namespace inkray {

bool Autosave::tick(const SceneDesc& scene, const std::filesystem::path& original, uint64_t revision,
                    bool dirty, std::chrono::steady_clock::time_point now) {
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
  // Replaced atomically too: a truncated note would restore with the wrong asset folder.
  remove_stale_temporaries(origin_file());
  return write_file_atomically(origin_file(), original.string() + '\n' + scene.base_dir.string() + '\n',
                               error);
}

void Autosave::clear() {
  std::error_code ec;
  std::filesystem::remove(file_, ec);
  std::filesystem::remove(origin_file(), ec);
  written_revision_ = 0;
}

std::optional<Recovery> Autosave::find(std::vector<std::string>* errors) const {
  // At start-up no write of ours is running, so whatever a killed one left can go.
  remove_stale_temporaries(file_);
  remove_stale_temporaries(origin_file());
  std::ifstream in(file_);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  std::string original, base_dir;
  std::ifstream origin(origin_file());
  std::getline(origin, original);
  std::getline(origin, base_dir);
  // Whatever the editor held is recovered, even a document that cannot render yet.
  SceneLoadResult loaded = parse_scene(text.str(), base_dir, file_.string(), ReadFor::editing);
  if (!loaded) {
    if (errors) *errors = std::move(loaded.errors);
    return std::nullopt;
  }
  return Recovery{std::move(*loaded.scene), original};
}

}  // namespace inkray
