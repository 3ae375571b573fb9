// One pass over the text, tracking only whether it is inside a string.
#include "core/io/json_bounds.h"

namespace inkray {

std::string json_bounds_problem(std::string_view text, std::size_t max_depth, std::size_t max_bytes) {
  if (text.size() > max_bytes)
    return "is " + std::to_string(text.size()) + " bytes, more than " + std::to_string(max_bytes);
  std::size_t depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;  // the escaped character, a quote included
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) return "nests deeper than " + std::to_string(max_depth) + " levels";
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return "";
}

}  // namespace inkray
