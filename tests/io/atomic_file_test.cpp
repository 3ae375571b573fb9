// Atomic file replacement: the temporary, its clean-up on every failure, messages that
// keep their cause, symbolic links, and the removal of temporaries killed writers left.
#include "core/io/atomic_file.h"

#include "support/file_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace inkray {
namespace {

namespace fs = std::filesystem;
using namespace inkray::testing;

class AtomicFile : public InScratchFolder {};

TEST_F(AtomicFile, WritesAndReplacesLeavingNoTemporary) {
  ASSERT_TRUE(write_file_atomically(dir / "a.txt", "first", &error)) << error;
  EXPECT_EQ(read_file(dir / "a.txt"), "first");
  ASSERT_TRUE(write_file_atomically(dir / "a.txt", std::string(1 << 20, 'x'), &error)) << error;
  EXPECT_EQ(read_file(dir / "a.txt"), std::string(1 << 20, 'x'));
  EXPECT_EQ(dir.entries(), Names{"a.txt"});
}

TEST_F(AtomicFile, KeepsThePermissionsOfTheReplacedFile) {
  write_file(dir / "a.txt", "old");
  fs::permissions(dir / "a.txt", fs::perms::owner_read | fs::perms::group_read);
  ASSERT_TRUE(write_file_atomically(dir / "a.txt", "new", &error)) << error;
  EXPECT_EQ(fs::status(dir / "a.txt").permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::group_read);
  EXPECT_EQ(read_file(dir / "a.txt"), "new");
}

TEST_F(AtomicFile, ReplacesANewInodeSoOpenReadersKeepTheOldFile) {
  write_file(dir / "a.txt", "old contents");
  std::ifstream reader(dir / "a.txt");
  ASSERT_TRUE(write_file_atomically(dir / "a.txt", "new", &error)) << error;
  std::string seen;
  std::getline(reader, seen);
  EXPECT_EQ(seen, "old contents");  // a truncating write would have emptied it under the reader
}

TEST_F(AtomicFile, RenameFailureKeepsTheCauseAndRemovesTheTemporary) {
  StagedFile staged;
  ASSERT_TRUE(staged.stage(dir / "out.png", "bytes", &error)) << error;
  EXPECT_TRUE(fs::exists(staged.temporary()));
  fs::create_directory(dir / "out.png");  // appears between staging and the rename
  EXPECT_FALSE(staged.commit(&error));
  EXPECT_EQ(error, "cannot replace " + (dir / "out.png").string() + ": Is a directory");
  EXPECT_EQ(dir.entries(), Names{"out.png"});
  EXPECT_TRUE(fs::is_empty(dir / "out.png"));
}

TEST_F(AtomicFile, FailuresNameTheFileAndTheCause) {
  fs::create_directory(dir / "taken");
  EXPECT_FALSE(write_file_atomically(dir / "taken", "x", &error));
  EXPECT_EQ(error, "cannot replace " + (dir / "taken").string() + ": Is a directory");

  EXPECT_FALSE(write_file_atomically(dir / "missing" / "a.txt", "x", &error));
  EXPECT_NE(error.find("cannot write " + (dir / "missing" / "a.txt").string()), std::string::npos) << error;
  EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;

  write_file(dir / "file", "");
  EXPECT_FALSE(write_file_atomically(dir / "file" / "a.txt", "x", &error));
  EXPECT_NE(error.find("Not a directory"), std::string::npos) << error;

  EXPECT_EQ(dir.entries(), (Names{"file", "taken"}));
}

TEST_F(AtomicFile, DroppingAStagedFileRemovesItsTemporary) {
  write_file(dir / "a.txt", "old");
  {
    StagedFile staged;
    ASSERT_TRUE(staged.stage(dir / "a.txt", "new", &error)) << error;
    EXPECT_EQ(dir.entries().size(), 2u);
    StagedFile moved = std::move(staged);  // the temporary follows the move, removed once
    EXPECT_FALSE(staged.staged());
    EXPECT_TRUE(moved.staged());
  }
  EXPECT_EQ(dir.entries(), Names{"a.txt"});
  EXPECT_EQ(read_file(dir / "a.txt"), "old");
}

TEST_F(AtomicFile, WritingThroughASymlinkReplacesItsTarget) {
  fs::create_directory(dir / "real");
  write_file(dir / "real" / "scene.json", "old");
  fs::create_symlink("real/scene.json", dir / "link.json");
  fs::create_symlink("link.json", dir / "link2.json");  // a chain of links
  ASSERT_TRUE(write_file_atomically(dir / "link2.json", "new", &error)) << error;
  EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
  EXPECT_TRUE(fs::is_symlink(dir / "link2.json"));
  EXPECT_EQ(read_file(dir / "real" / "scene.json"), "new");
  EXPECT_EQ(dir.entries(), (Names{"link.json", "link2.json", "real"}));

  // A dangling link creates the file it names, as a shell redirection would.
  fs::create_symlink("real/fresh.json", dir / "dangling.json");
  ASSERT_TRUE(write_file_atomically(dir / "dangling.json", "fresh", &error)) << error;
  EXPECT_TRUE(fs::is_symlink(dir / "dangling.json"));
  EXPECT_EQ(read_file(dir / "real" / "fresh.json"), "fresh");
}

TEST_F(AtomicFile, LinkLoopsFailWithTheCause) {
  fs::create_symlink("b", dir / "a");
  fs::create_symlink("a", dir / "b");
  EXPECT_FALSE(write_file_atomically(dir / "a", "x", &error));
  EXPECT_NE(error.find((dir / "a").string()), std::string::npos) << error;
  EXPECT_NE(error.find("Too many levels of symbolic links"), std::string::npos) << error;
  EXPECT_EQ(dir.entries(), (Names{"a", "b"}));
}

TEST_F(AtomicFile, TemporariesAreHiddenAndCarryThePid) {
  StagedFile staged;
  ASSERT_TRUE(staged.stage(dir / "a.json", "x", &error)) << error;
  const std::string name = staged.temporary().filename().string();
  EXPECT_EQ(name.rfind(".a.json.inkray-tmp-" + std::to_string(::getpid()) + "-", 0), 0u) << name;
  EXPECT_EQ(staged.temporary().parent_path(), dir.path());
  long pid = 0;
  EXPECT_TRUE(is_temporary_of(dir / "a.json", name, &pid));
  EXPECT_EQ(pid, ::getpid());
  EXPECT_FALSE(is_temporary_of(dir / "b.json", name, &pid));
  EXPECT_TRUE(is_temporary_of(dir / "a.json", "a.json.tmp-0a1b2c", &pid));  // save_scene's old form
  EXPECT_EQ(pid, 0);
  EXPECT_TRUE(is_temporary_of(dir / "a.json", "a.json.tmp-0a1b2c3d", &pid));  // write_image's old form
  for (const char* other :
       {"a.json.tmp-0a1b2", "a.json.tmp-0A1B2C", "a.json.tmp-0a1b2cx", ".a.json.inkray-tmp-0-0a1b2c3d",
        ".a.json.inkray-tmp--5-0a1b2c3d", ".a.json.inkray-tmp-12-xyz", "a.json", "a.json~"})
    EXPECT_FALSE(is_temporary_of(dir / "a.json", other, &pid)) << other;
}

TEST_F(AtomicFile, LongNamesStillFitTheTemporary) {
  const std::string name(250, 'n');
  ASSERT_TRUE(write_file_atomically(dir / name, "x", &error)) << error;
  EXPECT_EQ(dir.entries(), Names{name});
}

TEST_F(AtomicFile, RemovesOnlyTemporariesOfDeadWriters) {
  write_file(dir / "x.json", "scene");
  const std::string dead = ".x.json.inkray-tmp-" + std::to_string(dead_pid()) + "-0123abcd";
  const std::string live = ".x.json.inkray-tmp-" + std::to_string(::getpid()) + "-0123abcd";
  const std::string other_file = ".y.json.inkray-tmp-" + std::to_string(dead_pid()) + "-0123abcd";
  for (const std::string& name :
       {dead, live, other_file, std::string("x.json.tmp-abcdef"), std::string("x.json.tmp-12345678"),
        std::string("x.json.tmp-fedcba"), std::string("x.json.tmp-notes")})
    write_file(dir / name, "partial");
  make_older(dir / "x.json.tmp-abcdef", std::chrono::minutes(2));
  make_older(dir / "x.json.tmp-12345678", std::chrono::minutes(2));
  make_older(dir / "x.json.tmp-notes", std::chrono::minutes(2));
  // x.json.tmp-fedcba is fresh: an old-style save may still be writing it.
  fs::create_directory(dir / (".x.json.inkray-tmp-" + std::to_string(dead_pid()) + "-00000000"));

  EXPECT_EQ(remove_stale_temporaries(dir / "x.json"), 3);
  EXPECT_FALSE(fs::exists(dir / dead));
  EXPECT_FALSE(fs::exists(dir / "x.json.tmp-abcdef"));
  EXPECT_FALSE(fs::exists(dir / "x.json.tmp-12345678"));
  EXPECT_TRUE(fs::exists(dir / live));
  EXPECT_TRUE(fs::exists(dir / other_file));
  EXPECT_TRUE(fs::exists(dir / "x.json.tmp-fedcba"));
  EXPECT_TRUE(fs::exists(dir / "x.json.tmp-notes"));
  EXPECT_EQ(read_file(dir / "x.json"), "scene");
  EXPECT_EQ(dir.entries().size(), 6u);  // the folder with a temporary's name is not a temporary
}

TEST_F(AtomicFile, StaleTemporariesAreLookedForBesideTheLinkedFile) {
  fs::create_directory(dir / "real");
  fs::create_symlink("real/x.json", dir / "x.json");
  const std::string dead = ".x.json.inkray-tmp-" + std::to_string(dead_pid()) + "-0123abcd";
  write_file(dir / "real" / dead, "partial");
  EXPECT_EQ(remove_stale_temporaries(dir / "x.json"), 1);
  EXPECT_FALSE(fs::exists(dir / "real" / dead));
}

}  // namespace
}  // namespace inkray
