// Atomic file replacement: bytes go to a temporary beside the target, are flushed to disk
// and renamed over it, so a reader, a crash or a full disk sees the old file or the new
// one, never a mix. Scenes, images and the editor's recovery files all go through here.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace inkray {

// The file a write to `target` replaces: a symbolic link is followed (through chains of
// links, dangling ones included) so the link stays and the file it names is replaced.
// False with *error naming `target` when a link cannot be read or loops.
bool resolve_write_target(const std::filesystem::path& target, std::filesystem::path* resolved,
                          std::string* error);

// One file written to its temporary and flushed, not yet renamed over its target.
// Destroying it (or discard()) before commit() removes the temporary; the target is
// untouched until commit().
class StagedFile {
 public:
  StagedFile() = default;
  StagedFile(StagedFile&& other) noexcept;
  StagedFile& operator=(StagedFile&& other) noexcept;
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;
  ~StagedFile() { discard(); }

  // First removes what killed writers left beside `target` (remove_stale_temporaries),
  // then creates the temporary (O_EXCL, with the permissions of the file it will replace),
  // writes `bytes` and fsyncs it. Errors name `target` and keep the cause, e.g.
  // "cannot replace /x/out.png: Is a directory"; no temporary is left behind.
  bool stage(const std::filesystem::path& target, std::string_view bytes, std::string* error);
  // Renames the temporary over the target and fsyncs the folder, so the rename survives
  // a power cut. On failure the temporary is removed and the target is as it was.
  bool commit(std::string* error);
  void discard();

  bool staged() const { return !temporary_.empty(); }
  const std::filesystem::path& target() const { return target_; }            // as the caller named it
  const std::filesystem::path& destination() const { return destination_; }  // the file replaced
  const std::filesystem::path& temporary() const { return temporary_; }

 private:
  std::filesystem::path target_, destination_, temporary_;
};

// Milliseconds StagedFile::commit waits before its rename: INKRAY_TEST_COMMIT_DELAY_MS, a
// test hook only, which widens the moment a kill leaves a temporary (and, in an output
// set, a journal) behind, so tests/app/output_kill_test.cpp can stop writers there on
// purpose. 0 when unset; at most a minute.
int test_commit_delay_ms();

// stage() then commit(): one file replaced atomically.
bool write_file_atomically(const std::filesystem::path& target, std::string_view bytes, std::string* error);

// A fresh name for a temporary of `destination`, beside it:
// "." name ".inkray-tmp-" pid "-" 8 random hex digits "-" 8 hex digits naming the host.
std::filesystem::path new_temporary_path(const std::filesystem::path& destination);
// True for a name new_temporary_path gives (or one without the host's part, as written
// before it had one), for any file: then *stem is the name of the file it was for (cut to
// fit NAME_MAX), *pid its writer and *host (when given) the host's part or "".
bool parse_temporary_name(std::string_view file_name, std::string_view* stem, long* pid,
                          std::string_view* host);

// True for a temporary that a write to `target` creates ("." name ".inkray-tmp-" pid "-"
// random), and for the older "<name>.tmp-" + 6 or 8 hex digits; *pid is 0 for the latter.
bool is_temporary_of(const std::filesystem::path& target, std::string_view file_name, long* pid);

// Deletes the temporaries killed processes left in the folder of `target` (the file a
// write to it replaces): first, every interrupted set of files there is completed
// (recover_journal in core/io/commit_journal.h), since their temporaries are the sets'
// newest versions; then `target`'s temporaries whose process is gone, and old-style ones
// (no pid) not modified for a minute; and any other file's temporary written on this
// machine (its host part) by a process that is gone. A live process's temporary is never
// touched, and a process id is tested only on its own machine for other files, so
// machines sharing a folder do not break each other's saves. StagedFile::stage calls it,
// so every writer cleans up before it writes. Returns how many it removed; failures are
// ignored, as the next call tries again.
int remove_stale_temporaries(const std::filesystem::path& target);

}  // namespace inkray
