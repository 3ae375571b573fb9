// A file path parameter: the path as text, and a "..." button that opens the file
// dialog (file_dialog.h) filtered by the parameter's file type. A file chosen inside
// the scene's folder is stored relative to it (param_text.h, path_in_scene).
#pragma once

#include "core/document/params.h"

#include <filesystem>
#include <string>

namespace inkray {

// Draws the field; true when *value changed (typed, or chosen in the dialog).
// `scene_dir` is the folder relative paths resolve against.
bool path_field(const char* label, const Param& p, std::string* value,
                const std::filesystem::path& scene_dir);

}  // namespace inkray
