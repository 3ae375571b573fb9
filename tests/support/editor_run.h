// Running the real editor under Xvfb from a test: whether it can run here (else the
// reason to skip), and the command line that starts it in a window of a given size
// with its own config folder, so no test sees another's saved settings.
#pragma once

#include "tests/support/file_helpers.h"

#include <filesystem>
#include <string>

namespace inkray::testing {

// Empty when xvfb-run and the editor are there; else why the test cannot run.
inline std::string editor_unavailable() {
  int code = 0;
  run_command("command -v xvfb-run", &code);
  if (code != 0) return "xvfb-run is not installed";
  if (!std::filesystem::exists(std::string(INKRAY_BINARY_DIR) + "/bin/inkray")) return "the editor was not built";
  return {};
}

// "INKRAY_CONFIG_DIR=... xvfb-run ... inkray --window-size W H": append the options.
inline std::string editor_command(const std::filesystem::path& config_dir, int width, int height) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  return "INKRAY_CONFIG_DIR=" + config_dir.string() + " xvfb-run -a -s '-screen 0 " + size + "x24' " +
         std::string(INKRAY_BINARY_DIR) + "/bin/inkray --window-size " + std::to_string(width) + " " +
         std::to_string(height);
}

}  // namespace inkray::testing
