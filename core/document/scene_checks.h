// Checks that no single value can make: unique names, material references, asset
// files that exist, the image size. Independent of JSON, so the editor can run them
// on a document it has changed as well as the reader on a file it has read.
#pragma once

#include "core/document/desc.h"
#include "core/document/error_log.h"

#include <filesystem>
#include <string>
#include <vector>

namespace inkray {

// The largest image a scene may ask for, so a hostile file cannot make the renderer
// allocate without bound.
inline constexpr long long kMaxImagePixels = 8192LL * 8192LL;

// Stroke vertices in a whole scene: 1.8 million strokes of 8 segments, about 6 GiB
// at the 190 bytes a vertex measured (ribbon, kept copy and BVH; memory_budget.cpp).
inline constexpr long long kMaxStrokeVertices = 32LL << 20;
inline long long stroke_vertex_count(const StrokeEmitterDesc& e) {
  return e.count <= 0 ? 0 : static_cast<long long>(e.count) * 2 * (static_cast<long long>(e.segments) + 1);
}

// A file a scene refers to, found generically among every struct's ParamKind::path
// fields: texture images and toon ramps, OBJ meshes, and brush images in use.
enum class AssetKind { image, mesh, brush };
struct AssetRef {
  std::string at;       // JSON path of the key
  std::string written;  // the path as written, relative to the scene's folder
  AssetKind kind = AssetKind::image;
  bool required = false;  // a texture's or mesh's file, as opposed to an optional ramp image
};
std::vector<AssetRef> collect_assets(const SceneDesc& scene);

// Gives objects, lights and stroke emitters without a name "object_<index>" /
// "light_<index>" / "strokes_<index>", with a suffix when that name is already taken.
void name_unnamed(SceneDesc& scene);

// Reports duplicate material, object, light and stroke emitter names, objects and
// mixes naming a material that does not exist, mixes that refer to themselves
// (directly or through other mixes), stroke emitters on a missing object or with
// min above max, more than kMaxStrokeVertices stroke vertices, asset paths (textures, meshes, toon ramps,
// used brush images) that are not regular files relative to base_dir, and an image larger than
// kMaxImagePixels. Paths in messages are JSON paths.
// All of these leave the document whole, so they are ErrorLog::add_unrenderable
// problems (warnings when it is read for editing), but a path with a NUL.
void check_scene(const SceneDesc& scene, const std::filesystem::path& base_dir, ErrorLog& log);

}  // namespace inkray
