#include "core/document/param_text.h"

#include "core/document/tagged_variant.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <utility>

namespace inkray {
namespace {

// Words of JSON keys that read poorly as they are.
constexpr std::array<std::pair<std::string_view, std::string_view>, 12> kSpelledWords = {{
    {"spp", "samples per pixel"},
    {"vfov", "vertical field of view"},
    {"fac", "factor"},
    {"color", "colour"},
    {"uv", "UV"},
    {"ior", "IOR"},
    {"hsv", "HSV"},
    {"rgb", "RGB"},
    {"srgb", "sRGB"},
    {"aov", "AOV"},
    {"id", "ID"},
    {"obj", "OBJ"},
}};

std::string spelled(std::string_view word) {
  for (const auto& [key, text] : kSpelledWords)
    if (word == key) return std::string(text);
  // Single letters name axes and operands: "edge_u" -> "Edge U", "a" -> "A".
  if (word.size() == 1) return std::string(1, char(std::toupper(static_cast<unsigned char>(word[0]))));
  return std::string(word);
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_space(char c) { return c == ' ' || c == '\n' || c == '\t'; }

}  // namespace

std::string derived_label(std::string_view key) {
  // Words: split at underscores and where letters turn into digits ("color1").
  std::vector<std::string> words;
  std::string word;
  for (size_t i = 0; i < key.size(); ++i) {
    const char c = key[i];
    if (c == '_') {
      if (!word.empty()) words.push_back(spelled(word)), word.clear();
      continue;
    }
    if (is_digit(c) && !word.empty() && !is_digit(word.back())) words.push_back(spelled(word)), word.clear();
    word += c;
  }
  if (!word.empty()) words.push_back(spelled(word));
  std::string label;
  for (const std::string& w : words) label += (label.empty() ? "" : " ") + w;
  // Capitalised unless the first word has its own capitals ("sRGB").
  if (!label.empty() && std::none_of(words.front().begin(), words.front().end(),
                                     [](char c) { return std::isupper(static_cast<unsigned char>(c)); }))
    label[0] = char(std::toupper(static_cast<unsigned char>(label[0])));
  return label;
}

std::string param_label(const Param& p) {
  return p.label.empty() ? derived_label(p.name) : std::string(p.label);
}

std::string plain_text(std::string_view markdown) {
  std::string out;
  for (size_t i = 0; i < markdown.size(); ++i) {
    const char c = markdown[i];
    if (c == '`') continue;
    if (c == '*') {
      // A run of asterisks is emphasis when it touches a word on one side only.
      size_t end = i;
      while (end < markdown.size() && markdown[end] == '*') ++end;
      const bool space_before = i == 0 || is_space(markdown[i - 1]);
      const bool space_after = end == markdown.size() || is_space(markdown[end]);
      if (space_before != space_after) {
        i = end - 1;
        continue;
      }
    }
    out += c;
  }
  return out;
}

std::string param_tooltip(const Param& p, bool typed_value) {
  std::string text = plain_text(p.doc);
  if (!text.empty()) text += "\n\n";
  text += "JSON key: " + std::string(p.name);
  if (typed_value) text += "\nCtrl+click to type a value.";
  return text;
}

std::optional<SliderRange> slider_range(const Param& p) {
  if (p.kind != ParamKind::number && p.kind != ParamKind::integer) return std::nullopt;
  if (std::isfinite(p.soft_min) && std::isfinite(p.soft_max))
    return SliderRange{std::max(p.soft_min, p.min), std::min(p.soft_max, p.max), p.logarithmic};
  if (!std::isfinite(p.min) || !std::isfinite(p.max)) return std::nullopt;
  // Wider hard ranges without a soft one are drags: a slider over them jumps.
  const double widest = p.kind == ParamKind::integer ? 64.0 : 1000.0;
  if (p.max - p.min > widest) return std::nullopt;
  return SliderRange{p.min, p.max, false};
}

int slider_decimals(const SliderRange& range) {
  if (!range.logarithmic || range.min <= 0.0) return 3;
  return std::clamp(int(std::ceil(-std::log10(range.min))) + 1, 3, 7);
}

std::span<const std::string_view> file_extensions(FileType type) {
  // What core/image reads (stb through image_guard.h) and core/geometry's OBJ reader.
  static constexpr std::array<std::string_view, 6> kImages = {".png", ".jpg", ".jpeg",
                                                              ".hdr", ".bmp", ".tga"};
  static constexpr std::array<std::string_view, 1> kMeshes = {".obj"};
  // Brushes are masks: formats with an alpha channel.
  static constexpr std::array<std::string_view, 3> kBrushes = {".png", ".tga", ".bmp"};
  switch (type) {
    case FileType::image:
      return kImages;
    case FileType::mesh:
      return kMeshes;
    case FileType::brush:
      return kBrushes;
    case FileType::none:
      break;
  }
  return {};
}

std::string path_in_scene(const std::filesystem::path& chosen, const std::filesystem::path& scene_dir) {
  const std::filesystem::path file = chosen.lexically_normal();
  if (scene_dir.empty()) return file.generic_string();
  const std::filesystem::path relative = file.lexically_relative(scene_dir.lexically_normal());
  const bool inside = !relative.empty() && *relative.begin() != ".." && relative.is_relative();
  return inside ? relative.generic_string() : file.generic_string();
}

}  // namespace inkray
