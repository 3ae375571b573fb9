// Error and warning lines joined into one string, for assertion messages and finds.
#pragma once

#include <string>
#include <vector>

namespace inkray::testing {

inline std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

}  // namespace inkray::testing
