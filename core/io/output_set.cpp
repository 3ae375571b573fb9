// Two-phase commit of output files, and the up-front check of output paths.
#include "core/io/output_set.h"

#include "core/io/commit_journal.h"

#include <cerrno>
#include <cstring>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>

namespace inkray {
namespace fs = std::filesystem;

namespace {

// The identity two outputs are compared by; weakly_canonical also resolves links in the
// folders above, so "a/out.png" and "b/out.png" with b a link to a collide.
fs::path identity_of(const fs::path& destination) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(destination, ec);
  if (ec) p = fs::absolute(destination, ec).lexically_normal();
  return p;
}

// Why `file` (already resolved) cannot be written, or "".
std::string write_problem(const fs::path& file) {
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  struct stat st;
  if (::stat(dir.c_str(), &st) != 0) {
    if (errno == ENOENT) return "folder " + dir.string() + " does not exist";
    if (errno == ENOTDIR) return dir.string() + " is not a folder";
    return "cannot use folder " + dir.string() + ": " + std::strerror(errno);
  }
  if (!S_ISDIR(st.st_mode)) return dir.string() + " is not a folder";
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    return "cannot write in folder " + dir.string() + ": " + std::strerror(errno);
  if (file.filename().empty()) return "names a folder, not a file";
  if (::stat(file.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) return file.string() + " is a folder";
    if (!S_ISREG(st.st_mode)) return file.string() + " is not a regular file";
  }
  return "";
}

}  // namespace

bool OutputSet::stage(const fs::path& target, std::string_view bytes, std::string* error) {
  fs::path destination;
  if (!resolve_write_target(target, &destination, error)) return false;
  const fs::path identity = identity_of(destination);
  for (const StagedFile& other : files_) {
    if (identity_of(other.destination()) == identity) {
      if (error) *error = "cannot write " + target.string() + ": the same file as " + other.target().string();
      return false;
    }
  }
  StagedFile file;  // stage() first completes or removes what a killed writer left
  if (!file.stage(target, bytes, error)) return false;
  files_.push_back(std::move(file));
  return true;
}

bool OutputSet::commit(std::string* error) {
  // One file needs no journal: its rename is atomic by itself.
  CommitJournal journal;
  if (files_.size() > 1) {
    std::vector<JournalEntry> entries;
    for (const StagedFile& file : files_) entries.push_back({file.temporary(), file.destination()});
    if (!journal.begin(entries, error)) {
      files_.clear();
      return false;
    }
  }
  std::string replaced;
  for (StagedFile& file : files_) {
    std::string reason;
    if (!file.commit(&reason)) {
      if (error) *error = reason + (replaced.empty() ? "" : " (already replaced: " + replaced + ")");
      files_.clear();
      return false;  // the journal goes with the temporaries: the message says what was replaced
    }
    replaced += (replaced.empty() ? "" : ", ") + file.target().string();
  }
  files_.clear();
  return true;
}

std::string check_outputs(const std::vector<PlannedOutput>& outputs) {
  std::vector<fs::path> identities;
  for (const PlannedOutput& output : outputs) {
    fs::path destination;
    std::string error;
    if (!resolve_write_target(output.file, &destination, &error)) return output.label + ": " + error;
    if (const std::string problem = write_problem(destination); !problem.empty())
      return output.label + ": " + problem;
    identities.push_back(identity_of(destination));
    for (std::size_t i = 0; i + 1 < identities.size(); ++i)
      if (identities[i] == identities.back()) return output.label + ": the same file as " + outputs[i].label;
  }
  return "";
}

}  // namespace inkray
