// Where the editor keeps its own files (recent list, crash recovery):
// $INKRAY_CONFIG_DIR, else $XDG_CONFIG_HOME/inkray, else ~/.config/inkray.
#pragma once

#include <filesystem>

namespace inkray {

std::filesystem::path editor_config_dir();

}  // namespace inkray
