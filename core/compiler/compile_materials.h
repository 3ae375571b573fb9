// Material compilation: MaterialDesc -> the flat Material the path loop reads,
// with textures read once per file through the compiler's asset cache.
#pragma once

#include "core/compiler/asset_cache.h"
#include "core/world/render_scene.h"

#include <string>
#include <vector>

namespace inkray {

// Fills scene.materials and scene.material_names in document order; a material
// that fails is left out and its error (naming materials[i]) appended. Images
// come through `assets`.
void compile_materials(const SceneDesc& desc, RenderScene& scene, std::vector<std::string>& errors,
                       AssetCache& assets);

}  // namespace inkray
