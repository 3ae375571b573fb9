// The NPR parts of the scene document: outline settings and painterly stroke
// emitters. Included by desc.h.
#pragma once

#include "core/math/types.h"
#include "core/document/line_set_desc.h"
#include "core/document/params.h"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// ---------------------------------------------------------------- outlines
enum class LineWidthUnit { pixels, percent, world };
inline constexpr std::array<std::string_view, 3> kLineWidthUnitNames = {"pixels", "percent", "world"};

// One line type: on or off, with its own colour, width and opacity.
struct LineStyleDesc {
  bool enabled = false;
  Color color{0.f};
  float width = 1.f;  // multiplies OutlineDesc::width
  float opacity = 1.f;
  float threshold = 0.f;  // crease: angle in degrees; depth: relative jump; unused otherwise
  bool operator==(const LineStyleDesc&) const = default;
};
template <>
struct ParamTable<LineStyleDesc> {
  static constexpr auto rows = std::tuple{
      row(&LineStyleDesc::enabled, at(Stage::sampling, toggle("enabled", "Draw this line type"))),
      row(&LineStyleDesc::color,
          at(Stage::resolve,
             color("color", 1e3, "Line colour (applied when the image is resolved: no re-render)"))),
      row(&LineStyleDesc::width, at(Stage::sampling, number("width", 0, 100, "Multiplies the outline width")
                                                         .log_slider(0.1, 10)
                                                         .labelled("Width scale"))),
      row(&LineStyleDesc::opacity, at(Stage::resolve, number("opacity", 0, 1, "Line opacity"))),
      row(&LineStyleDesc::threshold,
          at(Stage::sampling,
             number("threshold", 0, 1e6, "Crease: angle in degrees; depth: relative distance jump")
                 .log_slider(0.01, 180)))};
};

struct OutlineDesc {
  int quality = 1;       // stencil rays per camera sample
  bool adaptive = true;  // trace stencil rays only where lines are still uncertain
  float width = 2.f;
  LineWidthUnit unit = LineWidthUnit::pixels;
  float reference_height = 1080.f;  // `pixels` are pixels of an image this tall
  float distance_falloff = 0.f;     // 0: constant width; 1: width shrinks as 1/distance beyond falloff_start
  float falloff_start = 10.f;
  bool in_reflections = true;  // follow mirror and glass to the surface seen through them
  LineStyleDesc silhouette{true, Color(0.f), 1.f, 1.f, 0.f};
  LineStyleDesc object{true, Color(0.f), 1.f, 1.f, 0.f};
  LineStyleDesc material{false, Color(0.f), 1.f, 1.f, 0.f};
  LineStyleDesc crease{false, Color(0.f), 0.75f, 1.f, 30.f};
  LineStyleDesc depth{false, Color(0.f), 1.f, 1.f, 0.1f};
  LineStyleDesc intersection{false, Color(0.f), 1.f, 1.f, 0.f};
  bool enabled = false;  // master switch; a scene without "outlines" draws none
  // Line sets: with none, each line type is drawn pixel by pixel in its own colour as
  // above; with any, the lines are chained and drawn as the sets' styled strokes.
  std::vector<LineSetDesc> sets{};

  bool any_line() const {
    return enabled && (silhouette.enabled || object.enabled || material.enabled || crease.enabled ||
                       depth.enabled || intersection.enabled);
  }
  bool operator==(const OutlineDesc&) const = default;
};
template <>
struct ParamTable<OutlineDesc> {
  static constexpr auto rows = std::tuple{
      row(&OutlineDesc::enabled, at(Stage::sampling, toggle("enabled", "Draw outlines"))),
      row(&OutlineDesc::quality,
          at(Stage::sampling,
             integer("quality", 1, 16,
                     "Stencil rays per camera sample: more give clean lines in fewer samples")
                 .labelled("Line quality"))),
      row(&OutlineDesc::adaptive,
          at(Stage::sampling, toggle("adaptive",
                                     "Trace stencil rays only where a pixel's lines are still uncertain; the "
                                     "converged lines are the same")
                                  .labelled("Adaptive line sampling"))),
      row(&OutlineDesc::width,
          at(Stage::sampling,
             number("width", 0, 1000,
                    "Line width in `unit`; below one pixel a line fades instead of thinning, 0 draws none")
                 .log_slider(0.1, 20)
                 .labelled("Line width"))),
      row(&OutlineDesc::unit,
          at(Stage::sampling,
             choice("unit", kLineWidthUnitNames,
                    "pixels (at reference_height), percent of image height, or world units"))),
      row(&OutlineDesc::reference_height,
          at(Stage::sampling, number("reference_height", 1, 1e5, "Image height that `pixels` refer to")
                                  .log_slider(240, 4320))),
      row(&OutlineDesc::distance_falloff,
          at(Stage::sampling,
             number("distance_falloff", 0, 4,
                    "Width shrinks as (falloff_start / distance)^falloff beyond falloff_start"))),
      row(&OutlineDesc::falloff_start,
          at(Stage::sampling,
             number("falloff_start", 0, 1e9, "Distance where the falloff begins").log_slider(0.1, 1000))),
      row(&OutlineDesc::in_reflections,
          at(Stage::sampling, toggle("in_reflections", "Lines appear in mirrors and through glass")
                                  .labelled("Show in reflections"))),
      row(&OutlineDesc::silhouette,
          group("silhouette", "Where a surface meets the background or a surface behind it")),
      row(&OutlineDesc::object, group("object", "Where one object meets another")),
      row(&OutlineDesc::material, group("material", "Where materials change")),
      row(&OutlineDesc::crease, group("crease",
                                      "Where the normal bends by more than `threshold` degrees; on meshes, "
                                      "along feature edges sharper than that")),
      row(&OutlineDesc::depth,
          group("depth", "Where one surface occludes another more than `threshold` (relative) further away")),
      row(&OutlineDesc::intersection, group("intersection", "Where two objects cross")),
      row(&OutlineDesc::sets,
          at(Stage::resolve, list("sets",
                                  "Line sets: each takes the lines of some types, objects and paths and "
                                  "draws them as strokes in its style; none draws plain lines")))};
};

