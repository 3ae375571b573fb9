// Material compilation: MaterialDesc -> the flat Material the path loop reads,
// with textures read once per file through the compiler's asset cache.
#pragma once

#include "core/compiler/asset_cache.h"
#include "core/document/desc.h"
#include "core/world/render_scene.h"

#include <string>
#include <vector>

namespace inkray {

// The table the last successful compile made from `desc` (every material compiled,
// in document order): entries whose description is unchanged are taken from it.
struct LastMaterials {
  const SharedList<MaterialDesc>* desc = nullptr;
  const std::vector<Material>* table = nullptr;
  const std::vector<std::vector<std::string>>* keys = nullptr;  // the cache entries each was built from
};

// Fills world.materials and world.material_names in document order; a material
// that fails is left out and its error (naming materials[i]) appended. Images
// come through `assets`. With `last` given and the list of names unchanged, only
// the materials whose description changed are compiled; returns how many were.
// `keys` receives, per material, the cache entries it was built from (kept entries
// are touched, so the cache keeps their images). With `broken_graphs` given, a graph
// that does not compile is drawn in a loud stand-in colour and its errors go there
// instead of `errors`, so the rest of the scene still renders (the editor's choice).
size_t compile_materials(const SceneDesc& desc, World& world, std::vector<std::string>& errors,
                         AssetCache& assets, std::vector<std::vector<std::string>>& keys,
                         const LastMaterials& last = {}, std::vector<std::string>* broken_graphs = nullptr);

// The loud look of what cannot be drawn as described (a broken graph, strokes whose
// brush image is missing): the stand-in checker, `squares` across the uv square,
// unlit so no light hides it.
Material stand_in_material(float squares);

}  // namespace inkray
