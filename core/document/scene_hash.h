// A render's content hash: what it was rendered from, the bytes of every file the scene
// refers to included (meshes, textures, toon ramps, brush images, graph image textures),
// so that partials, checkpoints and line decisions of a scene whose mesh or texture
// changed between two slices are refused instead of blended (docs/final-renders.md).
#pragma once

#include "core/document/desc.h"
#include "core/io/content_hash.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// Every asset the scene's render reads (scene_checks' collect_assets, so a new asset type
// needs no change here), once each in document order, resolved against scene.base_dir.
std::vector<AssetHash> hash_scene_assets(const SceneDesc& scene);

// The scene's text as compared between slices: its sample limits (render.spp and
// render.time_limit) say how long a render ran, not what it shows, and are left out.
// Text that is not JSON within json_bounds' limits is returned as it is.
std::string comparable_scene_text(std::string_view scene_text);

// The assets as a JSON list of [path, digest] pairs, as partial and line decision headers
// keep them, and back: "" on success, else what is wrong with the text.
std::string assets_to_json(const std::vector<AssetHash>& assets);
std::string assets_from_json(std::string_view text, std::vector<AssetHash>* assets);

// The hash of the comparable scene and of its assets' paths and hashes.
uint64_t scene_content_hash(std::string_view scene_text, const std::vector<AssetHash>& assets);

}  // namespace inkray
