// The recovery file's origin note is replaced atomically like the recovery file itself,
// reports why it failed, and temporaries a killed editor left are removed at start-up.
#include "ui/model/autosave.h"

#include "support/file_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/stat.h>

namespace inkray {
namespace {

namespace fs = std::filesystem;
using namespace inkray::testing;

ino_t inode_of(const fs::path& file) {
  struct stat st {};
  ::stat(file.c_str(), &st);
  return st.st_ino;
}

TEST(AutosaveFiles, OriginNoteIsReplacedNotTruncated) {
  ScratchFolder dir;
  Autosave autosave(dir / "recovery.json", std::chrono::seconds(60));
  SceneDesc scene;
  scene.base_dir = dir / "assets";
  std::string error;
  ASSERT_TRUE(autosave.write(scene, dir / "first.json", &error)) << error;
  const fs::path note = dir / "recovery.json.origin";
  const std::string first = (dir / "first.json").string() + "\n" + (dir / "assets").string() + "\n";
  EXPECT_EQ(read_file(note), first);

  // A reader that opened the old note (a second editor starting up) still reads all of it.
  std::ifstream reader(note);
  const ino_t before = inode_of(note);
  ASSERT_TRUE(autosave.write(scene, dir / "second.json", &error)) << error;
  std::stringstream old_text;
  old_text << reader.rdbuf();
  EXPECT_EQ(old_text.str(), first);
  EXPECT_NE(inode_of(note), before);
  EXPECT_EQ(read_file(note), (dir / "second.json").string() + "\n" + (dir / "assets").string() + "\n");
  EXPECT_EQ(dir.entries(), (Names{"recovery.json", "recovery.json.origin"}));
}

TEST(AutosaveFiles, AFailedOriginNoteSaysWhy) {
  ScratchFolder dir;
  fs::create_directory(dir / "recovery.json.origin");
  Autosave autosave(dir / "recovery.json", std::chrono::seconds(60));
  std::string error;
  EXPECT_FALSE(autosave.write(SceneDesc{}, dir / "doc.json", &error));
  EXPECT_EQ(error, "cannot replace " + (dir / "recovery.json.origin").string() + ": Is a directory");
}

TEST(AutosaveFiles, FindingRecoveryRemovesTemporariesOfAKilledEditor) {
  ScratchFolder dir;
  const std::string tag = ".inkray-tmp-" + std::to_string(dead_pid()) + "-00000001";
  const std::string live = ".recovery.json.inkray-tmp-" + std::to_string(::getpid()) + "-00000001";
  for (const std::string& name : {".recovery.json" + tag, ".recovery.json.origin" + tag, live})
    write_file(dir / name, "partial");
  write_file(dir / "recovery.json.tmp-a1b2c3", "partial");
  testing::make_older(dir / "recovery.json.tmp-a1b2c3", std::chrono::minutes(10));
  Autosave autosave(dir / "recovery.json", std::chrono::seconds(60));
  EXPECT_FALSE(autosave.find());
  EXPECT_EQ(dir.entries(), Names{live});
}

}  // namespace
}  // namespace inkray
