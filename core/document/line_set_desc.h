// Line sets in the document (docs/architecture.md, "Lines as strokes"): which
// chains of a render a set selects, and the style it draws them in. Every field
// is a resolve-stage parameter: a set's edit redraws the lines over the samples
// already taken. Included by npr_desc.h.
#pragma once

#include "core/document/params.h"
#include "core/math/types.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// What a chain's value along it is read from, for its width, colour and opacity.
enum class LineModulation : uint8_t {
  none,       // constant
  along,      // from the chain's start (0) to its end (1)
  depth,      // near (0) to far (1) over the chains of the image
  curvature,  // straight (0) to turning by a radian per 10 pixels at 1080 lines or more (1)
  light,      // dark (0) to light (1) under the line
  coverage,   // how solidly the line was found: its resolved opacity
};
inline constexpr std::array<std::string_view, 6> kLineModulationNames = {"none",      "along", "depth",
                                                                         "curvature", "light", "coverage"};

// A point of a style's pressure curve: the width multiplier at a fraction of the
// chain's length, as a pen pressed harder or lighter along the stroke.
struct PressurePoint {
  float at = 0.f;     // fraction of the chain's length from its start, [0, 1]
  float width = 1.f;  // width multiplier there
  bool operator==(const PressurePoint&) const = default;
};
template <>
struct ParamTable<PressurePoint> {
  static constexpr auto rows =
      std::tuple{row(&PressurePoint::at, number("at", 0, 1, "Fraction of the line's length from its start")),
                 row(&PressurePoint::width, number("width", 0, 100, "Width multiplier there").slider(0, 2))};
};

// A set's style, the same block in the document and in the compiled line set
// (LineStyle, core/world/line_sets.h). Lengths are pixels of an image 1080 lines
// tall, scaled with the image as the painterly filter's radius is, so a look holds
// from the editor's preview to a 4K render.
struct LineStyleParams {
  Color color{0.f};
  Color color_end{0.f};  // the colour where color_by reads 1
  LineModulation color_by = LineModulation::none;
  float opacity = 1.f;
  float opacity_min = 1.f;  // opacity multiplier where opacity_by reads 1
  LineModulation opacity_by = LineModulation::none;
  float width = 2.f;      // pixels at 1080 lines
  float width_min = 1.f;  // width multiplier where width_by reads 1
  LineModulation width_by = LineModulation::none;
  float taper_start = 0.f;  // fraction of the chain's length over which it grows from nothing
  float taper_end = 0.f;    // ... and shrinks to nothing at its end
  // Width multiplier along the chain through these points (in any order), joined by
  // straight segments and flat past the first and last; none: 1.
  std::vector<PressurePoint> pressure{};
  float brush_repeat = 0.f;   // pixels of chain per brush image; 0: stretched over the whole chain
  float jitter = 0.f;         // amplitude of the noise that displaces the line across itself, pixels
  float jitter_scale = 20.f;  // wavelength of that noise along the chain, pixels
  float overshoot = 0.f;      // extension past both ends along the end tangents, pixels
  int passes = 1;             // strokes drawn over each chain, each with its own noise
  float dash = 0.f;           // dash length, pixels; 0: unbroken
  float gap = 0.f;            // gap between dashes, pixels
  float min_length = 0.f;     // chains shorter than this are not drawn, pixels
  float corner_angle = 0.f;   // degrees: chains split where they turn more sharply than 180 - this; 0 never
  int seed = 0;               // the noise of jitter and passes
  bool operator==(const LineStyleParams&) const = default;
};

// What is stretched along a styled line: nothing (a solid line), a procedural
// brush or an image (the painterly strokes' brushes, core/npr/strokes/brush.h).
enum class LineBrush { none, bristle, flat, image };
inline constexpr std::array<std::string_view, 4> kLineBrushNames = {"none", "bristle", "flat", "image"};

