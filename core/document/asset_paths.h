// The document's file paths: every ParamKind::path field found through the
// parameter lists (meshes, textures, toon ramps, brush images, and whatever type
// declares a path next), and moving a scene file to another folder, which must
// rewrite the relative ones or the moved scene no longer finds its files.
#pragma once

#include "core/document/desc.h"

#include <filesystem>
#include <functional>
#include <string>

namespace inkray {

// Where a path field sits in the document.
struct AssetSite {
  std::string at;    // JSON path of the key: "objects[2].shape.path"
  std::string user;  // who holds it, for people: object "knot", material "tiles", the environment
  FileType type = FileType::none;  // what it names (Param::file_type)
  // False for a brush_image kept while the emitter paints with another brush:
  // nothing reads it, so nothing is missing when it is.
  bool in_use = true;
};

// Calls f with every path field of the scene (empty ones included), in document
// order: the environment, materials (colour inputs and graph nodes), objects,
// lights, stroke emitters.
void for_each_asset_path(SceneDesc& scene, const std::function<void(const AssetSite&, std::string& path)>& f);
// The same walk over a scene it only reads.
void for_each_asset_path(const SceneDesc& scene,
                         const std::function<void(const AssetSite&, const std::string& path)>& f);

// Rewrites every relative ParamKind::path field so that, resolved against
// `to_dir`, it names the file it named resolved against `from_dir`. Absolute
// and empty paths are kept; a path with no relative form (another drive) becomes
// absolute. Separators are written as '/', which every platform reads.
void rebase_asset_paths(SceneDesc& scene, const std::filesystem::path& from_dir,
                        const std::filesystem::path& to_dir);

}  // namespace inkray
