// inkray-render's vector files of the lines: written with the image for every frame
// (a run of '#' is the frame), the image embedded on request, and refused before any
// rendering where they cannot be written (a slice of samples, a wrong extension, many
// frames into one file).
#include "tests/support/program_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>

namespace inkray {
namespace {

using testing::Names;
using testing::RunResult;
using testing::ScratchFolder;

RunResult render(const std::string& args) {
  return testing::run_program(
      "inkray-render",
      std::string(INKRAY_SOURCE_DIR) + "/scenes/lines_ink.json --width 96 --height 54 -q " + args);
}

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(LineFiles, EachFrameWritesItsSvgAndPdfBesideItsImage) {
  ScratchFolder dir;
  const std::string d = dir.path().string() + "/";
  const RunResult r = render("--spp 2 --frames 1-2 -o " + d + "f##.png --lines-svg " + d +
                             "f##.svg --lines-pdf " + d + "f##.pdf --lines-svg-image");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  Names names = dir.entries();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (Names{"f01.pdf", "f01.png", "f01.svg", "f02.pdf", "f02.png", "f02.svg"}));
  const std::string svg = read(dir / "f01.svg");
  EXPECT_NE(svg.find("inkscape:label=\"ink\""), std::string::npos);
  EXPECT_NE(svg.find("data:image/png;base64,"), std::string::npos);
  EXPECT_NE(svg.find("<path d=\"M"), std::string::npos);
  EXPECT_EQ(read(dir / "f01.pdf").rfind("%PDF", 0), 0u);
}

TEST(LineFiles, AreRefusedBeforeRenderingWhereTheyCannotBeWritten) {
  ScratchFolder dir;
  const std::string d = dir.path().string() + "/";
  struct Case {
    std::string args, message;
  };
  for (const Case& c : {
           Case{"--samples 0 2 -o " + d + "p.exr --lines-svg " + d + "p.svg", "give it to inkray-merge"},
           Case{"-o " + d + "a.png --lines-svg " + d + "a.pdf", "expected a file ending in .svg"},
           Case{"-o " + d + "a.png --lines-svg-image", "--lines-svg-image puts the image under the lines"},
           Case{"--frames 1-2 -o " + d + "f#.png --lines-pdf " + d + "one.pdf", "needs a run of '#'"},
       }) {
    SCOPED_TRACE(c.args);
    const RunResult r = render(c.args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
    EXPECT_EQ(dir.entries(), Names{});
  }
}

}  // namespace
}  // namespace inkray
