#include "core/io/file_bytes.h"

#include <fstream>
#include <sstream>
#include <system_error>

namespace inkray {

bool read_file_bytes(const std::filesystem::path& file, std::uintmax_t max_bytes, std::string* bytes,
                     std::string* error) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (!ec && size > max_bytes) {
    *error = file.string() + ": the file is " + std::to_string(size) + " bytes, more than the " +
             std::to_string(max_bytes) + " it can hold";
    return false;
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    *error = file.string() + ": cannot open the file";
    return false;
  }
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) {
    *error = file.string() + ": cannot read the file";
    return false;
  }
  *bytes = std::move(s).str();
  return true;
}

}  // namespace inkray
