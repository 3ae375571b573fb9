// Numbers on the command line, for inkray-render, inkray-merge and the editor alike: a
// whole argument must be the number (no trailing text, as std::atoi would allow), finite,
// and inside the option's range, or the option says what it expected.
#pragma once

#include <charconv>
#include <cmath>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>

namespace inkray::cli {

// Whether all of `text` is one number of type T (finite, for floating point).
template <class T>
bool parse_number(std::string_view text, T* out) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, *out);
  if (ec != std::errc() || ptr != end) return false;
  if constexpr (std::is_floating_point_v<T>) return std::isfinite(*out);
  return true;
}

// `text` as a number in [lo, hi] for `option`; empty on success, else the message:
// --threads: expected an integer in [1, 1024], got "many".
template <class T>
std::string read_option_number(std::string_view option, std::string_view text, T lo, T hi, T* out) {
  T value{};
  if (parse_number(text, &value) && value >= lo && value <= hi) {
    *out = value;
    return {};
  }
  std::ostringstream message;
  message << option << ": expected " << (std::is_integral_v<T> ? "an integer" : "a number") << " in [" << lo
          << ", " << hi << "], got \"" << text << "\"";
  return message.str();
}

}  // namespace inkray::cli
