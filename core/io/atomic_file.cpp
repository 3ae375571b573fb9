// Atomic file replacement through an O_EXCL temporary in the target's folder, and the
// clean-up of temporaries that killed processes left behind.
#include "core/io/atomic_file.h"

#include "core/io/commit_journal.h"
#include "core/io/posix_file.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <limits>
#include <system_error>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace inkray {
namespace fs = std::filesystem;
using posix::folder_of;

namespace {

constexpr std::string_view kTag = ".inkray-tmp-";
// "." + name + kTag + pid + "-" + 8 hex digits + "-" + 8 hex digits (the host) must fit
// NAME_MAX (255 bytes), so long names are cut; 41 bytes cover the rest with a 10-digit pid.
constexpr std::size_t kMaxStemBytes = 255 - 41;
// An old-style temporary has no pid; one untouched this long is no save in progress.
constexpr std::time_t kOldStyleStaleSeconds = 60;

void set_error(std::string* error, std::string message) {
  if (error) *error = std::move(message);
}

std::string temporary_stem(const fs::path& destination) {
  return destination.filename().string().substr(0, kMaxStemBytes);
}

// "out.png", or "out.png (a link to /data/real.png)" so the message names both.
std::string label_of(const fs::path& target, const fs::path& destination) {
  if (target == destination) return target.string();
  return target.string() + " (a link to " + destination.string() + ")";
}

bool all_hex(std::string_view text) {
  return text.find_first_not_of("0123456789abcdef") == std::string_view::npos;
}

}  // namespace

bool resolve_write_target(const fs::path& target, fs::path* resolved, std::string* error) {
  fs::path p = target;
  // 40 is the kernel's own limit on links followed in one lookup (ELOOP).
  for (int hops = 0;; ++hops) {
    struct stat st;
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) break;  // open() reports any other problem
    if (hops == 40) {
      set_error(error, "cannot write " + target.string() + ": " + std::strerror(ELOOP));
      return false;
    }
    std::error_code ec;
    const fs::path link = fs::read_symlink(p, ec);
    if (ec) {
      set_error(error, "cannot write " + target.string() + ": cannot read the link: " + ec.message());
      return false;
    }
    p = link.is_absolute() ? link : p.parent_path() / link;
  }
  *resolved = p;
  return true;
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : target_(std::move(other.target_)),
      destination_(std::move(other.destination_)),
      temporary_(std::move(other.temporary_)) {
  other.temporary_.clear();
}

StagedFile& StagedFile::operator=(StagedFile&& other) noexcept {
  if (this != &other) {
    discard();
    target_ = std::move(other.target_);
    destination_ = std::move(other.destination_);
    temporary_ = std::move(other.temporary_);
    other.temporary_.clear();
  }
  return *this;
}

void StagedFile::discard() {
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  temporary_.clear();
}

bool StagedFile::stage(const fs::path& target, std::string_view bytes, std::string* error) {
  discard();
  target_ = target;
  fs::path destination;
  if (!resolve_write_target(target, &destination, error)) return false;
  destination_ = destination;
  const std::string label = label_of(target, destination);

  // A killed writer's debris goes first, before the file replaced is looked at: an
  // interrupted set of files is completed (its temporaries are its newest versions), then
  // stale temporaries are removed.
  remove_stale_temporaries(destination);

  // A folder in the way would only fail at the rename; say so before writing anything.
  struct stat existing;
  const bool exists = ::stat(destination.c_str(), &existing) == 0;
  if (destination.filename().empty() || (exists && S_ISDIR(existing.st_mode))) {
    set_error(error, "cannot replace " + label + ": " + std::strerror(EISDIR));
    return false;
  }

  const fs::path dir = folder_of(destination);
  fs::path temporary;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temporary = new_temporary_path(destination);
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) {
      set_error(error, "cannot write " + label + ": cannot create a temporary file in " + dir.string() +
                           ": " + std::strerror(errno));
      return false;
    }
  }
  if (fd < 0) {
    set_error(error, "cannot write " + label + ": cannot create a temporary file in " + dir.string() + ": " +
                         std::strerror(EEXIST));
    return false;
  }

  if (exists && S_ISREG(existing.st_mode)) {
    // Only root may give a file away; for anyone else the owner is already right, so a
    // refusal is expected and harmless.
    [[maybe_unused]] const int owned = ::fchown(fd, existing.st_uid, existing.st_gid);
    ::fchmod(fd, existing.st_mode & 07777);
  }

  const auto abandon = [&](const char* what) {
    const int cause = errno;
    if (fd >= 0) ::close(fd);
    ::unlink(temporary.c_str());
    set_error(error, "cannot write " + label + ": " + what + std::strerror(cause));
    return false;
  };
  if (!posix::write_all(fd, bytes)) return abandon("");
  if (::fsync(fd) != 0) return abandon("flushing to disk failed: ");
  const int closed = ::close(fd);
  fd = -1;
  if (closed != 0) return abandon("");
  temporary_ = temporary;
  return true;
}

