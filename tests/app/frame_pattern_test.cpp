// Frame numbers in output names (inkray-render --frames): a run of '#' of any length is the
// zero-padded frame, and a range in which two frames, or two outputs of one frame, would
// write the same file is refused before anything renders.
#include "tests/support/program_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace inkray {
namespace {

namespace fs = std::filesystem;
using testing::Names;
using testing::ScratchFolder;

using testing::RunResult;

RunResult render(const std::string& scene, const std::string& args) {
  return testing::run_program("inkray-render", std::string(INKRAY_SOURCE_DIR) + "/scenes/" + scene +
                                                   " --width 8 --height 8 --spp 1 -q " + args);
}

Names files_in(const ScratchFolder& dir) {
  Names names = dir.entries();
  std::sort(names.begin(), names.end());
  return names;
}

TEST(FramePattern, AnyRunOfHashesIsTheZeroPaddedFrame) {
  ScratchFolder dir;
  const std::string hashes(64, '#');
  RunResult r =
      render("cornell.json", "--frames 9-10 -o '" + (dir / ("f_" + hashes + ".png")).string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(files_in(dir),
            (Names{"f_" + std::string(63, '0') + "9.png", "f_" + std::string(62, '0') + "10.png"}));

  // A negative frame keeps its sign inside the width, as printf's %03d does.
  ScratchFolder signs;
  r = render("cornell.json", "--frames -1-1 -o '" + (signs / "s_###.png").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(files_in(signs), (Names{"s_-01.png", "s_000.png", "s_001.png"}));
}

TEST(FramePattern, FramesThatWouldWriteOneFileAreRefusedBeforeRendering) {
  ScratchFolder dir;
  const std::string d = dir.path().string() + "/";
  struct Case {
    std::string scene, args, message;
  };
  for (const Case& c : {
           Case{"cornell.json", "--frames 1-12 -o " + d + "x#.png --aov depth=" + d + "x1#.png",
                "--frames 1-12: frames 1 and 11 would both write " + d + "x11.png (--aov depth=" + d +
                    "x1#.png at frame 1, -o " + d + "x#.png at frame 11)"},
           Case{"cornell.json", "--frames 9-12 -o " + d + "y#.png --aov depth=" + d + "y##.png",
                "--frames 9-12: frame 10 would write " + d + "y10.png twice (-o " + d +
                    "y#.png and --aov depth=" + d + "y##.png)"},
           Case{"cornell.json", "--frames 1-3 --denoise -o " + d + "z#.png --aov albedo=" + d + "z#_raw.png",
                "frame 1 would write " + d + "z1_raw.png twice (--denoise's raw image and --aov albedo=" + d +
                    "z#_raw.png)"},
           // "all" is the scene's range (1-48), known once the scene is read.
           Case{"animation.json", "--frames all -o " + d + "a#.png --aov depth=" + d + "a1#.png",
                "--frames 1-48: frames 1 and 11 would both write " + d + "a11.png"},
       }) {
    SCOPED_TRACE(c.args);
    const RunResult r = render(c.scene, c.args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_EQ(files_in(dir), Names{});
  }
}

TEST(FramePattern, DistinctNamesRender) {
  ScratchFolder dir;
  const std::string d = dir.path().string() + "/";
  const RunResult r =
      render("cornell.json", "--frames 1-11:5 -o " + d + "x#.png --aov depth=" + d + "x1#.exr");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(files_in(dir), (Names{"x1.png", "x11.exr", "x11.png", "x111.exr", "x16.exr", "x6.png"}));
}

}  // namespace
}  // namespace inkray
