// The journal of an output set's renames: a live commit's journal is never touched, a
// dead one's is completed by the next writer into its folder so the new set wins whole,
// and what cannot be completed is said.
#include "core/io/commit_journal.h"
#include "core/io/atomic_file.h"
#include "core/io/output_set.h"
#include "core/io/posix_file.h"

#include "support/file_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace inkray {
namespace {

namespace fs = std::filesystem;
using namespace inkray::testing;

// In a child process: stages every file with "new <name>", writes the journal, renames the
// first `renamed` files and dies (its lock goes with it), as a kill between renames would
// leave them. `lose`, when not empty, is a file whose temporary is deleted before dying.
void commit_part_way_and_die(const std::vector<fs::path>& files, size_t renamed, const fs::path& lose = {}) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::vector<StagedFile> staged(files.size());
    std::vector<JournalEntry> entries;
    for (size_t i = 0; i < files.size(); ++i) {
      if (!staged[i].stage(files[i], "new " + files[i].filename().string(), nullptr)) ::_exit(1);
      entries.push_back({staged[i].temporary(), staged[i].destination()});
    }
    CommitJournal journal;
    if (!journal.begin(entries, nullptr)) ::_exit(2);
    for (size_t i = 0; i < renamed; ++i)
      if (!staged[i].commit(nullptr)) ::_exit(3);
    for (size_t i = 0; i < files.size(); ++i)
      if (files[i] == lose) ::unlink(staged[i].temporary().c_str());
    ::_exit(0);  // no destructors: the temporaries and the journal stay
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

size_t temporaries_in(const ScratchFolder& dir) {
  size_t n = 0;
  for (const std::string& name : dir.entries())
    if (name.find(".inkray-tmp-") != std::string::npos || name.find(".inkray-journal") != std::string::npos)
      ++n;
  return n;
}

TEST(CommitJournal, AKilledCommitIsCompletedByTheNextWriterIntoTheFolder) {
  for (size_t renamed = 0; renamed <= 3; ++renamed) {
    SCOPED_TRACE(renamed);
    ScratchFolder dir;
    for (const char* name : {"a.png", "b.exr", "c.exr"}) write_file(dir / name, std::string("old ") + name);
    commit_part_way_and_die({dir / "a.png", dir / "b.exr", dir / "c.exr"}, renamed);
    EXPECT_TRUE(fs::exists(dir / ".a.png.inkray-journal"));
    EXPECT_EQ(temporaries_in(dir), 4 - renamed);  // the journal and the temporaries not renamed yet

    // Any writer into the folder, of any file, completes the set first.
    std::string error;
    ASSERT_TRUE(write_file_atomically(dir / "notes.txt", "x", &error)) << error;
    EXPECT_EQ(dir.entries(), (Names{"a.png", "b.exr", "c.exr", "notes.txt"}));
    EXPECT_EQ(read_file(dir / "a.png"), "new a.png");
    EXPECT_EQ(read_file(dir / "b.exr"), "new b.exr");
    EXPECT_EQ(read_file(dir / "c.exr"), "new c.exr");
  }
}

TEST(CommitJournal, AJournalOfALiveCommitIsLeftAlone) {
  ScratchFolder dir;
  StagedFile a, b;
  std::string error;
  ASSERT_TRUE(a.stage(dir / "a.png", "new a", &error)) << error;
  ASSERT_TRUE(b.stage(dir / "b.png", "new b", &error)) << error;
  CommitJournal journal;
  ASSERT_TRUE(journal.begin({{a.temporary(), a.destination()}, {b.temporary(), b.destination()}}, &error))
      << error;
  EXPECT_EQ(journal.file(), dir / ".a.png.inkray-journal");
  EXPECT_FALSE(recover_journal(journal.file()));  // locked: its writer lives
  EXPECT_EQ(remove_stale_temporaries(dir / "a.png"), 0);
  EXPECT_EQ(dir.entries().size(), 3u);
  ASSERT_TRUE(a.commit(&error)) << error;
  ASSERT_TRUE(b.commit(&error)) << error;
  journal.finish();
  EXPECT_EQ(dir.entries(), (Names{"a.png", "b.png"}));
}

TEST(CommitJournal, OutputSetsLeaveNoJournal) {
  ScratchFolder dir;
  OutputSet set;
  std::string error;
  ASSERT_TRUE(set.stage(dir / "a.png", "a", &error)) << error;
  ASSERT_TRUE(set.stage(dir / "b.png", "b", &error)) << error;
  ASSERT_TRUE(set.commit(&error)) << error;
  EXPECT_EQ(dir.entries(), (Names{"a.png", "b.png"}));
}

TEST(CommitJournal, SetsAcrossFoldersAndOddNamesAreCompleted) {
  ScratchFolder dir;
  fs::create_directory(dir / "aovs");
  const fs::path odd = dir / "aovs" / "depth\t100%\nz.exr";
  commit_part_way_and_die({dir / "image.png", odd}, 1);
  EXPECT_EQ(read_file(dir / "image.png"), "new image.png");
  EXPECT_FALSE(fs::exists(odd));
  std::string error;
  ASSERT_TRUE(write_file_atomically(dir / "image.png", "newer", &error)) << error;
  EXPECT_EQ(read_file(dir / "image.png"), "newer");
  EXPECT_EQ(read_file(odd), "new " + odd.filename().string());
  EXPECT_EQ(dir.entries(), (Names{"aovs", "image.png"}));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir / "aovs"), {}), 1);
}

