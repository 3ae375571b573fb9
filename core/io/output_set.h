// Several output files (a render and its AOVs) that land together or not at all: every
// file is staged to its temporary first and only when all staged are they renamed in.
// Also the check, before any work, that a list of output paths can be written.
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
  // Renames every staged file over its target. Staging has already failed for anything
  // predictable (a folder in the way, a full disk), so this fails only when the folder
  // changed meanwhile; then the rest are dropped and *error says what was replaced.
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
