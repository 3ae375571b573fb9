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
// With a scope, only its items are checked (see CheckScope).
struct CheckScope;
void check_scene(const SceneDesc& scene, const std::filesystem::path& base_dir, ErrorLog& log,
                 const CheckScope* scope = nullptr);

// The items of the document's lists a check reads, for checking an edit in time
// proportional to what it changed (docs/architecture.md, "Checks of an edit"). Valid
// between two documents whose lists hold the same names in the same order under the same
// base_dir (same_names): then duplicate names and every reference from an unchanged item
// are as they were, and so is every problem of an unchanged item. The document-wide
// checks (image size, frame range, camera, mix cycles, the stroke budget, animation)
// always run. Files are not looked at again for unchanged items: a caller that must
// see files change on disk checks them itself (SceneCompiler stamps them).
struct CheckScope {
  std::vector<bool> materials, objects, lights, strokes;  // per item: changed
  bool empty() const;                                     // no item changed
};
bool same_names(const SceneDesc& a, const SceneDesc& b);
// The items that differ between two documents with the same names (same_names).
CheckScope changed_items(const SceneDesc& before, const SceneDesc& after);

}  // namespace inkray
