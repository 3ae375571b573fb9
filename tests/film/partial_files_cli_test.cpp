// Partials, checkpoints and line decisions between inkray processes, end to end: a mesh
// changed between two slices, a FIFO or a device given as a partial, and headers nested
// 100,000 deep are each refused by inkray-merge and inkray-render with one line, exit 1.
#include "core/film/film_partial.h"
#include "core/film/line_decisions_file.h"
#include "core/io/atomic_file.h"

#include "tests/support/program_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>

namespace inkray {
namespace {

namespace fs = std::filesystem;
using testing::RunResult;
using testing::ScratchFolder;

// Under `timeout`, so a reader that blocks (on a FIFO) fails the test instead of hanging
// it: timeout's own status, 124, is then the exit code.
RunResult run_cli(const std::string& program, const std::string& args) {
  return testing::run_program(program, args, "timeout 60 ");
}

size_t lines_of(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

// A one-mesh scene beside its mesh, meshes/m.obj (a copy of the test cube).
class PartialFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir_ / "meshes");
    fs::copy_file(fs::path(INKRAY_SOURCE_DIR) / "tests/data/scenes/valid/meshes/cube.obj",
                  dir_ / "meshes/m.obj");
    std::ofstream(dir_ / "scene.json") << R"({"format": "inkray-scene", "version": 1,
      "camera": {"look_from": [2, 3, -5], "look_at": [0, 0, 0], "up": [0, 1, 0], "vfov": 40},
      "render": {"width": 16, "height": 12, "spp": 4},
      "environment": {"type": "constant", "color": 0.5},
      "materials": [{"name": "white", "type": "diffuse", "albedo": 0.7}],
      "objects": [{"name": "m", "material": "white", "shape": {"type": "mesh", "path": "meshes/m.obj"}}]})";
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  RunResult render(const std::string& args) const {
    return run_cli("inkray-render", path("scene.json") + " -q " + args);
  }
  ScratchFolder dir_;
};

TEST_F(PartialFiles, MergeRefusesAMeshChangedBetweenSlices) {
  ASSERT_EQ(render("--samples 0 2 -o " + path("a.exr")).exit_code, 0);
  ASSERT_EQ(render("--samples 2 4 -o " + path("b.exr")).exit_code, 0);
  RunResult r = run_cli("inkray-merge", path("same.pfm") + " " + path("a.exr") + " " + path("b.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.output;  // the slices of one scene merge

  // The same scene file, the mesh's bytes changed (one vertex moved) before the second slice.
  std::string mesh = testing::read_file(dir_ / "meshes/m.obj");
  const size_t v = mesh.find("\nv ");
  ASSERT_NE(v, std::string::npos);
  mesh.insert(v + 3, "0.5");
  std::ofstream(dir_ / "meshes/m.obj", std::ios::binary | std::ios::trunc) << mesh;
  ASSERT_EQ(render("--samples 2 4 -o " + path("c.exr")).exit_code, 0);
  r = run_cli("inkray-merge", path("changed.pfm") + " " + path("a.exr") + " " + path("c.exr"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("a.exr and " + path("c.exr") +
                          " are of different renders: the asset meshes/m.obj "
                          "changed between them"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(lines_of(r.output), 1u) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "changed.pfm"));

  // A checkpoint of the old mesh does not resume a render of the new one.
  fs::copy_file(dir_ / "a.exr", dir_ / "r.pfm.checkpoint.exr");
  r = render("--spp 4 --resume -o " + path("r.pfm"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("cannot resume this render from it: the asset meshes/m.obj changed"),
            std::string::npos)
      << r.output;
}

// Neither is read: /dev/zero never ends and opening a FIFO waits for a writer forever.
TEST_F(PartialFiles, MergeRefusesDevicesAndFifosPromptly) {
  ASSERT_EQ(render("--samples 0 4 -o " + path("a.exr")).exit_code, 0);
  RunResult r = run_cli("inkray-merge", path("out.pfm") + " " + path("a.exr") + " /dev/zero");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("/dev/zero: not a regular file (a character device)"), std::string::npos)
      << r.output;
  ASSERT_EQ(::mkfifo(path("fifo.exr").c_str(), 0600), 0);
  r = run_cli("inkray-merge", path("out.pfm") + " " + path("fifo.exr"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("fifo.exr: not a regular file (a FIFO)"), std::string::npos) << r.output;
  r = render("--samples 0 4 --line-decisions " + path("fifo.exr") + " -o " + path("b.exr"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("fifo.exr: not a regular file (a FIFO)"), std::string::npos) << r.output;
}

// A scene nested 100,000 deep in a partial's, a checkpoint's and a decision file's header
// (each sealed, as a file written by something else would be): refused, not a stack overflow.
TEST_F(PartialFiles, DeepHeadersAreRefusedByMergeResumeAndLineDecisions) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  Film film(16, 12, {}, false);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 16; ++x) film.add_sample(x, y, 0, Color(0.5f));
  PartialInfo info;
  info.width = 16;
  info.height = 12;
  info.window = {0, 0, 16, 12};
  info.end_pass = 1;
  info.scene = deep;
  std::string bytes, error;
  ASSERT_TRUE(encode_partial(film, info, &bytes, &error)) << error;
  ASSERT_TRUE(write_file_atomically(dir_ / "deep.exr", bytes, &error)) << error;
  ASSERT_TRUE(write_file_atomically(dir_ / "r.pfm.checkpoint.exr", bytes, &error)) << error;
  LineDecisions decisions;
  decisions.width = 16;
  decisions.height = 12;
  ASSERT_TRUE(write_file_atomically(dir_ / "lines.bin", encode_line_decisions(decisions, info), &error))
      << error;

  RunResult r = run_cli("inkray-merge", path("out.pfm") + " " + path("deep.exr"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("deep.exr: attribute inkray.scene nests deeper than 256 levels"), std::string::npos)
      << r.output;
  r = render("--spp 4 --resume -o " + path("r.pfm"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("nests deeper than 256 levels"), std::string::npos) << r.output;
  r = render("--samples 0 4 --line-decisions " + path("lines.bin") + " -o " + path("b.exr"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("lines.bin: header: the scene nests deeper than 256 levels"), std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace inkray
