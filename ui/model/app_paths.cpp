#include "ui/model/app_paths.h"

#include <cstdlib>

namespace inkray {

std::filesystem::path editor_config_dir() {
  if (const char* dir = std::getenv("INKRAY_CONFIG_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "inkray";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".config/inkray";
  return std::filesystem::temp_directory_path() / "inkray";
}

}  // namespace inkray
