// inkray-render end to end: exit codes, one-line errors, written images.
#include "core/image/image_io.h"
#include "tests/support/program_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace inkray {
namespace {

using testing::RunResult;

RunResult run_render(const std::string& args) { return testing::run_program("inkray-render", args); }

class InkrayRender : public ::testing::Test {
 protected:
  std::string scene(const std::string& name) const {
    return std::string(INKRAY_SOURCE_DIR) + "/scenes/" + name;
  }
  testing::ScratchFolder scratch_;  // removed with the fixture
  const std::filesystem::path dir_ = scratch_.path();
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

// --time bounds the whole run: a scene that takes longer to build than the limit is an
// error that writes nothing, not a render that overruns by minutes.
TEST_F(InkrayRender, TimeLimitCoversBuildingTheScene) {
  const auto file = dir_ / "heavy.json";
  std::ofstream(file) << R"({"format": "inkray-scene", "version": 1,
    "render": {"width": 32, "height": 24},
    "materials": [{"name": "m", "type": "diffuse"}],
    "objects": [{"name": "ball", "material": "m", "shape": {"type": "sphere"}}],
    "strokes": [{"name": "paint", "object": "ball", "count": 1500000, "seed": 77}]})";
  const auto out = dir_ / "heavy.png";
  const RunResult r = run_render(file.string() + " -o " + out.string() + " --time 0.3 -q");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("heavy.json: the time limit of 0.3 s ran out while building the scene"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// The anisotropic Kuwahara filter at radius 64 on a 1080p image takes minutes: with a
// time limit the render says so at once instead of overrunning it.
TEST_F(InkrayRender, TimeLimitLeavesRoomForThePainterlyFilter) {
  const auto file = dir_ / "filter.json";
  std::ofstream(file) << R"({"format": "inkray-scene", "version": 1,
    "render": {"width": 1920, "height": 1080, "painterly": "anisotropic", "painterly_radius": 64},
    "materials": [{"name": "m", "type": "diffuse"}],
    "objects": [{"name": "ball", "material": "m", "shape": {"type": "sphere"}}]})";
  const auto out = dir_ / "filter.png";
  RunResult r = run_render(file.string() + " -o " + out.string() + " --time 2 -q");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("filter.json: the painterly filter alone takes about"), std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  // Smaller, the same filter fits, and the image is written.
  r = run_render(file.string() + " -o " + out.string() + " --time 4 --width 96 --height 54 -q");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(out));
}

