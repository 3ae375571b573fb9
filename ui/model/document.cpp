#include "ui/model/document.h"

#include "core/document/asset_paths.h"
#include "core/document/asset_relink.h"
#include "core/document/animation_edit.h"
#include "core/document/json_io.h"

#include <algorithm>
#include <utility>

namespace inkray {
namespace {

// The reader's warning for a file in use that is not there ("<file>: <json path>:
// file not found: ...") gives way to one line per file naming who uses it.
void separate_missing_files(const SceneDesc& scene, std::vector<std::string>& warnings,
                            std::vector<std::string>& missing_files) {
  const std::vector<AssetReference> references = list_asset_references(scene);
  for (const AssetReference& r : references) {
    if (r.exists) continue;
    const std::string at = ": " + r.site.at + ": ";
    std::erase_if(warnings, [&](const std::string& w) { return w.find(at) != std::string::npos; });
  }
  for (const MissingAsset& m : missing_assets(references)) missing_files.push_back(describe(m));
}

// Undo, redo and discarding a step restore documents as they were, but not the frame they
// were on. `restore` takes one step of the history back or forth, false when there is none.
template <class Restore>
bool restore_keeping_frame(SceneDesc& scene, uint64_t& revision, Restore restore) {
  const float frame = scene.render.frame;
  if (!restore()) return false;
  scene.render.frame = frame;
  ++revision;
  return true;
}

}  // namespace

Document::Document() { reset(default_scene()); }

SceneDesc Document::default_scene() {
  SceneDesc s;
  s.camera.look_from = Point3(0.f, 1.5f, 6.f);
  s.camera.look_at = Point3(0.f, 0.7f, 0.f);
  s.render.width = 960;
  s.render.height = 540;
  s.environment = GradientEnvironmentDesc{};
  s.materials.push_back({"ground", DiffuseDesc{Color(0.6f)}, {}});
  s.materials.push_back({"red", DiffuseDesc{Color(0.7f, 0.15f, 0.1f)}, {}});
  ObjectDesc ground;
  ground.name = "ground";
  ground.shape = QuadDesc{Point3(-5.f, 0.f, 5.f), Vec3(10.f, 0.f, 0.f), Vec3(0.f, 0.f, -10.f)};
  ground.material = "ground";
  s.objects.push_back(ground);
  ObjectDesc sphere;
  sphere.name = "sphere";
  sphere.shape = SphereDesc{Point3(0.f, 1.f, 0.f), 1.f};
  sphere.material = "red";
  s.objects.push_back(sphere);
  LightDesc sun;
  sun.name = "sun";
  sun.data = DirectionalLightDesc{Vec3(-0.4f, -1.f, -0.3f), Color(1.f), 3.f};
  s.lights.push_back(sun);
  return s;
}

std::string Document::display_name() const {
  std::string name = file_.empty() ? std::string("untitled") : file_.filename().string();
  if (dirty()) name += '*';
  return name;
}

void Document::edit(SceneDesc after, std::string label, std::string merge_key, Selection selection) {
  if (after.render.frame != scene_.render.frame) {
    SceneDesc same_frame = after;
    same_frame.render.frame = scene_.render.frame;
    if (same_frame == scene_) return set_frame(after.render.frame);
  }
  if (!scene_.animation.empty()) {
    drop_vanished_tracks(scene_, after);
    key_edited(scene_, after);
  }
  history_.apply(scene_, std::move(after), std::move(label), std::move(merge_key), selection);
  ++revision_;
}

void Document::set_frame(double frame) {
  if (double(scene_.render.frame) == frame) return;
  scene_.render.frame = float(frame);
  ++revision_;
}

bool Document::undo(Selection* selection) {
  return restore_keeping_frame(scene_, revision_, [&] { return history_.undo(scene_, selection); });
}

bool Document::discard_newest() {
  return restore_keeping_frame(scene_, revision_, [&] { return history_.discard_newest(scene_); });
}

bool Document::redo(Selection* selection) {
  return restore_keeping_frame(scene_, revision_, [&] { return history_.redo(scene_, selection); });
}

bool Document::open(const std::filesystem::path& file, std::vector<std::string>* errors,
                    std::vector<std::string>* warnings, std::vector<std::string>* missing_files) {
  return open_loaded(load_scene(file, ReadFor::editing), file, errors, warnings, missing_files);
}

bool Document::open_loaded(SceneLoadResult loaded, const std::filesystem::path& file,
                           std::vector<std::string>* errors, std::vector<std::string>* warnings,
                           std::vector<std::string>* missing_files) {
  if (loaded && missing_files) {
    missing_files->clear();
    separate_missing_files(*loaded.scene, loaded.warnings, *missing_files);
  }
  if (warnings) *warnings = std::move(loaded.warnings);
  if (!loaded) {
    if (errors) *errors = std::move(loaded.errors);
    return false;
  }
  reset(std::move(*loaded.scene), std::filesystem::absolute(file));
  return true;
}

void Document::reset(SceneDesc scene, std::filesystem::path file, bool dirty) {
  scene_ = std::move(scene);
  file_ = std::move(file);
  history_.clear();
  saved_state_ = dirty ? ~uint64_t(0) : history_.state_id();
  ++revision_;
}

bool Document::save(std::string* error) {
  if (file_.empty()) {
    if (error) *error = "the document has no file yet: use Save As";
    return false;
  }
  return save_as(file_, error);
}

bool Document::save_as(const std::filesystem::path& file, std::string* error) {
  const std::filesystem::path absolute = std::filesystem::absolute(file);
  if (!save_scene_as(scene_, absolute, error)) return false;
  if (scene_.base_dir.empty()) {
    // Relative paths of a never-saved document resolved against the working directory;
    // from now on they resolve against the file's folder, as written.
    rebase_asset_paths(scene_, std::filesystem::current_path(), absolute.parent_path());
    scene_.base_dir = absolute.parent_path();
  }
  // Otherwise the document keeps resolving against its base_dir (paths the editor
  // writes are relative to it); only the file got paths relative to its folder.
  file_ = absolute;
  saved_state_ = history_.state_id();
  return true;
}

}  // namespace inkray
