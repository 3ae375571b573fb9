// Every writer of files (scenes, PNG, PFM and EXR images) goes through core/io's atomic
// replacement: the same symlink policy, the same messages, and temporaries of killed
// saves cleaned up at the next save.
#include "core/image/image_io.h"
#include "core/io/atomic_file.h"
#include "core/document/json_io.h"

#include "support/file_helpers.h"

#include <gtest/gtest.h>
#include <tinyexr.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>

namespace inkray {
namespace {

namespace fs = std::filesystem;
using namespace inkray::testing;

RgbImage test_image() {
  return RgbImage{
      3, 2, {Color(0.f), Color(1.f, 2.f, 3.f), Color(0.5f), Color(4.f), Color(0.25f), Color(7.f)}};
}

// Writes `file` with the writer its extension picks: save_scene for .json, else write_image.
bool write_any(const fs::path& file, std::string* error) {
  if (file.extension() == ".json") return save_scene(SceneDesc{}, file, error);
  return write_image(file, test_image(), error);
}

TEST(FileWriters, EveryWriterReplacesTheFileALinkNames) {
  ScratchFolder dir;
  fs::create_directory(dir / "real");
  for (const std::string name : {"a.png", "a.pfm", "a.exr", "a.json"}) {
    SCOPED_TRACE(name);
    write_file(dir / "real" / name, "old");
    fs::create_symlink("real/" + name, dir / name);
    std::string error;
    ASSERT_TRUE(write_any(dir / name, &error)) << error;
    EXPECT_TRUE(fs::is_symlink(dir / name));
    EXPECT_NE(read_file(dir / "real" / name), "old");
  }
  RgbImage back;
  std::string error;
  EXPECT_TRUE(read_image(dir / "a.png", true, &back, &error)) << error;
  EXPECT_TRUE(read_pfm(dir / "a.pfm", &back, &error)) << error;
  EXPECT_EQ(back.pixels, test_image().pixels);
  EXPECT_EQ(read_file(dir / "real" / "a.json"), scene_to_string(SceneDesc{}));
  EXPECT_EQ(dir.entries(), (Names{"a.exr", "a.json", "a.pfm", "a.png", "real"}));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir / "real"), {}), 4);  // no temporaries
}

TEST(FileWriters, EveryWriterGivesTheSameMessages) {
  ScratchFolder dir;
  for (const std::string name : {"a.png", "a.pfm", "a.exr", "a.json"}) {
    SCOPED_TRACE(name);
    fs::create_directory(dir / name);
    std::string error;
    EXPECT_FALSE(write_any(dir / name, &error));
    EXPECT_EQ(error, "cannot replace " + (dir / name).string() + ": Is a directory");
    EXPECT_FALSE(write_any(dir / "missing" / name, &error));
    EXPECT_EQ(error, "cannot write " + (dir / "missing" / name).string() +
                         ": cannot create a temporary file in " + (dir / "missing").string() +
                         ": No such file or directory");
  }
  EXPECT_EQ(dir.entries(), (Names{"a.exr", "a.json", "a.pfm", "a.png"}));
}

TEST(FileWriters, ExrIsEncodedInMemoryAndWrittenAsIs) {
  ScratchFolder dir;
  RgbImage image{20, 17, {}};
  for (int i = 0; i < 20 * 17; ++i) image.pixels.push_back(Color(float(i), 0.5f * float(i), -1.f));
  std::string bytes, error;
  ASSERT_TRUE(encode_image(dir / "a.exr", image, &bytes, &error)) << error;
  ASSERT_TRUE(write_image(dir / "a.exr", image, &error)) << error;
  EXPECT_EQ(read_file(dir / "a.exr"), bytes);
  float* rgba = nullptr;
  int w = 0, h = 0;
  const char* err = nullptr;
  ASSERT_EQ(LoadEXRFromMemory(&rgba, &w, &h, reinterpret_cast<const unsigned char*>(bytes.data()),
                              bytes.size(), &err),
            TINYEXR_SUCCESS)
      << (err ? err : "");
  ASSERT_EQ(w, 20);
  ASSERT_EQ(h, 17);
  for (int i = 0; i < w * h; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(rgba[4 * i + c], image.pixels[size_t(i)][c]) << i;
  std::free(rgba);
  EXPECT_FALSE(encode_image(dir / "a.bmp", image, &bytes, &error));
  EXPECT_NE(error.find("unknown image format"), std::string::npos);
}

TEST(FileWriters, SceneSaveRemovesTemporariesOfKilledSaves) {
  ScratchFolder dir;
  const std::string dead = ".scene.json.inkray-tmp-" + std::to_string(dead_pid()) + "-0badf00d";
  const std::string live = ".scene.json.inkray-tmp-" + std::to_string(::getpid()) + "-0badf00d";
  for (const std::string& name : {dead, live, std::string("scene.json.tmp-abcdef")})
    write_file(dir / name, std::string(1 << 16, '{'));
  make_older(dir / "scene.json.tmp-abcdef", std::chrono::minutes(5));
  std::string error;
  ASSERT_TRUE(save_scene(SceneDesc{}, dir / "scene.json", &error)) << error;
  EXPECT_EQ(dir.entries(), (Names{live, "scene.json"}));  // a live writer's temporary is never touched
}

// A real writer killed between writing its temporary and the rename: the child stages
// a scene and is killed; the next save clears what it left.
TEST(FileWriters, KilledSaveLeavesNothingAfterTheNextSave) {
  ScratchFolder dir;
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    StagedFile staged;
    std::string e;
    if (staged.stage(dir / "scene.json", std::string(4 << 20, ' '), &e)) ::raise(SIGKILL);
    ::_exit(1);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  ASSERT_EQ(dir.entries().size(), 1u);  // the killed writer's temporary
  std::string error;
  ASSERT_TRUE(save_scene(SceneDesc{}, dir / "scene.json", &error)) << error;
  EXPECT_EQ(dir.entries(), Names{"scene.json"});
}

}  // namespace
}  // namespace inkray