// ---------------------------------------------------------------- painterly strokes
enum class BrushKind { bristle, flat, image };
inline constexpr std::array<std::string_view, 3> kBrushKindNames = {"bristle", "flat", "image"};

struct StrokeEmitterDesc {
  std::string name;
  std::string object;  // the object the strokes grow on
  int seed = 1;
  int count = 1000;
  float width_min = 0.02f, width_max = 0.05f;  // world units
  float length_min = 0.1f, length_max = 0.25f;
  Vec3 flow{0.f, 1.f, 0.f};      // projected on the tangent plane
  float rotation_jitter = 15.f;  // degrees
  float hue_jitter = 8.f;        // degrees
  float saturation_jitter = 0.1f;
  float value_jitter = 0.1f;
  BrushKind brush = BrushKind::bristle;
  std::string brush_image{};  // PNG with alpha, for BrushKind::image; {}: initialisers may omit it
  float bristles = 12.f;      // procedural bristle count across the stroke
  float pressure = 0.7f;      // alpha falloff along the stroke
  int segments = 8;           // ribbon segments along each stroke
  float offset = 0.f;         // lift above the surface, world units; 0 picks one from the object's size
  bool indirect = false;      // light bouncing off diffuse and glossy surfaces sees the strokes
  bool operator==(const StrokeEmitterDesc&) const = default;
};
template <>
struct ParamTable<StrokeEmitterDesc> {
  static constexpr auto rows = std::tuple{
      row(&StrokeEmitterDesc::name, text("name", "Unique emitter name")),
      row(&StrokeEmitterDesc::object,
          required(text("object", "Object the strokes grow on")).refers(Ref::object)),
      row(&StrokeEmitterDesc::seed,
          integer("seed", 0, 2147483647, "Placement seed: the same seed gives the same strokes")),
      row(&StrokeEmitterDesc::count, integer("count", 0, 10000000, "Number of strokes").log_slider(10, 1e6)),
      row(&StrokeEmitterDesc::width_min, number("width_min", 0, 1e6, "Smallest stroke width, world units")
                                             .log_slider(0.001, 1)
                                             .labelled("Smallest width")),
      row(&StrokeEmitterDesc::width_max, number("width_max", 0, 1e6, "Largest stroke width, world units")
                                             .log_slider(0.001, 1)
                                             .labelled("Largest width")),
      row(&StrokeEmitterDesc::length_min, number("length_min", 0, 1e6, "Shortest stroke length, world units")
                                              .log_slider(0.01, 10)
                                              .labelled("Shortest length")),
      row(&StrokeEmitterDesc::length_max, number("length_max", 0, 1e6, "Longest stroke length, world units")
                                              .log_slider(0.01, 10)
                                              .labelled("Longest length")),
      row(&StrokeEmitterDesc::flow, direction("flow", "Flow direction, projected on the surface")),
      row(&StrokeEmitterDesc::rotation_jitter,
          number("rotation_jitter", 0, 180, "Random rotation about the normal, degrees")),
      row(&StrokeEmitterDesc::hue_jitter, number("hue_jitter", 0, 180, "Random hue shift, degrees")),
      row(&StrokeEmitterDesc::saturation_jitter,
          number("saturation_jitter", 0, 1, "Random saturation change")),
      row(&StrokeEmitterDesc::value_jitter, number("value_jitter", 0, 1, "Random value change")),
      row(&StrokeEmitterDesc::brush,
          choice("brush", kBrushKindNames, "Brush: procedural bristle or flat, or an image")),
      row(&StrokeEmitterDesc::brush_image,
          path("brush_image", "Brush image (PNG with alpha), for brush \"image\"").files(FileType::brush)),
      row(&StrokeEmitterDesc::bristles,
          number("bristles", 1, 256, "Bristle count across a procedural stroke").log_slider(1, 64)),
      row(&StrokeEmitterDesc::pressure, number("pressure", 0, 1, "Alpha falloff along the stroke")),
      row(&StrokeEmitterDesc::segments,
          integer("segments", 1, 64,
                  "Most ribbon segments along each stroke; fewer where the surface is flat")),
      row(&StrokeEmitterDesc::offset,
          number("offset", 0, 1e6, "Lift above the surface; 0 picks one from the object's size")
              .log_slider(0.001, 1)
              .labelled("Lift")),
      row(&StrokeEmitterDesc::indirect, toggle("indirect",
                                               "Light bouncing off diffuse and glossy surfaces sees the "
                                               "strokes; off, it sees the object under them (faster)")
                                            .labelled("In bounce light"))};
};

}  // namespace inkray
