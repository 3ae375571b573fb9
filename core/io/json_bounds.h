// Bounds checked on JSON text before a parser sees it: its size and how deep its arrays
// and objects nest, found by one linear scan (no recursion), so a header of a file from
// another machine cannot exhaust the stack of a recursive parser or comparison.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace inkray {

// Deeper than any header or scene inkray writes (scenes stop at kMaxJsonDepth, 64).
inline constexpr std::size_t kMaxHeaderJsonDepth = 256;

// "" when `text` is at most max_bytes long and nests at most max_depth levels (brackets
// inside strings, escaped quotes included, do not count); else what is wrong, e.g.
// "nests deeper than 256 levels" or "is 70000000 bytes, more than 67108864".
std::string json_bounds_problem(std::string_view text, std::size_t max_depth, std::size_t max_bytes);

}  // namespace inkray
