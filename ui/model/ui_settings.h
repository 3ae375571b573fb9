// The editor's own settings, kept between runs in <config dir>/editor.txt (ui/model/app_paths.h):
// the UI scale and the panel sizes. One "key value" pair per line; unknown keys and bad
// values are reported and skipped, so a damaged file never stops the editor.
#pragma once

#include "ui/model/panel_layout.h"

#include <filesystem>
#include <string>
#include <vector>

namespace inkray {

struct UiSettings {
  // Multiplies the monitor's content scale; the font and every size follow it.
  float ui_scale = 1.f;
  PanelLayout layout;
  bool operator==(const UiSettings&) const = default;
};

inline constexpr float kMinUiScale = 0.5f, kMaxUiScale = 3.f;

// Defaults where the file is missing; *problems lists lines that were skipped ("FILE:LINE: ...").
UiSettings read_ui_settings(const std::filesystem::path& file, std::vector<std::string>* problems);
// Written atomically; false with *error naming the file.
bool write_ui_settings(const std::filesystem::path& file, const UiSettings& settings, std::string* error);

}  // namespace inkray
