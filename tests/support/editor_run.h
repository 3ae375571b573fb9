// Running the real editor under Xvfb from a test: whether it can run here (else the
// reason to skip), the command line that starts it in a window of a given size with its
// own config folder, so no test sees another's saved settings, and reading what an input
// script's print commands wrote (ui/editor_app.cpp, InputScript).
#pragma once

#include "tests/support/file_helpers.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace inkray::testing {

// Empty when xvfb-run and the editor are there; else why the test cannot run.
inline std::string editor_unavailable() {
  int code = 0;
  run_command("command -v xvfb-run", &code);
  if (code != 0) return "xvfb-run is not installed";
  if (!std::filesystem::exists(std::string(INKRAY_BINARY_DIR) + "/bin/inkray"))
    return "the editor was not built";
  return {};
}

// A test of the running editor: skipped where it cannot run, in a scratch folder (which is
// also the editor's config folder), with a place for its exit code.
class EditorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (const std::string why = editor_unavailable(); !why.empty()) GTEST_SKIP() << why;
  }
  ScratchFolder dir;
  int code = 0;
};

// "INKRAY_CONFIG_DIR=... xvfb-run ... inkray --window-size W H": append the options.
inline std::string editor_command(const std::filesystem::path& config_dir, int width, int height) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  return "INKRAY_CONFIG_DIR=" + config_dir.string() + " xvfb-run -a -s '-screen 0 " + size + "x24' " +
         std::string(INKRAY_BINARY_DIR) + "/bin/inkray --window-size " + std::to_string(width) + " " +
         std::to_string(height);
}

// A scripted run (ui/editor_app.cpp, InputScript): the editor on tests/ui/data/SCENE in a
// window of the given size, `script` as its input script (written to dir/input.txt), the
// document it ends with written to dir/dump.json and its window to dir/screenshot.png,
// plus `options`. Its output; the exit code in *code.
inline std::string run_editor_script(const ScratchFolder& dir, int width, int height,
                                     const std::string& script, const std::string& options,
                                     const std::string& scene, int* code) {
  std::ofstream(dir / "input.txt") << script;
  return run_command(editor_command(dir.path(), width, height) + " --input-script " +
                         (dir / "input.txt").string() + " " + options + " --screenshot " +
                         (dir / "screenshot.png").string() + " --scene-dump " + (dir / "dump.json").string() +
                         " " + std::string(INKRAY_SOURCE_DIR) + "/tests/ui/data/" + scene,
                     code);
}

// The numbers on the n-th line of `out` that starts with `head` ("value", "keys",
// "frame"): its words that end in a digit. Empty when there is no such line.
inline std::vector<double> printed_numbers(const std::string& out, const std::string& head, int n = 0) {
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(head + " ", 0) != 0 || n-- > 0) continue;
    std::istringstream words(line.substr(head.size()));
    std::vector<double> numbers;
    std::string word;
    while (words >> word) {
      if (std::isdigit(static_cast<unsigned char>(word.back()))) numbers.push_back(std::stod(word));
    }
    return numbers;
  }
  return {};
}

}  // namespace inkray::testing
