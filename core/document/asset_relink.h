// The files a document refers to, whether each is on disk, and "Locate...": pointing
// a missing file's references at a file the user found, and with it every other
// missing file of the same folder found beside it. Pure functions over a SceneDesc
// (the editor's missing files panel applies them as one edit).
#pragma once

#include "core/document/asset_paths.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace inkray {

// One path field in use that names a file.
struct AssetReference {
  AssetSite site;
  std::string written;  // as the document holds it
  // Against scene.base_dir (the working directory when empty), absolute, normalised.
  std::filesystem::path resolved;
  bool exists = false;  // a regular file is there
};

// Every path field in use with a path (empty ones name nothing yet), in document
// order, each checked on disk (one stat each).
std::vector<AssetReference> list_asset_references(const SceneDesc& scene);

// A file that is not there, with everything that uses it.
struct MissingAsset {
  std::string written;  // as the first reference writes it
  std::filesystem::path resolved;
  FileType type = FileType::none;
  std::vector<std::string> users;  // AssetSite::user of each reference, in document order, each once
};
// The missing files of list_asset_references, one entry per file, in order of first use.
std::vector<MissingAsset> missing_assets(const SceneDesc& scene);
std::vector<MissingAsset> missing_assets(const std::vector<AssetReference>& references);
// "material \"a\", object \"b\"": users as a message names them.
std::string users_text(const std::vector<std::string>& users);
// `file not found: tex/a.png (resolved to /scenes/tex/a.png), used by material "a", object "b"`
std::string describe(const MissingAsset& missing);

// Points every reference to the file `missing_path` (as written; the same file
// written another way counts too) at `chosen_file`, and every other missing
// reference whose file was in the same folder at the chosen file's folder, when a
// file of its name is there. New paths are relative to the scene's folder when
// they have a relative form, with '/' separators. Returns how many fields changed.
size_t relink(SceneDesc& scene, const std::string& missing_path, const std::filesystem::path& chosen_file);

}  // namespace inkray
