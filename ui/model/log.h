// The editor's log: loader warnings and errors, render statistics, notes.
// Plain data; the log panel draws it.
#pragma once

#include <string>
#include <vector>

namespace inkray {

enum class LogLevel { info, warning, error };

struct LogLine {
  LogLevel level = LogLevel::info;
  double seconds = 0.0;  // since the editor started
  std::string text;
};

class Log {
 public:
  static constexpr size_t kMaxLines = 2000;
  void add(LogLevel level, std::string text);
  void info(std::string text) { add(LogLevel::info, std::move(text)); }
  void warning(std::string text) { add(LogLevel::warning, std::move(text)); }
  void error(std::string text) { add(LogLevel::error, std::move(text)); }
  const std::vector<LogLine>& lines() const { return lines_; }
  void clear() { lines_.clear(); }

 private:
  std::vector<LogLine> lines_;
};

}  // namespace inkray
