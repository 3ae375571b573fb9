// Checks that no single value can make: unique names, material references, asset
// files that exist, the image size. Independent of JSON, so the editor can run them
// on a document it has changed as well as the reader on a file it has read.
#pragma once

#include "core/scene/desc.h"
#include "core/scene/error_log.h"

#include <filesystem>

namespace inkray {

// The largest image a scene may ask for, so a hostile file cannot make the renderer
// allocate without bound.
inline constexpr long long kMaxImagePixels = 8192LL * 8192LL;

// Gives objects, lights and stroke emitters without a name "object_<index>" /
// "light_<index>" / "strokes_<index>", with a suffix when that name is already taken.
void name_unnamed(SceneDesc& scene);

// Reports duplicate material, object, light and stroke emitter names, objects and
// mixes naming a material that does not exist, mixes that refer to themselves
// (directly or through other mixes), stroke emitters on a missing object or with
// min above max, asset paths (textures, meshes, toon ramps, used brush images)
// that are not regular files relative to base_dir, and an image larger than
// kMaxImagePixels. Paths in messages are JSON paths.
void check_scene(const SceneDesc& scene, const std::filesystem::path& base_dir, ErrorLog& log);

}  // namespace inkray