bool StagedFile::commit(std::string* error) {
  if (!staged()) {
    set_error(error, "cannot replace " + target_.string() + ": nothing was staged");
    return false;
  }
  if (const int delay_ms = test_commit_delay_ms(); delay_ms > 0)
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
  if (::rename(temporary_.c_str(), destination_.c_str()) != 0) {
    const int cause = errno;
    discard();
    set_error(error, "cannot replace " + label_of(target_, destination_) + ": " + std::strerror(cause));
    return false;
  }
  temporary_.clear();
  posix::sync_directory(folder_of(destination_));
  return true;
}

int test_commit_delay_ms() {
  const char* text = std::getenv("INKRAY_TEST_COMMIT_DELAY_MS");
  if (!text) return 0;
  const int ms = std::atoi(text);
  return ms > 0 ? std::min(ms, 60000) : 0;
}

bool write_file_atomically(const fs::path& target, std::string_view bytes, std::string* error) {
  StagedFile file;
  return file.stage(target, bytes, error) && file.commit(error);
}

fs::path new_temporary_path(const fs::path& destination) {
  return destination.parent_path() /
         ("." + temporary_stem(destination) + std::string(kTag) + std::to_string(::getpid()) + "-" +
          posix::random_hex8() + "-" + posix::host_tag());
}

bool parse_temporary_name(std::string_view file_name, std::string_view* stem, long* pid,
                          std::string_view* host) {
  // The tag is searched from the end: a stem may itself contain it.
  const std::size_t tag = file_name.rfind(kTag);
  if (file_name.empty() || file_name[0] != '.' || tag == std::string_view::npos || tag < 2) return false;
  std::string_view rest = file_name.substr(tag + kTag.size());
  const std::size_t dash = rest.find('-');
  if (dash == 0 || dash == std::string_view::npos) return false;
  long value = 0;
  const auto [end, ec] = std::from_chars(rest.data(), rest.data() + dash, value);
  if (ec != std::errc() || end != rest.data() + dash || value <= 0 ||
      value > std::numeric_limits<pid_t>::max())
    return false;
  rest.remove_prefix(dash + 1);
  // The random part, then the host's tag (names written before it carried one have none).
  std::string_view tag_of_host;
  if (rest.size() == 17 && rest[8] == '-') {
    tag_of_host = rest.substr(9);
    rest = rest.substr(0, 8);
  }
  if (rest.size() != 8 || !all_hex(rest) || !all_hex(tag_of_host)) return false;
  *stem = file_name.substr(1, tag - 1);
  *pid = value;
  if (host) *host = tag_of_host;
  return true;
}

bool is_temporary_of(const fs::path& target, std::string_view file_name, long* pid) {
  const std::string name = target.filename().string();
  std::string_view stem;
  if (parse_temporary_name(file_name, &stem, pid, nullptr))
    return !name.empty() && stem == temporary_stem(target);
  // Written by save_scene (6 hex digits) and write_image (8) before this module.
  const std::string old_prefix = name + ".tmp-";
  if (!name.empty() && file_name.starts_with(old_prefix)) {
    const std::string_view rest = file_name.substr(old_prefix.size());
    if ((rest.size() != 6 && rest.size() != 8) || !all_hex(rest)) return false;
    *pid = 0;
    return true;
  }
  return false;
}

int remove_stale_temporaries(const fs::path& target) {
  fs::path destination;
  if (!resolve_write_target(target, &destination, nullptr)) return 0;
  // One pass over the folder collects the candidates; journals are completed before any
  // temporary is removed, since the temporaries they name are the sets' newest versions.
  std::vector<fs::path> journals, temporaries;
  {
    std::error_code ec;
    fs::directory_iterator it(folder_of(destination), ec);
    if (ec) return 0;
    for (const fs::directory_iterator end; it != end; it.increment(ec)) {
      if (ec) break;
      const std::string name = it->path().filename().string();
      if (is_journal_name(name))
        journals.push_back(it->path());
      else if (name.find(kTag) != std::string::npos || name.find(".tmp-") != std::string::npos)
        temporaries.push_back(it->path());
    }
  }
  for (const fs::path& journal : journals) recover_journal(journal);

  const std::time_t now = std::time(nullptr);
  int removed = 0;
  for (const fs::path& file : temporaries) {
    const std::string name = file.filename().string();
    long pid = 0;
    std::string_view stem, host;
    bool stale = false;
    struct stat st;
    if (::lstat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;  // renamed in by a journal
    if (is_temporary_of(destination, name, &pid))
      stale = pid > 0 ? posix::process_is_gone(pid) : now - st.st_mtime > kOldStyleStaleSeconds;
    else if (parse_temporary_name(name, &stem, &pid, &host))
      stale = host == posix::host_tag() && posix::process_is_gone(pid);  // any file's, from this machine
    if (stale && ::unlink(file.c_str()) == 0) ++removed;
  }
  return removed;
}

}  // namespace inkray
