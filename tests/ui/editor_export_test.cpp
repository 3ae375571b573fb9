// An export through the real editor's dialog under Xvfb (`inkray --export FILE` fills
// the dialog and presses Start): it renders on every core, writes the chosen file at
// the scene's resolution, and the finished image opens in the editor's image view.
#include "core/image/image_io.h"

#include "tests/support/editor_run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <thread>

namespace inkray {
namespace {

using namespace inkray::testing;

class EditorExport : public EditorTest {};

TEST_F(EditorExport, ThroughTheDialogOnAllCoresToTheChosenFile) {
  std::filesystem::create_directories(dir / "renders");
  const auto output = dir / "renders" / "final.png";
  const std::string out = run_command(editor_command(dir.path(), 1280, 720) + " --frames 5 --screenshot " +
                                          (dir / "shot.png").string() + " --export " + output.string() + " " +
                                          std::string(INKRAY_SOURCE_DIR) + "/scenes/toon.json",
                                      &code);
  ASSERT_EQ(code, 0) << out;

  const size_t at = out.find("export: ");
  ASSERT_NE(at, std::string::npos) << out;
  int threads = 0;
  std::istringstream(out.substr(at + 8)) >> threads;
  EXPECT_EQ(threads, int(std::max(1u, std::thread::hardware_concurrency()))) << out;
  EXPECT_NE(out.find("export wrote: " + output.string()), std::string::npos) << out;

  RgbImage image;
  std::string error;
  ASSERT_TRUE(read_image(output, true, &image, &error)) << error;
  EXPECT_EQ(image.width, 800);  // scenes/toon.json's resolution
  EXPECT_EQ(image.height, 450);
  // Exposure and sky make no pixel black, and the export is not a blank image.
  float lo = 1e9f, hi = 0.f;
  for (const Color& c : image.pixels) lo = std::min(lo, c.y), hi = std::max(hi, c.y);
  EXPECT_GT(hi - lo, 0.2f);
}

}  // namespace
}  // namespace inkray
