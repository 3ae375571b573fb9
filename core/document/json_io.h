// Scene files: loading (with validation that reports every problem at once),
// writing and atomic saving of the SceneDesc document. The format is described
// in docs/scene-format.md.
#pragma once

#include "core/base/cancel.h"
#include "core/document/desc.h"
#include "core/document/error_log.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// Scene files are small (meshes live in OBJ files); this bounds what a hostile one costs.
inline constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t(64) << 20;

struct SceneLoadResult {
  std::optional<SceneDesc> scene;     // set when there were no errors
  std::vector<std::string> errors;    // each a full line: "<file>: <json path>: <message>"
  std::vector<std::string> warnings;  // read for editing: what stops it rendering (error_log.h)
  bool cancelled = false;
  explicit operator bool() const { return scene.has_value(); }
};

// Reads and validates a scene file; scene->base_dir is the file's (absolute) folder.
// Never throws: every problem, including an unreadable file, becomes an error line.
// Read for editing, a whole document opens even when it cannot render yet.
// Reading a scene of hundreds of thousands of objects takes seconds: `cancel` stops
// it, with `cancelled` set.
SceneLoadResult load_scene(const std::filesystem::path& file, ReadFor purpose = ReadFor::rendering,
                           const Cancel& cancel = {});

// The same for text already in memory. Asset paths are checked relative to base_dir,
// and file_label starts every error line.
SceneLoadResult parse_scene(std::string_view json_text, const std::filesystem::path& base_dir,
                            std::string_view file_label, ReadFor purpose = ReadFor::rendering,
                            const Cancel& cancel = {});

// Every field, defaults included. nlohmann::json sorts keys; scene_to_string keeps
// the documented order (format, version, camera, render, environment, materials, objects, lights).
nlohmann::json scene_to_json(const SceneDesc& scene);
std::string scene_to_string(const SceneDesc& scene);  // 2-space indent, ends with a newline

// Atomic save (core/io/atomic_file.h): writes a temporary in the same folder, flushes it
// to disk and renames it over the target, so a crash never leaves a half-written scene;
// a symbolic link stays and the file it names is replaced. Temporaries that killed saves
// left beside the file are removed first. Returns false and sets *error (naming the file
// and the cause) on failure, leaving no temporary behind.
bool save_scene(const SceneDesc& scene, const std::filesystem::path& file, std::string* error);

// Save As: relative asset paths, which resolve against scene.base_dir (the working
// directory when it is empty), are rewritten relative to the file's folder, then the
// scene is saved atomically. The editor and `inkray-render --write-scene` both use it.
bool save_scene_as(const SceneDesc& scene, const std::filesystem::path& file, std::string* error);

}  // namespace inkray
