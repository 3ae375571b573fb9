// Final renders over many machines, end to end: inkray-render's sample slices,
// crop windows, checkpoints and frames, and inkray-merge adding partials up to
// the very image one run renders; every bad input a one-line error.
#include "core/film/film_partial.h"
#include "core/image/image_io.h"
#include "tests/support/program_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace inkray {
namespace {

namespace fs = std::filesystem;

using namespace inkray::testing;

RgbImage read(const fs::path& file) {
  RgbImage img;
  std::string error;
  EXPECT_TRUE(read_pfm(file, &img, &error)) << error;
  return img;
}

size_t lines_of(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

class FinalRender : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // The Cornell box with outlines, small: lines make the adaptive line sampler decide.
  RunResult render(const std::string& args) const {
    return run_program("inkray-render", std::string(INKRAY_SOURCE_DIR) +
                                            "/scenes/cornell_outlines.json --width 40 "
                                            "--height 30 -q " +
                                            args);
  }
  RunResult merge(const std::string& args) const { return run_program("inkray-merge", args); }
  testing::ScratchFolder scratch_;  // removed with the fixture
  const std::filesystem::path dir_ = scratch_.path();
};

TEST_F(FinalRender, SlicesMergeToTheImageOfOneRun) {
  ASSERT_EQ(render("--spp 12 -o " + path("one.pfm") + " --aov depth=" + path("one_depth.pfm") +
                   " --aov outline=" + path("one_lines.pfm"))
                .exit_code,
            0);
  RunResult r = render("--samples 0 5 --aov depth -o " + path("a.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = render("--samples 5 12 --aov depth -o " + path("b.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = merge(path("merged.pfm") + " " + path("b.exr") + " " + path("a.exr") +
            " --aov depth=" + path("merged_depth.pfm") + " --aov outline=" + path("merged_lines.pfm"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("12 spp"), std::string::npos) << r.output;
  EXPECT_EQ(read(dir_ / "one.pfm").pixels, read(dir_ / "merged.pfm").pixels);
  EXPECT_EQ(read(dir_ / "one_depth.pfm").pixels, read(dir_ / "merged_depth.pfm").pixels);
  EXPECT_EQ(read(dir_ / "one_lines.pfm").pixels, read(dir_ / "merged_lines.pfm").pixels);

  // In stages: a merge written as a partial merges again.
  r = merge(path("ab.partial.exr") + " " + path("a.exr") + " " + path("b.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = merge(path("staged.pfm") + " " + path("ab.partial.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read(dir_ / "one.pfm").pixels, read(dir_ / "staged.pfm").pixels);
}

// Denoising a split render: the slices keep the features, the merge denoises, and the
// result is the single-machine render's denoised image, bit for bit (the halves and
// features add up exactly).
TEST_F(FinalRender, DenoisedSlicesMergeToTheDenoisedImageOfOneRun) {
  ASSERT_EQ(render("--spp 8 --denoise -o " + path("one.pfm")).exit_code, 0);
  RunResult r = render("--samples 0 3 --denoise -o " + path("a.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = render("--samples 3 8 --denoise -o " + path("b.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = merge(path("merged.pfm") + " " + path("a.exr") + " " + path("b.exr") + " --denoise");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("denoised"), std::string::npos) << r.output;
  EXPECT_EQ(read(dir_ / "one.pfm").pixels, read(dir_ / "merged.pfm").pixels);
  EXPECT_EQ(read(dir_ / "one_raw.pfm").pixels, read(dir_ / "merged_raw.pfm").pixels);
  // Slices without the features cannot be denoised: one line naming the partial.
  ASSERT_EQ(render("--samples 0 8 -o " + path("plain.exr")).exit_code, 0);
  r = merge(path("x.pfm") + " " + path("plain.exr") + " --denoise");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("plain.exr"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--denoise"), std::string::npos) << r.output;
}

// Slices after the first read the line decisions written once by --decide-lines; one
// of another render is refused with one line.
TEST_F(FinalRender, SlicesReadingLineDecisionsMergeToTheImageOfOneRun) {
  ASSERT_EQ(render("--spp 40 -o " + path("one.pfm") + " --aov outline=" + path("one_lines.pfm")).exit_code,
            0);
  RunResult r = render("--decide-lines " + path("lines.bin"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "lines.bin"));
  r = render("--samples 0 20 -o " + path("a.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::pair<const char*, const char*> slices[] = {{"20 30", "b.exr"}, {"30 40", "c.exr"}};
  for (const auto& [range, file] : slices) {
    r = render("--line-decisions " + path("lines.bin") + " --samples " + range + " -o " + path(file));
    ASSERT_EQ(r.exit_code, 0) << range << "\n" << r.output;
  }
  r = merge(path("merged.pfm") + " " + path("a.exr") + " " + path("b.exr") + " " + path("c.exr") +
            " --aov outline=" + path("merged_lines.pfm"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read(dir_ / "one.pfm").pixels, read(dir_ / "merged.pfm").pixels);
  EXPECT_EQ(read(dir_ / "one_lines.pfm").pixels, read(dir_ / "merged_lines.pfm").pixels);

  // Decisions of another seed; --decide-lines with an image; --line-decisions alone.
  r = render("--seed 7 --samples 20 30 -o " + path("x.exr") + " --line-decisions " + path("lines.bin"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("line decisions of another render: seed"), std::string::npos) << r.output;
  EXPECT_EQ(lines_of(r.output), 1u) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "x.exr"));
  r = render("--decide-lines " + path("l2.bin") + " -o " + path("y.png"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(lines_of(r.output), 1u) << r.output;
  r = render("-o " + path("y.png") + " --line-decisions " + path("lines.bin"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("add --samples A B"), std::string::npos) << r.output;
}

TEST_F(FinalRender, CropWindowsMergeToTheWholeImage) {
  ASSERT_EQ(render("--spp 6 -o " + path("one.pfm")).exit_code, 0);
  std::string parts;
  for (const char* window : {"0 0 17 13", "17 0 40 13", "0 13 40 30"}) {
    const std::string file = path("crop_" + std::to_string(parts.size()) + ".exr");
    const RunResult r = render("--samples 0 6 --crop " + std::string(window) + " -o " + file);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    parts += " " + file;
  }
  const RunResult r = merge(path("merged.pfm") + parts);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read(dir_ / "one.pfm").pixels, read(dir_ / "merged.pfm").pixels);

  // Without --samples a crop writes the window's pixels: those of the whole image.
  ASSERT_EQ(render("--spp 6 --crop 5 4 31 22 -o " + path("window.pfm")).exit_code, 0);
  const RgbImage whole = read(dir_ / "one.pfm"), window = read(dir_ / "window.pfm");
  ASSERT_EQ(window.width, 26);
  ASSERT_EQ(window.height, 18);
  for (int y = 0; y < window.height; ++y)
    for (int x = 0; x < window.width; ++x)
      ASSERT_EQ(window.at(x, y), whole.at(x + 5, y + 4)) << x << "," << y;
}

TEST_F(FinalRender, ResumingACheckpointEqualsAnUninterruptedRender) {
  ASSERT_EQ(render("--spp 16 -o " + path("straight.pfm")).exit_code, 0);
  // Samples 0-8 as a checkpoint of the render to 16: the same format.
  const std::string checkpoint = path("resumed.pfm.checkpoint.exr");
  ASSERT_EQ(render("--samples 0 8 -o " + checkpoint).exit_code, 0);
  RunResult r = render("--spp 16 --resume --checkpoint 10 -o " + path("resumed.pfm"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read(dir_ / "straight.pfm").pixels, read(dir_ / "resumed.pfm").pixels);
  EXPECT_FALSE(fs::exists(checkpoint)) << "a completed render removes its checkpoint";

  // One of another render is refused, and kept.
  ASSERT_EQ(render("--seed 5 --samples 0 8 -o " + checkpoint).exit_code, 0);
  r = render("--spp 16 --resume -o " + path("resumed.pfm"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("cannot resume"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("seed 5 vs 0"), std::string::npos) << r.output;
  EXPECT_EQ(lines_of(r.output), 1u) << r.output;
  EXPECT_TRUE(fs::exists(checkpoint));
  // With no checkpoint and the image there, --resume has nothing to do.
  fs::remove(checkpoint);
  r = render("--spp 16 --resume -o " + path("resumed.pfm"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

// A render the time limit ends writes its film; --resume finishes it to the image
// of a render never stopped, whatever pass the limit fell in.
TEST_F(FinalRender, TimeLimitWritesACheckpointThatResumes) {
  const fs::path scene = dir_ / "room.json";
  std::ofstream(scene) << R"({"format": "inkray-scene", "version": 1,
    "camera": {"look_from": [0, 0, 0], "look_at": [0, 0, -1]},
    "render": {"width": 16, "height": 12, "max_depth": 256},
    "materials": [{"name": "white", "type": "diffuse", "albedo": [0.9, 0.9, 0.9]},
                  {"name": "glow", "type": "emissive", "color": [1, 1, 1], "strength": 1}],
    "objects": [{"name": "room", "material": "white", "shape": {"type": "sphere", "radius": 10}},
                {"name": "lamp", "material": "glow", "shape": {"type": "sphere", "center": [0, 0, -5], "radius": 1}}]})";
  const std::string base = scene.string() + " -q -o " + path("room.pfm");
  RunResult r = run_program("inkray-render", base + " --spp 100000 --time 0.6 --checkpoint 60");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path checkpoint = path("room.pfm.checkpoint.exr");
  PartialInfo info;
  std::string error;
  ASSERT_TRUE(read_partial(checkpoint, &info, nullptr, &error)) << error;
  ASSERT_GT(info.end_pass, 0u);
  const std::string spp = std::to_string(info.end_pass + 2);
  r = run_program("inkray-render", base + " --spp " + spp + " --resume");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(fs::exists(checkpoint));
  r = run_program("inkray-render", scene.string() + " -q -o " + path("straight.pfm") + " --spp " + spp);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read(dir_ / "straight.pfm").pixels, read(dir_ / "room.pfm").pixels);
}

TEST_F(FinalRender, MergeRefusesPartialsOfOtherRenders) {
  ASSERT_EQ(render("--samples 0 4 -o " + path("a.exr")).exit_code, 0);
  ASSERT_EQ(render("--samples 4 8 --seed 3 -o " + path("seed.exr")).exit_code, 0);
  ASSERT_EQ(render("--samples 2 6 -o " + path("overlap.exr")).exit_code, 0);
  ASSERT_EQ(run_program("inkray-render", std::string(INKRAY_SOURCE_DIR) +
                                             "/scenes/toon.json --width 40 --height 30 -q "
                                             "--samples 4 8 -o " +
                                             path("toon.exr"))
                .exit_code,
            0);
  ASSERT_EQ(render("--samples 0 4 --crop 0 0 20 30 -o " + path("left.exr")).exit_code, 0);
  ASSERT_EQ(render("--spp 1 -o " + path("image.exr")).exit_code, 0);

  const auto refused = [&](const std::string& args, const std::string& expected) {
    const RunResult r = merge(path("out.png") + " " + args);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(expected), std::string::npos) << r.output;
    EXPECT_EQ(lines_of(r.output), 1u) << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
    return r.output;
  };
  std::string out = refused(path("a.exr") + " " + path("seed.exr"), "seed 0 vs 3");
  EXPECT_NE(out.find("a.exr"), std::string::npos);
  EXPECT_NE(out.find("seed.exr"), std::string::npos);
  refused(path("a.exr") + " " + path("toon.exr"), "the scene differs at");
  refused(path("a.exr") + " " + path("overlap.exr"), "both hold samples 2-4");
  refused(path("left.exr"), "pixels are in no partial");
  refused(path("image.exr"), "not an inkray partial");
  std::ofstream(dir_ / "garbage.exr") << "garbage";
  refused(path("garbage.exr"), "not an OpenEXR file");
  std::string bytes;
  {
    std::ifstream in(dir_ / "a.exr", std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    bytes = s.str();
  }
  std::ofstream(dir_ / "truncated.exr", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  refused(path("truncated.exr"), "truncated.exr");
}

TEST_F(FinalRender, FramesFollowThePatternAndResumeSkipsDoneOnes) {
  RunResult r =
      render("--frames 1-3 -o " + path("f_##.pfm") + " --aov depth=" + path("d_###.pfm") + " --spp 1");
  // -q keeps the frame lines out; without it each frame prints one.
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"f_01.pfm", "f_02.pfm", "f_03.pfm", "d_001.pfm", "d_002.pfm", "d_003.pfm"})
    EXPECT_TRUE(fs::exists(dir_ / f)) << f;
  const std::string scene =
      std::string(INKRAY_SOURCE_DIR) + "/scenes/cornell_outlines.json --width 40 --height 30 ";
  r = run_program("inkray-render", scene + "--frames 2-6:2 --spp 1 -o " + path("g_####.pfm"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "g_0002.pfm"));
  EXPECT_TRUE(fs::exists(dir_ / "g_0004.pfm"));
  EXPECT_TRUE(fs::exists(dir_ / "g_0006.pfm"));
  EXPECT_FALSE(fs::exists(dir_ / "g_0003.pfm"));
  EXPECT_NE(r.output.find("frame 4: "), std::string::npos) << r.output;
  EXPECT_EQ(lines_of(r.output), 3u) << r.output;

  fs::remove(dir_ / "d_002.pfm");
  r = run_program("inkray-render", scene + "--frames 1-3 --spp 1 --resume -o " + path("f_##.pfm") +
                                       " --aov depth=" + path("d_###.pfm"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("frame 1: " + path("f_01.pfm") + " exists, skipped"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("frame 2: " + path("f_02.pfm") + ", 1 spp"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("frame 3: " + path("f_03.pfm") + " exists, skipped"), std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "d_002.pfm"));

  // Each frame's partial says which frame it is: frames do not merge.
  ASSERT_EQ(render("--frames 2 --samples 0 2 -o " + path("p2.exr")).exit_code, 0);
  ASSERT_EQ(render("--frames 3 --samples 2 4 -o " + path("p3.exr")).exit_code, 0);
  r = merge(path("out.pfm") + " " + path("p2.exr") + " " + path("p3.exr"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("frame 2 vs 3"), std::string::npos) << r.output;
}

TEST_F(FinalRender, BadArgumentsAreOneLineAndStatusTwo) {
  const auto bad = [&](const RunResult& r, const std::string& expected) {
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(expected), std::string::npos) << r.output;
    EXPECT_EQ(lines_of(r.output), 1u) << r.output;
  };
  const std::string out = " -o " + path("x.exr");
  bad(render("--samples 8 4" + out), "B must be above A");
  bad(render("--samples 0 4 -o " + path("x.png")), "must end in .exr");
  bad(render("--samples 0 4 --spp 8" + out), "leave out --spp");
  bad(render("--samples 0 4 --aov depth=" + path("d.exr") + out), "give only --aov depth");
  bad(render("--aov depth" + out), "expected NAME=FILE");
  bad(render("--crop 5 5 5 9" + out), "X1 > X0");
  bad(render("--crop 0 0 41 30" + out), "not inside the 40x30 image");
  bad(render("--frames 3-1" + out), "--frames");
  bad(render("--frames 1-x" + out), "--frames");
  bad(render("--frames 1-3" + out), "needs a run of '#'");
  bad(render("--frames 1-3 -o " + path("f_#.png") + " --aov depth=" + path("d.pfm")), "--aov depth=");
  bad(render("--checkpoint 0" + out), "--checkpoint");
  bad(merge(path("x.png")), "at least one partial");
  bad(merge(path("x.txt") + " " + path("a.exr")), "unknown image format");
  bad(merge(path("x.png") + " " + path("a.exr") + " --frobnicate"), "unknown option");
  bad(merge(path("x.partial.exr") + " " + path("a.exr") + " --aov depth=" + path("d.pfm")), "--aov");
}

}  // namespace
}  // namespace inkray
