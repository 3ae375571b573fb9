// The journal that makes the renames of an output set (core/io/output_set.h) all-or-nothing
// across a crash: written before the first rename, removed after the last, and completed by
// the next writer into its folder when the process that wrote it died in between.
// The protocol is described in docs/architecture.md, "Files written".
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// One rename a journal promises: the staged temporary and the file it replaces.
struct JournalEntry {
  std::filesystem::path temporary, destination;
};

// A journal held by a committing process: the file exists and is locked (flock) until
// finish() or destruction, so no other process takes it for the debris of a dead one.
class CommitJournal {
 public:
  CommitJournal() = default;
  CommitJournal(const CommitJournal&) = delete;
  CommitJournal& operator=(const CommitJournal&) = delete;
  ~CommitJournal() { finish(); }

  // Writes ".<name>.inkray-journal" beside entries.front().destination (name being that
  // file's), flushed to disk with its folder, naming every rename in order. Waits a few
  // seconds for a live process committing the same set; false with *error naming the
  // journal when it cannot be written (nothing has been renamed yet).
  bool begin(const std::vector<JournalEntry>& entries, std::string* error);
  // Removes the journal: every rename is done (or reported by the caller).
  void finish();

  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  int fd_ = -1;
};

// The journal a set whose first file is `destination` writes.
std::filesystem::path journal_path(const std::filesystem::path& destination);
// True for a journal's name (".<name>.inkray-journal").
bool is_journal_name(std::string_view file_name);

// Completes the journal `journal` when no live process holds it: every temporary it names
// that is still there is renamed over its destination in order, so the set that was being
// committed wins, then the journal is removed. A temporary that is gone although its
// destination is not that temporary's file (the journal records its inode) was lost: the
// rest is completed and stderr gets one line naming the journal and the file left from an
// earlier write. Returns true when it removed the journal.
bool recover_journal(const std::filesystem::path& journal);

}  // namespace inkray
