// Reading a whole file into memory, with a bound on its size, for the readers of
// binary files inkray writes itself (partials, line decisions). Only regular files
// are read: a FIFO would block the reader forever and a device never ends.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace inkray {

// True when `file` is a regular file (symbolic links followed); else false with
// *error: "FILE: not a regular file (a FIFO), expected ..." or "FILE: no such file".
bool check_regular_file(const std::filesystem::path& file, std::string* error);

// The file's bytes. Refused, with *error naming the file: anything but a regular file
// (checked before opening), and a file of more than max_bytes (its size is asked first,
// and a file growing while read is cut at max_bytes + 1 and refused).
bool read_file_bytes(const std::filesystem::path& file, std::uintmax_t max_bytes, std::string* bytes,
                     std::string* error);

}  // namespace inkray