// A closed white room at 1024 bounces: one pass takes seconds, the limit half of one.
TEST_F(InkrayRender, TimeLimitCutsTheFirstPassAndWritesNothing) {
  const auto file = dir_ / "room.json";
  std::ofstream(file) << R"({"format": "inkray-scene", "version": 1,
    "camera": {"look_from": [0, 0, 0], "look_at": [0, 0, -1]},
    "render": {"width": 160, "height": 120, "max_depth": 1024},
    "materials": [{"name": "white", "type": "diffuse", "albedo": 1}],
    "objects": [{"name": "room", "material": "white", "shape": {"type": "sphere", "radius": 10}}]})";
  const auto out = dir_ / "room.png";
  const RunResult r = run_render(file.string() + " -o " + out.string() + " --time 0.5 -q");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("ran out while rendering the first sample of every pixel"), std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(InkrayRender, MemoryLimitRefusesAScenePredictedToExceedIt) {
  const auto out = dir_ / "m.png";
  RunResult r = run_render(scene("strokes_100k.json") + " -o " + out.string() + " --memory-limit 16M -q");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("more than the limit of 16 MiB"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  r = run_render(scene("cornell.json") + " -o " + out.string() + " --memory-limit lots");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--memory-limit: expected a size such as 8G"), std::string::npos) << r.output;
}

TEST_F(InkrayRender, RendersImageAndAovsAndPrintsErrorTable) {
  const auto out = dir_ / "c.pfm";
  const RunResult r =
      run_render(scene("cornell.json") + " -o " + out.string() + " --spp 4 --width 40 --height 40 " +
                 "--aov normal=" + (dir_ / "n.png").string() + " --aov depth=" + (dir_ / "z.exr").string());
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

// --denoise writes the denoised image and the raw one beside it, with both estimates;
// the raw one is the render without --denoise, sample for sample.
TEST_F(InkrayRender, DenoiseWritesTheDenoisedAndTheRawImage) {
  const auto out = dir_ / "c.pfm";
  const std::string args = scene("cornell_outlines.json") + " --spp 8 --width 48 --height 48 -o ";
  RunResult r = run_render(args + out.string() + " --denoise");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("denoised"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("c_raw.pfm"), std::string::npos) << r.output;
  r = run_render(args + (dir_ / "plain.pfm").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  RgbImage denoised, raw, plain;
  std::string error;
  ASSERT_TRUE(read_pfm(out, &denoised, &error)) << error;
  ASSERT_TRUE(read_pfm(dir_ / "c_raw.pfm", &raw, &error)) << error;
  ASSERT_TRUE(read_pfm(dir_ / "plain.pfm", &plain, &error)) << error;
  EXPECT_EQ(raw.pixels, plain.pixels);
  EXPECT_NE(denoised.pixels, raw.pixels);
  // An existing raw file is only replaced as the render's other outputs are: the name
  // is planned with them, so the same file twice is refused before rendering.
  r = run_render(args + out.string() + " --denoise --aov depth=" + (dir_ / "c_raw.pfm").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
}

// Adaptive sampling in the CLI: the render reports its stopped tiles and fewer samples.
TEST_F(InkrayRender, NoiseThresholdStopsCleanTiles) {
  const RunResult r = run_render(scene("cornell.json") + " -o " + (dir_ / "c.png").string() +
                                 " --spp 64 --width 64 --height 64 --noise-threshold 0.2 --min-spp 8");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("adaptive sampling:"), std::string::npos) << r.output;
}

TEST_F(InkrayRender, TimeLimitStopsBeforeSpp) {
  const RunResult r = run_render(scene("cornell.json") + " -o " + (dir_ / "c.png").string() +
                                 " --spp 100000 --time 0.2 --width 32 --height 32");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("100000 spp"), std::string::npos) << r.output;
}

// --time is a budget: the denoiser's and the painterly filter's time is kept back from
// the render, so a render the clock stops still writes its denoised image, its raw one
// and the samples they hold (the README's example, at a small size).
TEST_F(InkrayRender, TimeLimitKeepsTimeForTheDenoiser) {
  const auto out = dir_ / "clean.png";
  const RunResult r =
      run_render(scene("cornell.json") + " -o " + out.string() +
                 " --spp 100000 --time 1.5 --denoise --noise-threshold 0.02 --width 96 --height 72");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(out));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "clean_raw.png"));
  EXPECT_EQ(r.output.find("100000 spp"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(" spp, "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("denoised in"), std::string::npos) << r.output;
}

TEST_F(InkrayRender, TimeLimitKeepsTimeForThePainterlyFilterAndTheDenoiser) {
  const auto file = dir_ / "paint.json";
  std::ofstream(file) << R"({"format": "inkray-scene", "version": 1,
    "render": {"width": 96, "height": 54, "painterly": "anisotropic", "painterly_radius": 6},
    "materials": [{"name": "m", "type": "diffuse"}],
    "lights": [{"name": "sun", "type": "directional"}],
    "objects": [{"name": "ball", "material": "m", "shape": {"type": "sphere"}}]})";
  const auto out = dir_ / "paint.png";
  const RunResult r =
      run_render(file.string() + " -o " + out.string() + " --spp 100000 --time 1.5 --denoise");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(out));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "paint_raw.png"));
  EXPECT_EQ(r.output.find("100000 spp"), std::string::npos) << r.output;
}

