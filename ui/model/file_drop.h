// Files dropped on the editor's window: a scene opens, a mesh is imported, an image
// becomes the selection's texture (a material's first colour input, or the material of a
// selected object) or brush (a selected stroke emitter). Window-free: the shell calls
// these with the paths GLFW's drop callback delivers.
#pragma once

#include "ui/model/selection.h"

#include <filesystem>
#include <string>

namespace inkray {

enum class DropKind { scene, mesh, image, unknown };
DropKind drop_kind(const std::filesystem::path& file);

// Sets the dropped image on the selection; false with *why (naming the file and what
// the selection can take) when it cannot, leaving the scene unchanged.
bool drop_image_on(SceneDesc& scene, const Selection& selection, const std::filesystem::path& image,
                   std::string* why);

}  // namespace inkray
