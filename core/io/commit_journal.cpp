// Writing, locking and completing the journal of an output set's renames
// (docs/architecture.md, "Files written").
#include "core/io/commit_journal.h"

#include "core/io/atomic_file.h"
#include "core/io/posix_file.h"

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <thread>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace inkray {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kSuffix = ".inkray-journal";
constexpr std::string_view kHeader = "inkray-journal 1\n";
constexpr std::string_view kEnd = "end\n";
// The journal's name is "." + stem + kSuffix; its temporary (new_temporary_path) cuts a
// name to 214 bytes, so a stem of 197 keeps the journal's name whole.
constexpr std::size_t kMaxStemBytes = 214 - 1 - kSuffix.size() - 1;
// How long begin() waits for a live process committing the same set before giving up.
constexpr auto kWaitForOtherCommit = std::chrono::seconds(10);

// Paths are written one per field; tab, newline and '%' are escaped so any name fits.
std::string escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '%')
      out += "%25";
    else if (c == '\t')
      out += "%09";
    else if (c == '\n')
      out += "%0A";
    else
      out += c;
  }
  return out;
}

bool unescape(std::string_view text, std::string* out) {
  out->clear();
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      *out += text[i];
      continue;
    }
    const std::string_view code = text.substr(i + 1, 2);
    if (code == "25")
      *out += '%';
    else if (code == "09")
      *out += '\t';
    else if (code == "0A")
      *out += '\n';
    else
      return false;
    i += 2;
  }
  return !out->empty();
}

// One line per rename: the temporary's name (it lies beside its destination) and the
// destination, as a name when it is in the journal's folder and else as an absolute path.
std::string journal_text(const std::vector<JournalEntry>& entries, const fs::path& journal) {
  std::string text(kHeader);
  std::error_code ec;
  const fs::path home = fs::absolute(journal, ec).lexically_normal().parent_path();
  for (const JournalEntry& e : entries) {
    fs::path destination = fs::absolute(e.destination, ec).lexically_normal();
    if (destination.parent_path() == home) destination = destination.filename();
    // The temporary's inode is what the destination has once renamed: how recovery tells
    // a rename done from a temporary lost.
    struct stat st;
    const unsigned long long inode = ::lstat(e.temporary.c_str(), &st) == 0 ? st.st_ino : 0;
    text += escape(e.temporary.filename().string()) + "\t" + escape(destination.string()) + "\t" +
            std::to_string(inode) + "\n";
  }
  text += kEnd;
  return text;
}

bool parse_journal(const std::string& text, const fs::path& folder, std::vector<JournalEntry>* entries,
                   std::vector<unsigned long long>* inodes) {
  if (!text.starts_with(kHeader) || !text.ends_with(kEnd)) return false;
  std::string_view body(text);
  body.remove_prefix(kHeader.size());
  body.remove_suffix(kEnd.size());
  while (!body.empty()) {
    const std::size_t newline = body.find('\n');
    if (newline == std::string_view::npos) return false;
    const std::string_view line = body.substr(0, newline);
    body.remove_prefix(newline + 1);
    const std::size_t tab = line.find('\t'), tab2 = line.rfind('\t');
    std::string temporary, destination;
    unsigned long long inode = 0;
    const std::string_view inode_text = line.substr(tab2 + 1);
    const auto [end, ec] = std::from_chars(inode_text.data(), inode_text.data() + inode_text.size(), inode);
    if (tab == std::string_view::npos || tab2 == tab || !unescape(line.substr(0, tab), &temporary) ||
        !unescape(line.substr(tab + 1, tab2 - tab - 1), &destination) ||
        temporary.find('/') != std::string::npos || ec != std::errc() ||
        end != inode_text.data() + inode_text.size())
      return false;
    JournalEntry e;
    e.destination = folder / destination;  // an absolute destination stays as it is
    e.temporary = posix::folder_of(e.destination) / temporary;
    entries->push_back(std::move(e));
    inodes->push_back(inode);
  }
  return !entries->empty();
}

bool read_all(int fd, std::string* text) {
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return false;
    if (n == 0) return true;
    text->append(buffer, std::size_t(n));
  }
}

bool is_plain_file(const fs::path& file) {
  struct stat st;
  return ::lstat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

}  // namespace

fs::path journal_path(const fs::path& destination) {
  const std::string stem = destination.filename().string().substr(0, kMaxStemBytes);
  return posix::folder_of(destination) / ("." + stem + std::string(kSuffix));
}

bool is_journal_name(std::string_view file_name) {
  return file_name.size() > kSuffix.size() + 1 && file_name[0] == '.' && file_name.ends_with(kSuffix);
}

