// How a parameter reads in the editor (params.h has what each list declares): its
// label, its tooltip in plain text, what its slider spans and which files it takes.
#pragma once

#include "core/document/desc.h"

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// "time_limit" -> "Time limit", "spp" -> "Samples per pixel", "ior" -> "IOR",
// "color1" -> "Colour 1": underscores become spaces, known abbreviations are spelled out.
std::string derived_label(std::string_view key);
// The Param's own label, else the derived one.
std::string param_label(const Param& p);

// Markdown as plain text: backticks and emphasis asterisks go; a `*` between spaces
// (a product, "color * strength") stays.
std::string plain_text(std::string_view markdown);
// The doc as plain text, the JSON key, and for sliders and drags how to type a value.
std::string param_tooltip(const Param& p, bool typed_value);

// What a number's slider spans: its soft range, else the hard range when that is
// small enough to slide. None: a drag whose speed follows the value (or not a number).
struct SliderRange {
  double min = 0.0, max = 1.0;
  bool logarithmic = false;
};
std::optional<SliderRange> slider_range(const Param& p);
// Decimals shown on a float slider. ImGui's logarithmic sliders treat values closer
// to 0 than the last shown decimal as 0, so a log slider shows enough of them.
int slider_decimals(const SliderRange& range);

// The extensions the browse dialog offers ("" extension list: every file).
std::span<const std::string_view> file_extensions(FileType type);
// A chosen file as a path parameter stores it: relative to the scene's folder when
// inside it (generic separators), else absolute.
std::string path_in_scene(const std::filesystem::path& chosen, const std::filesystem::path& scene_dir);

}  // namespace inkray
