// inkray-render end to end: exit codes, one-line errors, written images.
#include "core/image/image_io.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace inkray {
namespace {

struct RunResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

RunResult run_render(const std::string& args) {
  const std::string cmd = std::string(INKRAY_BINARY_DIR) + "/bin/inkray-render " + args + " 2>&1";
  RunResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) r.output.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

class InkrayRender : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("inkray_render_test_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string scene(const std::string& name) const { return std::string(INKRAY_SOURCE_DIR) + "/scenes/" + name; }
  std::filesystem::path dir_;
};

// --write-scene saves the scene as the editor does and renders nothing; the result opens
// again and renders, for a scene whose unset optional paths used to make it unloadable.
TEST_F(InkrayRender, WriteSceneSavesWhatTheEditorSavesAndItOpensAgain) {
  const auto saved = dir_ / "toon.json";
  RunResult r = run_render(scene("toon.json") + " --write-scene " + saved.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(saved));
  const auto out = dir_ / "toon.png";
  r = run_render(saved.string() + " -o " + out.string() + " --spp 1 --width 16 --height 12 -q");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(out));

  r = run_render(scene("toon.json") + " --write-scene " + saved.string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--write-scene"), std::string::npos) << r.output;
  r = run_render(scene("toon.json") + " --write-scene " + (dir_ / "no" / "such" / "t.json").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("t.json"), std::string::npos) << r.output;
}

TEST_F(InkrayRender, RendersImageAndAovsAndPrintsErrorTable) {
  const auto out = dir_ / "c.pfm";
  const RunResult r = run_render(scene("cornell.json") + " -o " + out.string() + " --spp 4 --width 40 --height 40 " +
                                 "--aov normal=" + (dir_ / "n.png").string() + " --aov depth=" +
                                 (dir_ / "z.exr").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  RgbImage img;
  std::string error;
  ASSERT_TRUE(read_pfm(out, &img, &error)) << error;
  EXPECT_EQ(img.width, 40);
  EXPECT_EQ(img.height, 40);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "n.png"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "z.exr"));
  EXPECT_NE(r.output.find("rel. error"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("4 spp"), std::string::npos) << r.output;
}

TEST_F(InkrayRender, TimeLimitStopsBeforeSpp) {
  const RunResult r = run_render(scene("cornell.json") + " -o " + (dir_ / "c.png").string() +
                                 " --spp 100000 --time 0.2 --width 32 --height 32");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("100000 spp"), std::string::npos) << r.output;
}

TEST_F(InkrayRender, BadArgumentsGiveOneLineAndExitTwo) {
  struct Case {
    std::string args, expected;
  };
  const std::string png = " -o " + (dir_ / "x.png").string();
  for (const Case& c : {Case{"", "no scene file given"}, Case{scene("cornell.json"), "no output file given"},
                        Case{scene("cornell.json") + png + " --spp 0", "--spp: expected an integer in [1, 1048576]"},
                        Case{scene("cornell.json") + png + " --spp 12x", "got \"12x\""},
                        Case{scene("cornell.json") + png + " --threads", "--threads: missing value"},
                        Case{scene("cornell.json") + png + " --time -1", "--time: expected seconds"},
                        Case{scene("cornell.json") + png + " --aov colour=a.png", "--aov: expected NAME=FILE"},
                        Case{scene("cornell.json") + png + " --frobnicate", "unknown option \"--frobnicate\""},
                        Case{scene("cornell.json") + " -o out.bmp", "unknown image format"},
                        Case{scene("cornell.json") + " -o /nonexistent/dir/a.png", "does not exist"}}) {
    const RunResult r = run_render(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
}

TEST_F(InkrayRender, SceneErrorsNameTheFileAndWriteNothing) {
  const auto bad = dir_ / "bad.json";
  std::ofstream(bad) << R"({"format": "inkray-scene", "version": 1, "render": {"spp": -3}})";
  const auto out = dir_ / "out.png";
  RunResult r = run_render(bad.string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("bad.json"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("render.spp"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  r = run_render((dir_ / "missing.json").string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("missing.json"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(InkrayRender, HelpDocumentsEveryOption) {
  const RunResult r = run_render("--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* opt : {"--output", "--spp", "--time", "--threads", "--width", "--height", "--seed", "--aov", "--write-scene"})
    EXPECT_NE(r.output.find(opt), std::string::npos) << opt;
}

}  // namespace
}  // namespace inkray
