// Several output files (a render and its AOVs) that land together or not at all: every
// file is staged to its temporary first and only when all staged are they renamed in.
// Also the check, before any work, that a list of output paths can be written.
//
// A kill between the renames cannot leave a mix of two writes. commit() protocol
// (docs/architecture.md, "Files written"):
//  1. every file is staged: a flushed temporary beside its destination;
//  2. the journal ".<first file>.inkray-journal" is written beside the first file, naming
//     every (temporary -> destination) rename in order; it is flushed, locked (flock) by
//     this process and given its name atomically, and its folder is flushed;
//  3. the renames, in the journal's order, each followed by a flush of its folder;
//  4. the journal is removed.
// Whoever next stages a file in that folder (any writer: StagedFile::stage) finds a journal
// no live process holds and completes it: every temporary it names that is still there is
// renamed in, so the killed write's set wins whole, then the journal goes. Killed before
// step 2 ended, nothing was replaced and the temporaries are removed as stale.
#pragma once

#include "core/io/atomic_file.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

class OutputSet {
 public:
  // Writes bytes to a flushed temporary beside `target`; no target is touched yet. On
  // failure returns false with *error naming the file; the caller then drops the set.
  // A second output that resolves to the file of an earlier one is refused.
  bool stage(const std::filesystem::path& target, std::string_view bytes, std::string* error);
  // Renames every staged file over its target, under a journal when there are several (see
  // above). Staging has already failed for anything predictable (a folder in the way, a
  // full disk), so this fails only when the journal cannot be written (nothing replaced) or
  // the folder changed meanwhile; then the rest are dropped and *error says what was replaced.
  bool commit(std::string* error);
  void discard() { files_.clear(); }  // removes every temporary; so does the destructor

  std::size_t size() const { return files_.size(); }

 private:
  std::vector<StagedFile> files_;
};

struct PlannedOutput {
  std::string label;  // how the user named it, e.g. "--aov depth=z.exr"
  std::filesystem::path file;
};

// Checks, before rendering, that every output can be written: its folder exists, is a
// folder and is writable, it is not itself a folder, and no two outputs are the same file
// (compared after following symbolic links, so "out.png", "./out.png" and a link to it
// collide). Returns "" when all is well, else one line: "<label>: <what is wrong>".
std::string check_outputs(const std::vector<PlannedOutput>& outputs);

}  // namespace inkray
