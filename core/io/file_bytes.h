// Reading a whole file into memory, with a bound on its size, for the readers of
// binary files inkray writes itself (partials, line decisions).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace inkray {

// False with *error ("FILE: cannot open the file", "... is N bytes, more than M") on failure.
bool read_file_bytes(const std::filesystem::path& file, std::uintmax_t max_bytes, std::string* bytes,
                     std::string* error);

}  // namespace inkray