TEST(CommitJournal, ASetThatCannotBeCompletedIsReported) {
  ScratchFolder dir;
  for (const char* name : {"a.png", "b.exr", "c.exr"}) write_file(dir / name, std::string("old ") + name);
  commit_part_way_and_die({dir / "a.png", dir / "b.exr", dir / "c.exr"}, 1, dir / "b.exr");
  ::testing::internal::CaptureStderr();
  EXPECT_TRUE(recover_journal(dir / ".a.png.inkray-journal"));
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find((dir / ".a.png.inkray-journal").string()), std::string::npos) << said;
  EXPECT_NE(said.find("except for " + (dir / "b.exr").string() + ", whose new version is gone"),
            std::string::npos)
      << said;
  EXPECT_EQ(read_file(dir / "a.png"), "new a.png");
  EXPECT_EQ(read_file(dir / "b.exr"), "old b.exr");
  EXPECT_EQ(read_file(dir / "c.exr"), "new c.exr");
  EXPECT_EQ(dir.entries(), (Names{"a.png", "b.exr", "c.exr"}));
}

TEST(CommitJournal, DamagedJournalsAndDeadJournalTemporariesAreRemoved) {
  ScratchFolder dir;
  write_file(dir / ".a.png.inkray-journal", "inkray-journal 1\nno tab here\nend\n");
  const std::string here = "-" + posix::host_tag();
  const std::string half =
      "..b.png.inkray-journal.inkray-tmp-" + std::to_string(dead_pid()) + "-0123abcd" + here;
  const std::string live =
      "..c.png.inkray-journal.inkray-tmp-" + std::to_string(::getpid()) + "-0123abcd" + here;
  write_file(dir / half, "inkray-journal 1\n");
  write_file(dir / live, "inkray-journal 1\n");
  ::testing::internal::CaptureStderr();
  std::string error;
  ASSERT_TRUE(write_file_atomically(dir / "x.txt", "x", &error)) << error;
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find(".a.png.inkray-journal: not a journal"), std::string::npos) << said;
  EXPECT_EQ(dir.entries(), (Names{live, "x.txt"}));
}

TEST(CommitJournal, EveryWriteRemovesStaleTemporaries) {
  ScratchFolder dir;
  // A slice, a line-decision file and a checkpoint are single files: write_file_atomically.
  const std::string dead = std::to_string(dead_pid());
  const std::string own = ".part.exr.inkray-tmp-" + dead + "-00c0ffee";  // of the file written, any host
  const std::string other = ".other.png.inkray-tmp-" + dead + "-00c0ffee-" + posix::host_tag();
  const std::string remote = ".other.png.inkray-tmp-" + dead + "-00c0ffee-0000beef";  // another machine's
  const std::string untagged = ".other.png.inkray-tmp-" + dead + "-00c0ffee";
  for (const std::string& name : {own, other, remote, untagged}) write_file(dir / name, "half a file");
  std::string error;
  ASSERT_TRUE(write_file_atomically(dir / "part.exr", "partial", &error)) << error;
  Names expected = {"part.exr", remote, untagged};
  std::sort(expected.begin(), expected.end());
  if (posix::host_tag() == "0000beef") expected = {"part.exr", untagged};
  EXPECT_EQ(dir.entries(), expected);
}

TEST(CommitJournal, JournalNames) {
  EXPECT_EQ(journal_path("/x/out.png"), fs::path("/x/.out.png.inkray-journal"));
  EXPECT_TRUE(is_journal_name(".out.png.inkray-journal"));
  EXPECT_FALSE(is_journal_name("out.png.inkray-journal"));
  EXPECT_FALSE(is_journal_name(".out.png.inkray-journal~"));
  // A long name still gives a journal whose temporary fits NAME_MAX.
  const fs::path journal = journal_path(std::string(255, 'n'));
  EXPECT_LE(journal.filename().string().size(), 255u);
  EXPECT_LE(new_temporary_path(journal).filename().string().size(), 255u);
  long pid = 0;
  std::string_view stem, host;
  const std::string name = new_temporary_path("/x/out.png").filename().string();
  EXPECT_TRUE(parse_temporary_name(name, &stem, &pid, &host));
  EXPECT_EQ(stem, "out.png");
  EXPECT_EQ(pid, ::getpid());
  EXPECT_EQ(host, posix::host_tag());
}

}  // namespace
}  // namespace inkray
