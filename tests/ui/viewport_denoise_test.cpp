// The viewport's Denoise toggle in the real editor under Xvfb: clicking it denoises the
// samples already taken (the render had finished; nothing restarts) and the image shown
// loses its grain.
#include "core/image/image_io.h"

#include "tests/support/editor_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace inkray {
namespace {

using namespace inkray::testing;

struct ViewportRun {
  std::string out;
  bool denoised = false;
  uint32_t spp = 0;
  double grain = 0.0;  // mean |difference| of horizontal neighbours in the viewport's image
};

ViewportRun run(const std::string& script) {
  ViewportRun r;
  ScratchFolder dir;
  int code = 0;
  r.out = run_editor_script(dir, 1280, 720, script, "--threads 1 --frames 60", "timeline.json", &code);
  EXPECT_EQ(code, 0) << r.out;
  EXPECT_NE(r.out.find("input script: done"), std::string::npos) << r.out;
  const std::vector<double> denoised = printed_numbers(r.out, "viewport denoised:");
  const std::vector<double> spp = printed_numbers(r.out, "viewport spp:");
  const std::vector<double> rect = printed_numbers(r.out, "viewport image:");
  if (denoised.size() != 1 || spp.size() != 1 || rect.size() != 4) {
    ADD_FAILURE() << r.out;
    return r;
  }
  r.denoised = denoised[0] != 0.0;
  r.spp = uint32_t(spp[0]);
  RgbImage shot;
  std::string error;
  if (!read_image(dir / "screenshot.png", false, &shot, &error)) {
    ADD_FAILURE() << error;
    return r;
  }
  double sum = 0.0, n = 0.0;
  for (int y = int(rect[1]) + 2; y < int(rect[1] + rect[3]) - 2; ++y)
    for (int x = int(rect[0]) + 2; x < int(rect[0] + rect[2]) - 3; ++x) {
      sum += std::abs(double(luminance(shot.at(x + 1, y))) - double(luminance(shot.at(x, y))));
      n += 1.0;
    }
  r.grain = n > 0.0 ? sum / n : 0.0;
  return r;
}

TEST(ViewportDenoise, TheToggleDenoisesTheSamplesTaken) {
  if (const std::string why = editor_unavailable(); !why.empty()) GTEST_SKIP() << why;
  const ViewportRun plain = run("wait 30\n");
  const ViewportRun denoised = run("wait 30\nhover viewport.denoise\nclick\nwait 20\n");
  EXPECT_FALSE(plain.denoised) << plain.out;
  EXPECT_TRUE(denoised.denoised) << denoised.out;
  // The document's 4 samples, in both: the toggle did not restart the render.
  EXPECT_EQ(plain.spp, 4u);
  EXPECT_EQ(denoised.spp, 4u);
  EXPECT_LT(denoised.grain, 0.7 * plain.grain) << "plain " << plain.grain << ", denoised " << denoised.grain;
}

}  // namespace
}  // namespace inkray
