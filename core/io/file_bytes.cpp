// Reads through POSIX descriptors: stat and fstat tell a regular file from a FIFO or a device.
#include "core/io/file_bytes.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace inkray {
namespace {

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a plain file";
}

std::string not_regular(const std::filesystem::path& file, mode_t mode) {
  return file.string() + ": not a regular file (" + kind_of(mode) + "), expected a file inkray wrote";
}

struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

bool check_regular_file(const std::filesystem::path& file, std::string* error) {
  struct stat st;
  if (::stat(file.c_str(), &st) != 0) {
    *error = file.string() + ": " +
             (errno == ENOENT ? "no such file"
                              : "cannot open the file (" + std::string(std::strerror(errno)) + ")");
    return false;
  }
  if (!S_ISREG(st.st_mode)) {
    *error = not_regular(file, st.st_mode);
    return false;
  }
  return true;
}

bool read_file_bytes(const std::filesystem::path& file, std::uintmax_t max_bytes, std::string* bytes,
                     std::string* error) {
  // stat first: opening a FIFO blocks until a writer comes. The file may be swapped for
  // one between stat and open, so the open descriptor is checked again (O_NONBLOCK: an
  // open FIFO returns at once).
  if (!check_regular_file(file, error)) return false;
  Fd f;
  f.fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (f.fd < 0) {
    *error = file.string() + ": cannot open the file (" + std::strerror(errno) + ")";
    return false;
  }
  struct stat st;
  if (::fstat(f.fd, &st) != 0) {
    *error = file.string() + ": cannot read the file (" + std::strerror(errno) + ")";
    return false;
  }
  if (!S_ISREG(st.st_mode)) {
    *error = not_regular(file, st.st_mode);
    return false;
  }
  const std::uintmax_t size = std::uintmax_t(st.st_size);
  if (size > max_bytes) {
    *error = file.string() + ": the file is " + std::to_string(size) + " bytes, more than the " +
             std::to_string(max_bytes) + " it can hold";
    return false;
  }
  std::string out;
  out.resize(size_t(size));
  size_t got = 0;
  for (;;) {
    if (got == out.size()) {
      if (out.size() > max_bytes) {
        *error = file.string() + ": the file grew past " + std::to_string(max_bytes) + " bytes while read";
        return false;
      }
      // A file that grew since fstat: read on, up to one byte past the bound.
      const std::uintmax_t room = max_bytes - out.size();
      out.resize(out.size() + size_t(std::min<std::uintmax_t>(room, 65535) + 1));
    }
    const ssize_t n = ::read(f.fd, out.data() + got, out.size() - got);
    if (n < 0) {
      if (errno == EINTR) continue;
      *error = file.string() + ": cannot read the file (" + std::strerror(errno) + ")";
      return false;
    }
    if (n == 0) break;
    got += size_t(n);
  }
  out.resize(got);
  *bytes = std::move(out);
  return true;
}

}  // namespace inkray
