// Moving a scene file to another folder: relative asset paths (meshes, textures,
// toon ramps, brush images) are written relative to the scene file, so they must
// be rewritten or the moved scene no longer finds its files.
#pragma once

#include "core/document/desc.h"

#include <filesystem>

namespace inkray {

// Rewrites every relative ParamKind::path field so that, resolved against
// `to_dir`, it names the file it named resolved against `from_dir`. Absolute
// and empty paths are kept; a path with no relative form (another drive) becomes
// absolute. Separators are written as '/', which every platform reads.
void rebase_asset_paths(SceneDesc& scene, const std::filesystem::path& from_dir,
                        const std::filesystem::path& to_dir);

}  // namespace inkray
