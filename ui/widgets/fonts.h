// The editor's type: DejaVu Sans (resources/fonts, from Debian's fonts-dejavu-core, with
// its licence beside it) rasterised at the UI scale, and ImGui's style sizes scaled to
// match. Called before the first frame and whenever the scale changes, between frames.
#pragma once

#include <filesystem>
#include <string>

namespace inkray {

// The UI scale the current font was built for (its size over the size at scale 1), for
// sizes drawn in pixels, such as the viewport's gizmo.
float ui_scale_of_font();

// Where the editor's resources are: $INKRAY_RESOURCE_DIR, else the source tree's resources/.
std::filesystem::path resource_dir();

// Rebuilds ImGui's font atlas and style for `scale` (1 = 15 px text). With the font file
// missing or unreadable it falls back to ImGui's built-in font and says why in *warning.
// The renderer backend's font texture must be recreated afterwards.
void set_ui_scale(float scale, std::string* warning);

}  // namespace inkray
