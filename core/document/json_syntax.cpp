// A SAX handler that builds the DOM itself, because nlohmann's own DOM parser turns
// a number overflow (1e400) into an exception without a position and silently keeps
// the last of duplicate keys; here both become error lines naming where they are.
#include "core/document/json_syntax.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace inkray {
namespace {

using Json = nlohmann::json;

// nlohmann reports the number of bytes read; editors show lines and columns.
std::string text_position(std::string_view text, std::size_t bytes_read) {
  const std::size_t last = std::min(bytes_read, text.size());  // one past the offending byte
  const std::size_t offending = last > 0 ? last - 1 : 0;
  const std::string_view before = text.substr(0, offending);
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
  const std::size_t line_start = before.rfind('\n');
  const std::size_t column = line_start == std::string_view::npos ? offending + 1 : offending - line_start;
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error ..." -> "syntax error ...".
std::string strip_exception_prefix(std::string_view what) {
  const std::size_t tag_end = what.find("] ");
  if (tag_end != std::string_view::npos) what.remove_prefix(tag_end + 2);
  if (what.starts_with("parse error")) {
    const std::size_t colon = what.find(": ");
    if (colon != std::string_view::npos) what.remove_prefix(colon + 2);
  }
  return std::string(what);
}

class DomBuilder final : public nlohmann::json_sax<Json> {
 public:
  DomBuilder(std::string_view text, ErrorLog& log, const Cancel& cancel)
      : text_(text), log_(log), cancel_(cancel) {}

  Json take_root() { return std::move(root_); }

  bool null() override { return add(Json(nullptr)); }
  bool boolean(bool value) override { return add(Json(value)); }
  bool number_integer(number_integer_t value) override { return add(Json(value)); }
  bool number_unsigned(number_unsigned_t value) override { return add(Json(value)); }
  bool number_float(number_float_t value, const string_t&) override { return add(Json(value)); }
  bool string(string_t& value) override { return add(Json(std::move(value))); }
  bool binary(binary_t& value) override { return add(Json::binary(std::move(value))); }

  bool start_object(std::size_t) override { return open(Json::object()); }
  bool start_array(std::size_t) override { return open(Json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& name) override {
    Frame& frame = frames_.back();
    if (frame.value->contains(name)) log_.add(container_path(), "duplicate key " + in_quotes(name));
    frame.key = std::move(name);
    return true;
  }

  bool parse_error(std::size_t position, const std::string& last_token, const Json::exception& ex) override {
    constexpr int kNumberOverflow = 406;
    if (ex.id == kNumberOverflow) {
      log_.add(next_value_path(),
               "number " + last_token + " is out of range (" + text_position(text_, position) + ")");
    } else {
      log_.add(text_position(text_, position), strip_exception_prefix(ex.what()));
    }
    return false;
  }

 private:
  struct Frame {
    Json* value;      // an object or array being filled
    std::string key;  // the key of the next member, for objects
  };

  Json* slot_for_next_value() {
    if (frames_.empty()) return &root_;
    Frame& frame = frames_.back();
    if (frame.value->is_array()) {
      frame.value->push_back(nullptr);
      return &frame.value->back();
    }
    return &(*frame.value)[frame.key];
  }

  bool add(Json&& value) {
    *slot_for_next_value() = std::move(value);
    return true;
  }

  bool open(Json&& container) {
    if ((++containers_ & 4095) == 0 && cancel_.requested()) {
      log_.add("", kCancelledReading);
      return false;
    }
    if (frames_.size() >= kMaxJsonDepth) {
      log_.add(container_path(),
               "values are nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
      return false;
    }
    // The parent cannot grow while this child is open, so the pointer stays valid.
    Json* slot = slot_for_next_value();
    *slot = std::move(container);
    frames_.push_back({slot, {}});
    return true;
  }

  bool close() {
    frames_.pop_back();
    return true;
  }

  // Path of frames_[0..count): "objects[3].shape".
  std::string path_of(std::size_t count) const {
    std::string path;
    for (std::size_t i = 1; i < count; ++i) {
      const Frame& parent = frames_[i - 1];
      if (parent.value->is_array()) {
        path += '[';
        path += std::to_string(parent.value->size() - 1);
        path += ']';
      } else {
        if (!path.empty()) path += '.';
        path += parent.key;
      }
    }
    return path;
  }

  std::string container_path() const { return path_of(frames_.size()); }

  std::string next_value_path() const {
    std::string path = container_path();
    if (frames_.empty()) return path;
    const Frame& frame = frames_.back();
    if (frame.value->is_array()) return path + "[" + std::to_string(frame.value->size()) + "]";
    return path.empty() ? frame.key : path + "." + frame.key;
  }

  std::string_view text_;
  ErrorLog& log_;
  const Cancel& cancel_;
  std::size_t containers_ = 0;
  Json root_;
  std::vector<Frame> frames_;
};

}  // namespace

std::optional<nlohmann::json> parse_json_document(std::string_view text, ErrorLog& log,
                                                  const Cancel& cancel) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    log.add("", "the file is empty (expected a JSON object)");
    return std::nullopt;
  }
  DomBuilder builder(text, log, cancel);
  const bool ok = Json::sax_parse(text.begin(), text.end(), &builder, Json::input_format_t::json,
                                  /*strict=*/true, /*ignore_comments=*/false);
  if (!ok) return std::nullopt;
  return builder.take_root();
}

}  // namespace inkray