struct LineSetStyleDesc : LineStyleParams {
  LineBrush brush = LineBrush::none;
  std::string brush_image{};  // PNG with alpha, for LineBrush::image
  bool operator==(const LineSetStyleDesc&) const = default;
};
template <>
struct ParamTable<LineSetStyleDesc> {
  static constexpr auto rows = std::tuple{
      row(&LineSetStyleDesc::color, color("color", 1e3, "Line colour, a display colour")),
      row(&LineSetStyleDesc::color_end,
          color("color_end", 1e3, "Colour where color_by reads 1").labelled("Second colour")),
      row(&LineSetStyleDesc::color_by,
          choice("color_by", kLineModulationNames, "What blends the colour towards color_end")
              .labelled("Colour by")),
      row(&LineSetStyleDesc::opacity, number("opacity", 0, 1, "Line opacity")),
      row(&LineSetStyleDesc::opacity_min,
          number("opacity_min", 0, 1, "Opacity multiplier where opacity_by reads 1")
              .labelled("Least opacity")),
      row(&LineSetStyleDesc::opacity_by,
          choice("opacity_by", kLineModulationNames, "What fades the opacity towards opacity_min")
              .labelled("Opacity by")),
      row(&LineSetStyleDesc::width,
          number("width", 0, 1000, "Line width, pixels of an image 1080 lines tall").log_slider(0.25, 40)),
      row(&LineSetStyleDesc::width_min, number("width_min", 0, 10, "Width multiplier where width_by reads 1")
                                            .slider(0, 2)
                                            .labelled("Least width")),
      row(&LineSetStyleDesc::width_by,
          choice("width_by", kLineModulationNames, "What thins (or thickens) the line towards width_min")
              .labelled("Width by")),
      row(&LineSetStyleDesc::taper_start,
          number("taper_start", 0, 1, "Fraction of the line's length over which it swells from nothing")),
      row(&LineSetStyleDesc::taper_end,
          number("taper_end", 0, 1, "Fraction of the line's length over which it thins to nothing")),
      row(&LineSetStyleDesc::pressure,
          list("pressure",
               "Pressure curve: width multipliers along the line, points {\"at\": fraction of its length, "
               "\"width\": multiplier} joined by straight segments; none: 1")),
      row(&LineSetStyleDesc::brush,
          choice("brush", kLineBrushNames,
                 "Texture along the line: none (solid), bristle, flat or an image")),
      row(&LineSetStyleDesc::brush_image,
          path("brush_image",
               "Brush image (PNG with alpha), for brush \"image\": the stroke runs along its x axis")
              .files(FileType::brush)),
      row(&LineSetStyleDesc::brush_repeat,
          number("brush_repeat", 0, 1e5, "Pixels of line per brush image; 0 stretches it over the whole line")
              .log_slider(4, 400)),
      row(&LineSetStyleDesc::jitter,
          number("jitter", 0, 100, "Amplitude of the wobble across the line, pixels").slider(0, 5)),
      row(&LineSetStyleDesc::jitter_scale,
          number("jitter_scale", 0.5, 1e4, "Wavelength of the wobble along the line, pixels")
              .log_slider(2, 200)),
      row(&LineSetStyleDesc::overshoot,
          number("overshoot", 0, 1000, "Extension past both ends, pixels").slider(0, 20)),
      row(&LineSetStyleDesc::passes,
          integer("passes", 1, 16, "Strokes drawn over each line, each with its own wobble")),
      row(&LineSetStyleDesc::dash, number("dash", 0, 1e4, "Dash length, pixels; 0: unbroken").slider(0, 40)),
      row(&LineSetStyleDesc::gap, number("gap", 0, 1e4, "Gap between dashes, pixels").slider(0, 40)),
      row(&LineSetStyleDesc::min_length,
          number("min_length", 0, 1e5, "Lines shorter than this are not drawn, pixels")
              .slider(0, 100)
              .labelled("Shortest line")),
      row(&LineSetStyleDesc::corner_angle,
          number("corner_angle", 0, 180,
                 "Lines split where they turn more sharply than 180 minus this, degrees; 0 never")
              .labelled("Split at corners")),
      row(&LineSetStyleDesc::seed, integer("seed", 0, 2147483647, "Seed of the wobble"))};
};

