#include "ui/model/log.h"

#include <chrono>
#include <cstdio>

namespace inkray {

void Log::add(LogLevel level, std::string text) {
  static const auto start = std::chrono::steady_clock::now();
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Errors also go to stderr: headless runs (screenshots, CI) have no log panel to read.
  if (level == LogLevel::error) std::fprintf(stderr, "inkray: %s\n", text.c_str());
  if (lines_.size() >= kMaxLines) lines_.erase(lines_.begin(), lines_.begin() + kMaxLines / 4);
  lines_.push_back({level, t, std::move(text)});
}

}  // namespace inkray
