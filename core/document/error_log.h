// Collects a scene file's problems as full lines, "<file>: <json path>: <message>",
// so a reader can report every problem instead of stopping at the first; and the
// small helpers that spell paths and values in those lines.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace inkray {

// What a document is read for. Every problem that makes a document malformed
// (syntax, a wrong type, a value out of range) stops both. A whole document can
// still be unrenderable: a missing or unset file, a name that refers to nothing,
// settings that contradict each other or exceed a budget. Rendering refuses it;
// the editor opens it, shows the problems as warnings and lets the user mend them,
// which is what makes every document the editor can save one it can open again.
enum class ReadFor { rendering, editing };

class ErrorLog {
 public:
  // A hostile file can contain millions of mistakes; past this many we only count them.
  static constexpr std::size_t kMaxLines = 100;

  explicit ErrorLog(std::string_view file_label, ReadFor purpose = ReadFor::rendering)
      : file_(file_label), purpose_(purpose) {}

  // `where` is a JSON path ("objects[3].material") or a text position; empty for the whole file.
  void add(std::string_view where, std::string_view message) {
    ++count_;
    if (lines_.size() < kMaxLines) lines_.push_back(line(where, message));
  }

  // A problem that stops rendering but not editing (see ReadFor).
  void add_unrenderable(std::string_view where, std::string_view message) {
    if (purpose_ == ReadFor::rendering) return add(where, message);
    if (warnings_.size() < kMaxLines) warnings_.push_back(line(where, message));
  }
  std::vector<std::string> take_warnings() { return std::move(warnings_); }

  std::size_t count() const { return count_; }
  bool empty() const { return count_ == 0; }

  // The lines, with a final summary when some were left out.
  std::vector<std::string> take() {
    std::vector<std::string> out = std::move(lines_);
    if (count_ > out.size()) {
      out.push_back(file_ + ": " + std::to_string(count_ - out.size()) + " more problems not shown");
    }
    lines_.clear();
    count_ = 0;
    return out;
  }

 private:
  std::string line(std::string_view where, std::string_view message) const {
    std::string out = file_;
    if (!out.empty()) out += ": ";
    if (!where.empty()) {
      out += where;
      out += ": ";
    }
    out += message;
    return out;
  }

  std::string file_;
  ReadFor purpose_;
  std::vector<std::string> lines_, warnings_;
  std::size_t count_ = 0;
};

// "objects[3]" + "material" -> "objects[3].material"; a key at the top level has no dot.
inline std::string child_path(std::string_view path, std::string_view key) {
  std::string out(path);
  if (!out.empty()) out += '.';
  out += key;
  return out;
}

inline std::string element_path(std::string_view path, std::size_t index) {
  std::string out(path);
  out += '[';
  out += std::to_string(index);
  out += ']';
  return out;
}

// A user's string in a message: quoted, control characters escaped, and cut short
// (a hostile value may be megabytes long).
inline std::string in_quotes(std::string_view s) {
  constexpr std::size_t kMaxShown = 60;
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size() && i < kMaxShown; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (s.size() > kMaxShown) out += "...";
  return out + "\"";
}

}  // namespace inkray
