// Reads a parsed scene document into a SceneDesc through the visit_params lists,
// checking every value against its Param and the references between sections.
// Every problem goes to the log; none stops the reading.
#pragma once

#include "core/scene/desc.h"
#include "core/scene/error_log.h"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace inkray {

// The largest image a scene may ask for, so a hostile file cannot make the renderer
// allocate without bound.
inline constexpr long long kMaxImagePixels = 8192LL * 8192LL;

// Asset paths (textures, meshes) are checked to name regular files relative to base_dir.
void read_scene_document(const nlohmann::json& doc, const std::filesystem::path& base_dir, SceneDesc& scene,
                         ErrorLog& log);

}  // namespace inkray
