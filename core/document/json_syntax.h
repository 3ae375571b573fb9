// Strict JSON text -> nlohmann::json for scene files. Syntax errors get a line and
// column, overflowing numbers and duplicate keys get their JSON path, and nesting is
// bounded so a hostile file cannot exhaust the stack.
#pragma once

#include "core/base/cancel.h"
#include "core/document/error_log.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string_view>

namespace inkray {

// Far deeper than any scene needs (the deepest value, a colour of a ramp stop on a
// material graph's node, is at depth 8).
inline constexpr std::size_t kMaxJsonDepth = 64;

// The document, or nullopt after an error that stops parsing (logged). Duplicate keys
// are logged without stopping, so the reader can report the file's other problems too.
// A 60 MB scene takes seconds to parse: `cancel` is checked every few thousand values
// and stops it with kCancelledReading logged.
std::optional<nlohmann::json> parse_json_document(std::string_view text, ErrorLog& log,
                                                  const Cancel& cancel = {});

inline constexpr std::string_view kCancelledReading = "cancelled while reading the scene";

}  // namespace inkray