inline constexpr std::array<std::string_view, 6> kLinePresetNames = {
    "ink", "pencil", "brush", "sketch", "technical", "technical_hidden"};
// The editor's presets of a style (core/document/line_presets.cpp):
//   ink:              3 px black, tapered at both ends
//   pencil:           1.2 px grey, two slightly jittered passes
//   brush:            5 px, tapered, the bristle brush
//   sketch:           three loose passes, jittered and overshooting, translucent
//   technical:        1.5 px, even, unbroken
//   technical_hidden: the same dashed 6 / 4, for hidden lines
template <>
struct ParamPresets<LineSetStyleDesc> {
  static constexpr const auto& names = kLinePresetNames;
  // Replaces the whole style with the preset's; an unknown name gives the default style.
  static void apply(std::string_view name, LineSetStyleDesc& style);
};

// Which line types a set takes.
struct LineTypeChoice {
  bool silhouette = true, object = true, material = true, crease = true, depth = true, intersection = true;
  bool operator==(const LineTypeChoice&) const = default;
};
template <>
struct ParamTable<LineTypeChoice> {
  static constexpr auto rows =
      std::tuple{row(&LineTypeChoice::silhouette, toggle("silhouette", "Silhouette lines")),
                 row(&LineTypeChoice::object, toggle("object", "Lines between objects")),
                 row(&LineTypeChoice::material, toggle("material", "Lines between materials")),
                 row(&LineTypeChoice::crease, toggle("crease", "Crease lines")),
                 row(&LineTypeChoice::depth, toggle("depth", "Depth lines")),
                 row(&LineTypeChoice::intersection, toggle("intersection", "Lines where objects cross"))};
};

// Which ways to the camera a set takes: seen directly, in a mirror, through glass.
struct LinePathChoice {
  bool direct = true, reflected = true, refracted = true;
  bool operator==(const LinePathChoice&) const = default;
};
template <>
struct ParamTable<LinePathChoice> {
  static constexpr auto rows =
      std::tuple{row(&LinePathChoice::direct, toggle("direct", "Lines seen directly")),
                 row(&LinePathChoice::reflected, toggle("reflected", "Lines seen in mirrors")),
                 row(&LinePathChoice::refracted, toggle("refracted", "Lines seen through glass"))};
};

// Whether a set takes the lines the camera sees, those behind other surfaces
// (hidden lines, found along the meshes' edges: core/npr/lines/hidden_lines.h), or both.
enum class LineVisibility { visible, hidden, both };
inline constexpr std::array<std::string_view, 3> kLineVisibilityNames = {"visible", "hidden", "both"};

struct LineSetDesc {
  std::string name;
  bool enabled = true;
  LineTypeChoice types;
  LinePathChoice paths;
  LineVisibility visibility = LineVisibility::visible;
  std::string objects{};    // names or patterns with * and ?, separated by commas; empty: all
  std::string materials{};  // likewise
  LineSetStyleDesc style;
  bool operator==(const LineSetDesc&) const = default;
};
template <>
struct ParamTable<LineSetDesc> {
  static constexpr auto rows = std::tuple{
      row(&LineSetDesc::name, text("name", "Name of the set; a layer of that name in SVG files")),
      row(&LineSetDesc::enabled, toggle("enabled", "Draw this set")),
      row(&LineSetDesc::types, group("types", "Line types the set takes")),
      row(&LineSetDesc::paths,
          group("paths", "Whether the set takes lines seen directly, in mirrors, through glass")),
      row(&LineSetDesc::visibility,
          choice("visibility", kLineVisibilityNames,
                 "Lines the camera sees, hidden lines (silhouettes and creases of meshes and spheres behind "
                 "other surfaces), or both")),
      row(&LineSetDesc::objects,
          text("objects",
               "Objects whose lines the set takes: names or patterns with * and ?, separated by "
               "commas; empty takes every object")),
      row(&LineSetDesc::materials,
          text("materials", "Materials whose lines the set takes, as objects; empty takes every material")),
      row(&LineSetDesc::style, group("style", "How the set draws its lines"))};
};

}  // namespace inkray
