// Output sets: every file staged before any is replaced, nothing touched when one fails,
// and the up-front check of output paths that inkray-render and the export run.
#include "core/io/output_set.h"

#include "support/file_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace inkray {
namespace {

namespace fs = std::filesystem;
using namespace inkray::testing;

TEST(OutputSet, NothingIsReplacedUntilCommit) {
  ScratchFolder dir;
  write_file(dir / "image.png", "old image");
  OutputSet set;
  std::string error;
  ASSERT_TRUE(set.stage(dir / "image.png", "new image", &error)) << error;
  ASSERT_TRUE(set.stage(dir / "depth.exr", "depth", &error)) << error;
  EXPECT_EQ(read_file(dir / "image.png"), "old image");
  EXPECT_FALSE(fs::exists(dir / "depth.exr"));
  EXPECT_EQ(dir.entries().size(), 3u);  // the old image and two temporaries
  ASSERT_TRUE(set.commit(&error)) << error;
  EXPECT_EQ(read_file(dir / "image.png"), "new image");
  EXPECT_EQ(read_file(dir / "depth.exr"), "depth");
  EXPECT_EQ(dir.entries(), (Names{"depth.exr", "image.png"}));
}

TEST(OutputSet, AFailedStageLeavesEveryTargetUntouched) {
  ScratchFolder dir;
  write_file(dir / "image.png", "old image");
  std::string error;
  {
    OutputSet set;
    ASSERT_TRUE(set.stage(dir / "image.png", "new image", &error)) << error;
    EXPECT_FALSE(set.stage(dir / "missing" / "depth.exr", "depth", &error));
    EXPECT_NE(error.find((dir / "missing" / "depth.exr").string()), std::string::npos) << error;
    EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
  }  // dropped without commit
  EXPECT_EQ(read_file(dir / "image.png"), "old image");
  EXPECT_EQ(dir.entries(), Names{"image.png"});
}

TEST(OutputSet, TheSameFileTwiceIsRefused) {
  ScratchFolder dir;
  fs::create_symlink("out.png", dir / "link.png");
  OutputSet set;
  std::string error;
  ASSERT_TRUE(set.stage(dir / "out.png", "image", &error)) << error;
  EXPECT_FALSE(set.stage(dir.path() / "." / "out.png", "depth", &error));
  EXPECT_NE(error.find("the same file as " + (dir / "out.png").string()), std::string::npos) << error;
  EXPECT_FALSE(set.stage(dir / "link.png", "depth", &error));
  EXPECT_NE(error.find("the same file as"), std::string::npos) << error;
  set.discard();
  EXPECT_EQ(dir.entries(), Names{"link.png"});
}

TEST(OutputSet, ARenameFailureSaysWhatWasAlreadyReplaced) {
  ScratchFolder dir;
  OutputSet set;
  std::string error;
  ASSERT_TRUE(set.stage(dir / "a.png", "a", &error)) << error;
  ASSERT_TRUE(set.stage(dir / "b.png", "b", &error)) << error;
  ASSERT_TRUE(set.stage(dir / "c.png", "c", &error)) << error;
  fs::create_directory(dir / "b.png");  // the folder changed after staging
  EXPECT_FALSE(set.commit(&error));
  EXPECT_EQ(error, "cannot replace " + (dir / "b.png").string() +
                       ": Is a directory (already replaced: " + (dir / "a.png").string() + ")");
  EXPECT_EQ(dir.entries(), (Names{"a.png", "b.png"}));  // c's temporary is gone too
}

TEST(OutputSet, StagingCleansStaleTemporariesOfItsTargets) {
  ScratchFolder dir;
  const std::string stale = ".a.png.inkray-tmp-" + std::to_string(testing::dead_pid()) + "-00c0ffee";
  write_file(dir / stale, "half an image");
  OutputSet set;
  std::string error;
  ASSERT_TRUE(set.stage(dir / "a.png", "a", &error)) << error;
  ASSERT_TRUE(set.commit(&error)) << error;
  EXPECT_EQ(dir.entries(), Names{"a.png"});
}

TEST(CheckOutputs, AcceptsDistinctWritableFiles) {
  ScratchFolder dir;
  write_file(dir / "out.png", "an older render, to be replaced");
  EXPECT_EQ(check_outputs({{"-o", dir / "out.png"}, {"--aov depth", dir / "z.exr"}}), "");
}

TEST(CheckOutputs, NamesTheOutputAndWhatIsWrong) {
  ScratchFolder dir;
  fs::create_directory(dir / "taken.png");
  write_file(dir / "file", "");
  fs::create_symlink("out.png", dir / "link.png");
  const std::string out = (dir / "out.png").string();
  struct Case {
    fs::path file;
    std::string expected;
  };
  for (const Case& c :
       {Case{dir / "missing" / "z.exr", "--aov x: folder " + (dir / "missing").string() + " does not exist"},
        Case{dir / "taken.png", "--aov x: " + (dir / "taken.png").string() + " is a folder"},
        Case{dir / "file" / "z.exr", "--aov x: " + (dir / "file").string() + " is not a folder"},
        Case{dir / "out.png", "--aov x: the same file as -o"},
        Case{dir.path() / "." / "out.png", "--aov x: the same file as -o"},
        // Not the same file as out.png: sub/ does not exist, so the path goes nowhere.
        Case{dir.path() / "sub" / ".." / "out.png",
             "--aov x: folder " + (dir.path() / "sub" / "..").string() + " does not exist"},
        Case{dir / "link.png", "--aov x: the same file as -o"}}) {
    EXPECT_EQ(check_outputs({{"-o", dir / "out.png"}, {"--aov x", c.file}}), c.expected) << c.file;
  }
  EXPECT_EQ(check_outputs({{"-o", "/dev/null"}}), "-o: /dev/null is not a regular file");
}

}  // namespace
}  // namespace inkray
