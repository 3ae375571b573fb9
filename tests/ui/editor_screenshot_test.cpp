// The real editor under Xvfb: its screenshot must show the rendered scene in
// the viewport, matching a headless render of the same scene block by block.
#include "core/image/image_io.h"

#include "tests/support/editor_run.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

namespace inkray {
namespace {

using testing::run_command;

// Mean display value (sRGB-encoded luminance-like average of r, g, b) of a rectangle.
float block_mean(const RgbImage& img, float x0, float y0, float x1, float y1) {
  double sum = 0.0;
  int n = 0;
  for (int y = int(y0); y < int(y1); ++y) {
    for (int x = int(x0); x < int(x1); ++x) {
      const Color& c = img.at(x, y);
      sum += (linear_to_srgb(std::min(c.r, 1.f)) + linear_to_srgb(std::min(c.g, 1.f)) +
              linear_to_srgb(std::min(c.b, 1.f))) /
             3.0;
      ++n;
    }
  }
  return n ? float(sum / n) : 0.f;
}

TEST(EditorScreenshot, ViewportShowsTheRenderedScene) {
  if (const std::string why = testing::editor_unavailable(); !why.empty()) GTEST_SKIP() << why;
  int code = 0;
  const std::string bin = std::string(INKRAY_BINARY_DIR) + "/bin/";
  const auto dir = std::filesystem::temp_directory_path() / "inkray_editor_screenshot_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string scene = std::string(INKRAY_SOURCE_DIR) + "/scenes/cornell.json";

  const std::string shot = (dir / "editor.png").string();
  const std::string out =
      run_command("INKRAY_CONFIG_DIR=" + dir.string() + " xvfb-run -a -s '-screen 0 1600x900x24' " + bin +
                      "inkray --screenshot " + shot + " --frames 10 " + scene,
                  &code);
  ASSERT_EQ(code, 0) << out;
  int vx = 0, vy = 0, vw = 0, vh = 0;
  const size_t at = out.find("viewport image:");
  ASSERT_NE(at, std::string::npos) << out;
  std::istringstream(out.substr(at + 15)) >> vx >> vy >> vw >> vh;
  ASSERT_GT(vw, 100);
  ASSERT_GT(vh, 100);

  const std::string ref = (dir / "ref.png").string();
  const std::string ref_out = run_command(bin + "inkray-render " + scene + " -o " + ref + " --spp 16", &code);
  ASSERT_EQ(code, 0) << ref_out;

  RgbImage editor, reference;
  std::string error;
  ASSERT_TRUE(read_image(shot, true, &editor, &error)) << error;
  ASSERT_TRUE(read_image(ref, true, &reference, &error)) << error;
  ASSERT_LE(vx + vw, editor.width);
  ASSERT_LE(vy + vh, editor.height);

  // Non-uniform: the viewport is not a blank rectangle.
  float lo = 1.f, hi = 0.f;
  constexpr int kGrid = 8;
  int compared = 0;
  for (int gy = 0; gy < kGrid; ++gy) {
    for (int gx = 0; gx < kGrid; ++gx) {
      if (gy < 2 && gx < 4) continue;  // the statistics overlay sits in the top-left corner
      const float e = block_mean(editor, vx + vw * gx / float(kGrid), vy + vh * gy / float(kGrid),
                                 vx + vw * (gx + 1) / float(kGrid), vy + vh * (gy + 1) / float(kGrid));
      const float r =
          block_mean(reference, reference.width * gx / float(kGrid), reference.height * gy / float(kGrid),
                     reference.width * (gx + 1) / float(kGrid), reference.height * (gy + 1) / float(kGrid));
      lo = std::min(lo, e), hi = std::max(hi, e);
      EXPECT_NEAR(e, r, 0.08f) << "block " << gx << "," << gy;
      ++compared;
    }
  }
  EXPECT_GT(compared, 50);
  EXPECT_GT(hi - lo, 0.2f) << "the viewport looks uniform";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace inkray
