// The editor's command line: a number option takes a whole number in its range, or the
// editor says which option expected what and exits 2 before opening a window (std::atoi
// read "8x" as 8 and "many" as 0).
#include "tests/support/file_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace inkray {
namespace {

TEST(EditorArguments, NumbersAreWholeAndInRange) {
  const std::string editor = std::string(INKRAY_BINARY_DIR) + "/bin/inkray";
  if (!std::filesystem::exists(editor)) GTEST_SKIP() << "the editor was not built";
  struct Case {
    std::string args, expected;
  };
  for (const Case& c : {Case{"--threads many", "--threads: expected an integer in [1, 1024], got \"many\""},
                        Case{"--threads 8x", "--threads: expected an integer in [1, 1024], got \"8x\""},
                        Case{"--frames -3", "--frames: expected an integer in [0, 1000000], got \"-3\""},
                        Case{"--window-size 800 tall", "--window-size: expected an integer in [64, 16384]"},
                        Case{"--ui-scale nan", "--ui-scale: expected a number in [0.5, 3], got \"nan\""},
                        Case{"--measure-edits 0", "--measure-edits: expected an integer in [1, 100000]"}}) {
    int code = 0;
    const std::string out = testing::run_command(editor + " " + c.args, &code);
    EXPECT_EQ(code, 2) << c.args << "\n" << out;
    EXPECT_NE(out.find("inkray: " + c.expected), std::string::npos) << c.args << "\n" << out;
  }
}

}  // namespace
}  // namespace inkray