bool CommitJournal::begin(const std::vector<JournalEntry>& entries, std::string* error) {
  finish();
  if (entries.empty()) return true;
  const fs::path file = journal_path(entries.front().destination);
  const fs::path folder = posix::folder_of(file);
  const std::string text = journal_text(entries, file);
  const auto fail = [&](const std::string& why) {
    if (error) *error = "cannot write " + file.string() + " (the list of files replaced together): " + why;
    return false;
  };

  // Locked before it has its name, so no other process ever sees it unlocked while this
  // one lives; the lock dies with the process, which is how the next writer knows.
  fs::path temporary;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temporary = new_temporary_path(file);
    fd = ::open(temporary.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0 && errno != EEXIST) return fail(std::strerror(errno));
  }
  if (fd < 0) return fail(std::strerror(EEXIST));
  const auto abandon = [&](int cause) {
    ::close(fd);
    ::unlink(temporary.c_str());
    return fail(std::strerror(cause));
  };
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) return abandon(errno);
  if (!posix::write_all(fd, text)) return abandon(errno);
  if (::fsync(fd) != 0) return abandon(errno);

  // link() refuses to replace a journal that is there: a live process committing the same
  // files finishes first (it takes milliseconds), a dead one's is completed first.
  const auto give_up = std::chrono::steady_clock::now() + kWaitForOtherCommit;
  for (;;) {
    if (::link(temporary.c_str(), file.c_str()) == 0) {
      ::unlink(temporary.c_str());
      break;
    }
    if (errno != EEXIST) {
      // A file system without hard links: rename, which cannot wait for another commit.
      if (::rename(temporary.c_str(), file.c_str()) != 0) return abandon(errno);
      break;
    }
    if (recover_journal(file)) continue;
    if (std::chrono::steady_clock::now() > give_up) {
      abandon(EEXIST);
      return fail("another live process has been replacing the same files for " +
                  std::to_string(kWaitForOtherCommit.count()) + " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  posix::sync_directory(folder);
  file_ = file;
  fd_ = fd;
  return true;
}

void CommitJournal::finish() {
  if (fd_ < 0) return;
  ::unlink(file_.c_str());
  posix::sync_directory(posix::folder_of(file_));
  ::close(fd_);  // releases the lock
  fd_ = -1;
  file_.clear();
}

bool recover_journal(const fs::path& journal) {
  const int fd = ::open(journal.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  // Held: its writer is alive (or another process is completing it).
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) return false;
  // Completed and removed between the open and the lock: nothing to do.
  struct stat opened, named;
  if (::fstat(fd, &opened) != 0 || ::lstat(journal.c_str(), &named) != 0 || opened.st_ino != named.st_ino ||
      opened.st_dev != named.st_dev || !S_ISREG(opened.st_mode))
    return false;

  std::string text;
  std::vector<JournalEntry> entries;
  std::vector<unsigned long long> inodes;
  const fs::path folder = posix::folder_of(journal);
  if (!read_all(fd, &text) || !parse_journal(text, folder, &entries, &inodes)) {
    std::fprintf(stderr, "warning: %s: not a journal of replaced files that inkray can read; removed\n",
                 journal.c_str());
    ::unlink(journal.c_str());
    return true;
  }

  // A temporary still there is renamed in; one gone was renamed already when its
  // destination is now that temporary's inode, and was lost otherwise (its destination
  // keeps an earlier write).
  std::vector<std::string> lost;
  std::set<fs::path> folders;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const JournalEntry& e = entries[i];
    struct stat st;
    if (is_plain_file(e.temporary)) {
      if (::rename(e.temporary.c_str(), e.destination.c_str()) != 0)
        lost.push_back(e.destination.string() + " (" + std::strerror(errno) + ")");
      folders.insert(posix::folder_of(e.destination));
    } else if (::lstat(e.destination.c_str(), &st) != 0 || st.st_ino != inodes[i]) {
      lost.push_back(e.destination.string());
    }
  }
  for (const fs::path& f : folders) posix::sync_directory(f);
  ::unlink(journal.c_str());
  posix::sync_directory(folder);
  if (!lost.empty()) {
    std::string names;
    for (const std::string& name : lost) names += (names.empty() ? "" : ", ") + name;
    std::fprintf(stderr,
                 "warning: %s: a killed process's write of %zu files together was completed except for %s, "
                 "whose new version is gone: it holds an earlier write\n",
                 journal.c_str(), entries.size(), names.c_str());
  }
  return true;
}

}  // namespace inkray
