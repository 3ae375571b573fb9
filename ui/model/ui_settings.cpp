#include "ui/model/ui_settings.h"

#include "core/io/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace inkray {
namespace {

struct Field {
  const char* key;
  float UiSettings::*scalar = nullptr;
  float PanelLayout::*layout = nullptr;
};

constexpr Field kFields[] = {
    {"ui_scale", &UiSettings::ui_scale, nullptr},
    {"scene_width", nullptr, &PanelLayout::scene_width},
    {"properties_width", nullptr, &PanelLayout::properties_width},
    {"output_height", nullptr, &PanelLayout::output_height},
    {"node_split", nullptr, &PanelLayout::node_split},
};

float& field_of(UiSettings& s, const Field& f) { return f.scalar ? s.*f.scalar : s.layout.*f.layout; }

}  // namespace

UiSettings read_ui_settings(const std::filesystem::path& file, std::vector<std::string>* problems) {
  UiSettings settings;
  std::ifstream in(file);
  if (!in) return settings;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string key;
    float value = 0.f;
    words >> key;
    const auto field =
        std::find_if(std::begin(kFields), std::end(kFields), [&](const Field& f) { return key == f.key; });
    const std::string where = file.string() + ":" + std::to_string(number) + ": ";
    if (field == std::end(kFields)) {
      if (problems) problems->push_back(where + "unknown setting \"" + key + "\"");
    } else if (!(words >> value) || !std::isfinite(value)) {
      if (problems) problems->push_back(where + "\"" + key + "\" needs a number");
    } else {
      field_of(settings, *field) = value;
    }
  }
  settings.ui_scale = std::clamp(settings.ui_scale, kMinUiScale, kMaxUiScale);
  settings.layout = sanitized(settings.layout);
  return settings;
}

bool write_ui_settings(const std::filesystem::path& file, const UiSettings& settings, std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  std::ostringstream out;
  out << "# inkray editor settings\n";
  UiSettings copy = settings;
  for (const Field& f : kFields) out << f.key << ' ' << field_of(copy, f) << '\n';
  return write_file_atomically(file, out.str(), error);
}

}  // namespace inkray