TEST_F(InkrayRender, BadArgumentsGiveOneLineAndExitTwo) {
  struct Case {
    std::string args, expected;
  };
  const std::string png = " -o " + (dir_ / "x.png").string();
  for (const Case& c :
       {Case{"", "no scene file given"}, Case{scene("cornell.json"), "no output file given"},
        Case{scene("cornell.json") + png + " --spp 0", "--spp: expected an integer in [1, 1048576]"},
        Case{scene("cornell.json") + png + " --spp 12x", "got \"12x\""},
        Case{scene("cornell.json") + png + " --threads", "--threads: missing value"},
        // The ranges of options that set a render setting are its parameter's (RenderSettings).
        Case{scene("cornell.json") + png + " --width 16385", "--width: expected an integer in [1, 16384]"},
        Case{scene("cornell.json") + png + " --seed -1", "--seed: expected an integer in [0, 2147483647]"},
        Case{scene("cornell.json") + " --samples 4 2 -o p.exr", "B must be above A"},
        Case{scene("cornell.json") + png + " --crop 0 0 10", "--crop: missing value"},
        Case{scene("cornell.json") + " " + scene("toon.json") + png, "only one scene file is rendered"},
        Case{scene("cornell.json") + png + " --time -1", "--time: expected seconds"},
        Case{scene("cornell.json") + png + " --aov colour=a.png", "--aov: expected NAME=FILE"},
        Case{scene("cornell.json") + png + " --frobnicate", "unknown option \"--frobnicate\""},
        Case{scene("cornell.json") + " -o out.bmp", "unknown image format"},
        Case{scene("cornell.json") + png + " --noise-threshold 0", "--noise-threshold: expected"},
        Case{scene("cornell.json") + png + " --min-spp 8", "add --noise-threshold"},
        Case{scene("cornell.json") + " --samples 0 4 -o p.exr --noise-threshold 0.1",
             "adaptive sampling is for renders on one machine"},
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
  for (const char* opt :
       {"--output", "--spp", "--time", "--threads", "--width", "--height", "--seed", "--aov", "--write-scene",
        "--memory-limit", "--denoise", "--noise-threshold", "--min-spp"})
    EXPECT_NE(r.output.find(opt), std::string::npos) << opt;
}

// ---------------------------------------------------------------- outputs never lose data
std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> entries_of(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST_F(InkrayRender, TheSameFileTwiceIsRefusedBeforeRendering) {
  const auto out = dir_ / "out.png";
  std::ofstream(out) << "an earlier render";
  std::filesystem::create_symlink("out.png", dir_ / "link.png");
  for (const std::string& aov :
       {out.string(), (dir_ / "." / "out.png").string(), (dir_ / "link.png").string()}) {
    const RunResult r = run_render(scene("cornell.json") + " -o " + out.string() + " --aov depth=" + aov +
                                   " --spp 1 --width 8 --height 8");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--aov depth=" + aov + ": the same file as -o " + out.string()),
              std::string::npos)
        << r.output;
    EXPECT_EQ(file_text(out), "an earlier render");
  }
}

TEST_F(InkrayRender, UnwritableAovIsRefusedBeforeRenderingAndNoImageIsWritten) {
  std::filesystem::create_directory(dir_ / "taken.exr");
  std::ofstream(dir_ / "file") << "";
  const auto out = dir_ / "out.png";
  struct Case {
    std::filesystem::path aov;
    std::string problem;
  };
  for (const Case& c :
       {Case{dir_ / "missing" / "d.exr", "folder " + (dir_ / "missing").string() + " does not exist"},
        Case{dir_ / "taken.exr", (dir_ / "taken.exr").string() + " is a folder"},
        Case{dir_ / "file" / "d.exr", (dir_ / "file").string() + " is not a folder"}}) {
    const RunResult r = run_render(scene("cornell.json") + " -o " + out.string() +
                                   " --aov depth=" + c.aov.string() + " --spp 1 --width 8 --height 8");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--aov depth=" + c.aov.string() + ": " + c.problem), std::string::npos)
        << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

// The AOV's folder passes the check and is removed while the render runs: the write
// fails after rendering, and the image, already encoded, must not land without it.
TEST_F(InkrayRender, AovFolderGoneAfterTheRenderLeavesNoImage) {
  std::filesystem::create_directory(dir_ / "aovs");
  const std::string binary = std::string(INKRAY_BINARY_DIR) + "/bin/inkray-render";
  const std::string log = (dir_ / "log.txt").string(), out = (dir_ / "out.png").string();
  const std::string aov = "depth=" + (dir_ / "aovs" / "d.exr").string(), cornell = scene("cornell.json");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    ::execl(binary.c_str(), binary.c_str(), cornell.c_str(), "-o", out.c_str(), "--aov", aov.c_str(), "--spp",
            "1048576", "--time", "2", "--width", "32", "--height", "32", "--threads", "2", "-q",
            (char*)nullptr);
    ::_exit(127);
  }
  // Worker threads exist only after the arguments (and output paths) were checked.
  const std::filesystem::path tasks = "/proc/" + std::to_string(child) + "/task";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  std::error_code ec;
  while (std::distance(std::filesystem::directory_iterator(tasks, ec), {}) < 2 &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  std::filesystem::remove_all(dir_ / "aovs");
  int status = 0;
  ::waitpid(child, &status, 0);
  const std::string output = file_text(log);
  ASSERT_TRUE(WIFEXITED(status)) << output;
  EXPECT_EQ(WEXITSTATUS(status), 1) << output;
  EXPECT_NE(output.find("cannot write " + (dir_ / "aovs" / "d.exr").string()), std::string::npos) << output;
  EXPECT_NE(output.find("No such file or directory"), std::string::npos) << output;
  EXPECT_EQ(entries_of(dir_), std::vector<std::string>{"log.txt"});  // no image, no temporary
}

TEST_F(InkrayRender, OutputThroughASymlinkReplacesItsTarget) {
  std::ofstream(dir_ / "real.png") << "an earlier render";
  std::filesystem::create_symlink("real.png", dir_ / "link.png");
  const RunResult r = run_render(scene("cornell.json") + " -o " + (dir_ / "link.png").string() +
                                 " --spp 1 --width 8 --height 8 -q");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::is_symlink(dir_ / "link.png"));
  RgbImage img;
  std::string error;
  ASSERT_TRUE(read_image(dir_ / "real.png", true, &img, &error)) << error;
  EXPECT_EQ(img.width, 8);
  EXPECT_EQ(entries_of(dir_), (std::vector<std::string>{"link.png", "real.png"}));
}

}  // namespace
}  // namespace inkray
