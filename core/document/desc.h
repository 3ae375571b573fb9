// SceneDesc: the editable scene document (docs/architecture.md, "From JSON to
// pixels"). Plain structs with defaults, references by name, serialised to JSON
// by document/json_io. Every struct lists its parameters once in its ParamTable
// (document/params.h; docs/architecture.md, "Parameter tables").
// Closed sets are std::variants whose alternatives carry their JSON "type" tag.
#pragma once

#include "core/base/shared_list.h"
#include "core/camera/camera_params.h"
#include "core/math/types.h"
#include "core/document/animation_desc.h"
#include "core/document/filter_kinds.h"
#include "core/document/graph_desc.h"
#include "core/document/material_desc.h"
#include "core/document/npr_desc.h"
#include "core/document/params.h"

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace inkray {

inline constexpr int kSceneFormatVersion = 1;
inline constexpr std::string_view kSceneFormatName = "inkray-scene";

// A plain material is one closure node; a graph wires many nodes into an output.
using MaterialVariant = std::variant<DiffuseDesc, ConductorDesc, DielectricDesc, EmissiveDesc, UnlitDesc,
                                     TransparentDesc, ToonDesc, MixDesc, GraphDesc>;

// Per-material and per-object outline overrides.
struct LineOverrideDesc {
  bool exclude = false;     // produces no lines
  bool stop_lines = false;  // mirrors/glass: lines are not followed through this surface
  float width_scale = 1.f;
  bool override_color = false;
  Color color{0.f};
  bool operator==(const LineOverrideDesc&) const = default;
};
template <>
struct ParamTable<LineOverrideDesc> {
  static constexpr auto rows = std::tuple{
      row(&LineOverrideDesc::exclude,
          toggle("exclude", "This surface produces no outlines").labelled("No outlines")),
      row(&LineOverrideDesc::stop_lines,
          toggle("stop_lines", "Outlines are not seen through this mirror or glass")
              .labelled("Hide lines behind")),
      row(&LineOverrideDesc::width_scale,
          number("width_scale", 0, 100, "Multiplies the outline width on this surface").log_slider(0.1, 10)),
      row(&LineOverrideDesc::override_color,
          toggle("override_color", "Draw this surface's lines in `color`")),
      row(&LineOverrideDesc::color,
          color("color", 1e3, "Line colour when override_color is set").labelled("Line colour"))};
};

struct MaterialDesc {
  std::string name;
  MaterialVariant data = DiffuseDesc{};
  LineOverrideDesc lines;
  bool operator==(const MaterialDesc&) const = default;
};

// ---------------------------------------------------------------- shapes
struct SphereDesc {
  static constexpr std::string_view type_name = "sphere";
  Point3 center{0.f};
  float radius = 1.f;
  bool operator==(const SphereDesc&) const = default;
};
template <>
struct ParamTable<SphereDesc> {
  static constexpr auto rows =
      std::tuple{row(&SphereDesc::center, point("center", "Centre in object space")),
                 row(&SphereDesc::radius,
                     number("radius", 1e-12, 1e12, "Radius in object space").log_slider(0.01, 100))};
};

struct QuadDesc {
  static constexpr std::string_view type_name = "quad";
  Point3 corner{0.f};
  Vec3 edge_u{1.f, 0.f, 0.f};
  Vec3 edge_v{0.f, 0.f, 1.f};  // normal = normalize(cross(edge_u, edge_v))
  bool operator==(const QuadDesc&) const = default;
};
template <>
struct ParamTable<QuadDesc> {
  static constexpr auto rows = std::tuple{
      row(&QuadDesc::corner, point("corner", "One corner")),
      row(&QuadDesc::edge_u, vector("edge_u", "First edge from the corner")),
      row(&QuadDesc::edge_v, vector("edge_v", "Second edge; the front faces along cross(edge_u, edge_v)"))};
};

struct BoxDesc {
  static constexpr std::string_view type_name = "box";
  Point3 min{0.f};
  Point3 max{1.f};
  bool operator==(const BoxDesc&) const = default;
};
template <>
struct ParamTable<BoxDesc> {
  static constexpr auto rows = std::tuple{row(&BoxDesc::min, point("min", "Minimum corner")),
                                          row(&BoxDesc::max, point("max", "Maximum corner"))};
};

struct MeshDesc {
  static constexpr std::string_view type_name = "mesh";
  std::string path;           // Wavefront OBJ, relative to the scene file
  float smooth_angle = 30.f;  // degrees; normals for a file without them (geometry/mesh_normals.h)
  bool operator==(const MeshDesc&) const = default;
};
template <>
struct ParamTable<MeshDesc> {
  static constexpr auto rows = std::tuple{
      row(&MeshDesc::path, required(path("path", "Wavefront OBJ file, relative to the scene file"))
                               .files(FileType::mesh)
                               .labelled("OBJ file")),
      row(&MeshDesc::smooth_angle,
          number(
              "smooth_angle", 0, 180,
              "For a file without normals: shading is smooth across edges whose faces meet at most this many "
              "degrees apart and sharp at the others. 0 keeps the facets, 180 smooths everything; normals in "
              "the file are used as given")
              .slider(0, 180)
              .labelled("Auto smooth angle"))};
};

using ShapeVariant = std::variant<SphereDesc, QuadDesc, BoxDesc, MeshDesc>;

// Applied as scale, then each rotation in order, then translate.
struct RotationDesc {
  Vec3 axis{0.f, 1.f, 0.f};
  float degrees = 0.f;  // right-handed about axis
  bool operator==(const RotationDesc&) const = default;
};
template <>
struct ParamTable<RotationDesc> {
  static constexpr auto rows =
      std::tuple{row(&RotationDesc::axis, direction("axis", "Rotation axis")),
                 row(&RotationDesc::degrees, number("degrees", -1e6, 1e6, "Right-handed angle about the axis")
                                                 .slider(-180, 180)
                                                 .labelled("Angle"))};
};

struct TransformDesc {
  Vec3 scale{1.f};
  std::vector<RotationDesc> rotate;
  Vec3 translate{0.f};
  bool operator==(const TransformDesc&) const = default;
};

struct ObjectDesc {
  std::string name;
  ShapeVariant shape = SphereDesc{};
  TransformDesc transform;
  std::string material;  // name of a MaterialDesc
  bool visible = true;
  LineOverrideDesc lines;
  bool operator==(const ObjectDesc&) const = default;
};
template <>
struct ParamTable<ObjectDesc> {
  static constexpr auto rows =
      std::tuple{row(&ObjectDesc::name, text("name", "Unique object name")),
                 row(&ObjectDesc::material,
                     required(text("material", "Name of the object's material")).refers(Ref::material)),
                 row(&ObjectDesc::visible, toggle("visible", "Hidden objects are not rendered")),
                 row(&ObjectDesc::lines, group("lines", "Outline overrides for this object"))};
};

// ---------------------------------------------------------------- lights
struct PointLightDesc {
  static constexpr std::string_view type_name = "point";
  Point3 position{0.f};
  Color color{1.f};
  float intensity = 1.f;  // radiant intensity scale (W/sr)
  bool operator==(const PointLightDesc&) const = default;
};
template <>
struct ParamTable<PointLightDesc> {
  static constexpr auto rows =
      std::tuple{row(&PointLightDesc::position, point("position", "Position")),
                 row(&PointLightDesc::color, color("color", 1e6, "Colour")),
                 row(&PointLightDesc::intensity,
                     number("intensity", 0, 1e9, "Radiant intensity: color * intensity per steradian")
                         .log_slider(0.1, 1e4))};
};

struct SpotLightDesc {
  static constexpr std::string_view type_name = "spot";
  Point3 position{0.f};
  Point3 target{0.f, -1.f, 0.f};
  Color color{1.f};
  float intensity = 1.f;
  float cone_angle = 30.f;     // half-angle in degrees where light ends
  float falloff_angle = 25.f;  // half-angle in degrees where falloff starts
  bool operator==(const SpotLightDesc&) const = default;
};
template <>
struct ParamTable<SpotLightDesc> {
  static constexpr auto rows = std::tuple{
      row(&SpotLightDesc::position, point("position", "Position")),
      row(&SpotLightDesc::target, point("target", "Point the spot aims at")),
      row(&SpotLightDesc::color, color("color", 1e6, "Colour")),
      row(&SpotLightDesc::intensity,
          number("intensity", 0, 1e9, "Radiant intensity on the axis").log_slider(0.1, 1e4)),
      row(&SpotLightDesc::cone_angle,
          number("cone_angle", 0.01, 90, "Half-angle in degrees where the light ends").slider(1, 90)),
      row(&SpotLightDesc::falloff_angle,
          number("falloff_angle", 0, 90, "Half-angle in degrees where the smooth falloff starts"))};
};

struct DirectionalLightDesc {
  static constexpr std::string_view type_name = "directional";
  Vec3 direction{0.f, -1.f, 0.f};  // direction the light travels
  Color color{1.f};
  float intensity = 1.f;  // irradiance on a surface facing the light
  bool operator==(const DirectionalLightDesc&) const = default;
};
template <>
struct ParamTable<DirectionalLightDesc> {
  static constexpr auto rows = std::tuple{
      row(&DirectionalLightDesc::direction, direction("direction", "Direction the light travels")),
      row(&DirectionalLightDesc::color, color("color", 1e6, "Colour")),
      row(&DirectionalLightDesc::intensity,
          number("intensity", 0, 1e9, "Irradiance on a surface facing the light").log_slider(0.01, 100))};
};

using LightVariant = std::variant<PointLightDesc, SpotLightDesc, DirectionalLightDesc>;

struct LightDesc {
  std::string name;
  LightVariant data = PointLightDesc{};
  bool operator==(const LightDesc&) const = default;
};

// ---------------------------------------------------------------- environment
struct ConstantEnvironmentDesc {
  static constexpr std::string_view type_name = "constant";
  Color color{0.f};
  bool operator==(const ConstantEnvironmentDesc&) const = default;
};
template <>
struct ParamTable<ConstantEnvironmentDesc> {
  static constexpr auto rows = std::tuple{
      row(&ConstantEnvironmentDesc::color, color("color", 1e6, "Radiance arriving from every direction"))};
};

struct GradientEnvironmentDesc {
  static constexpr std::string_view type_name = "gradient";
  Color zenith{0.5f, 0.7f, 1.f};
  Color horizon{1.f};
  Color nadir{0.2f};
  bool operator==(const GradientEnvironmentDesc&) const = default;
};
template <>
struct ParamTable<GradientEnvironmentDesc> {
  static constexpr auto rows =
      std::tuple{row(&GradientEnvironmentDesc::zenith, color("zenith", 1e6, "Radiance straight up (+y)")),
                 row(&GradientEnvironmentDesc::horizon, color("horizon", 1e6, "Radiance at the horizon")),
                 row(&GradientEnvironmentDesc::nadir, color("nadir", 1e6, "Radiance straight down (-y)"))};
};

using EnvironmentDesc = std::variant<ConstantEnvironmentDesc, GradientEnvironmentDesc>;

// ---------------------------------------------------------------- camera, render
// The camera's settings are the block a compiled Camera is built from (CameraParams);
// the rows below point into it.
struct CameraDesc : CameraParams {
  bool operator==(const CameraDesc&) const = default;
};
template <>
struct ParamTable<CameraDesc> {
  static constexpr auto rows =
      std::tuple{row(&CameraDesc::look_from, point("look_from", "Eye position")),
                 row(&CameraDesc::look_at, point("look_at", "Point at the image centre")),
                 row(&CameraDesc::up, direction("up", "Up direction")),
                 row(&CameraDesc::vfov, number("vfov", 0.01, 179, "Vertical field of view in degrees")
                                            .slider(5, 120)
                                            .labelled("Field of view")),
                 row(&CameraDesc::aperture,
                     number("aperture", 0, 1e6, "Lens diameter; 0 is a pinhole").log_slider(0.001, 10)),
                 row(&CameraDesc::focus_distance,
                     number("focus_distance", 0, 1e12, "Distance in focus; 0 focuses on look_at")
                         .log_slider(0.1, 1000))};
};

struct RenderSettings {
  int width = 640;
  int height = 480;
  int spp = 64;
  float time_limit = 0.f;  // seconds; 0 means no limit
  int max_depth = 16;
  int seed = 0;
  float clamp = 0.f;  // maximum sample luminance; 0 means no clamping
  PixelFilter filter = PixelFilter::box;
  float filter_radius = 0.5f;  // pixels; the box's half-width or the Gaussian's 3-sigma radius
  PainterlyFilter painterly = PainterlyFilter::none;
  float painterly_radius = 4.f;     // pixels at the reference height 1080
  float painterly_sharpness = 8.f;  // sector weighting exponent
  // Animation (document/animation.h): the frames a render of the shot covers, and the
  // frame this document shows and a still renders. Frames are numbered from frame_start.
  int frame_start = 1;
  int frame_end = 1;
  float fps = 24.f;
  float frame = 1.f;  // the current frame; fractional frames are in between
  // Motion blur: the shutter opens and closes this many frames from the frame's time
  // (e.g. -0.25 and 0.25: half a frame, centred). Equal: no motion blur.
  float shutter_open = 0.f;
  float shutter_close = 0.f;
  bool motion_blur() const { return shutter_close > shutter_open; }
  bool operator==(const RenderSettings&) const = default;
};
template <>
struct ParamTable<RenderSettings> {
  static constexpr auto rows = std::tuple{
      row(&RenderSettings::width,
          at(Stage::film, integer("width", 1, 16384, "Image width in pixels").log_slider(64, 8192))),
      row(&RenderSettings::height,
          at(Stage::film, integer("height", 1, 16384, "Image height in pixels").log_slider(64, 8192))),
      row(&RenderSettings::spp,
          at(Stage::limits, integer("spp", 1, 1 << 20, "Samples per pixel").log_slider(1, 16384))),
      row(&RenderSettings::time_limit,
          at(Stage::limits, number("time_limit", 0, 1e7, "Stop after this many seconds; 0 means no limit")
                                .log_slider(1, 3600))),
      row(&RenderSettings::max_depth,
          at(Stage::sampling, integer("max_depth", 1, 1024, "Maximum path length in bounces").slider(1, 64))),
      row(&RenderSettings::seed,
          at(Stage::sampling, integer("seed", 0, 2147483647, "Seed of every random decision"))),
      row(&RenderSettings::clamp,
          at(Stage::sampling, number("clamp", 0, 1e9, "Clamp sample luminance to this value; 0 is off")
                                  .log_slider(1, 1e4)
                                  .labelled("Clamp luminance"))),
      row(&RenderSettings::filter,
          at(Stage::sampling,
             choice("filter", kPixelFilterNames, "Pixel reconstruction filter").labelled("Pixel filter"))),
      row(&RenderSettings::filter_radius,
          at(Stage::sampling, number("filter_radius", 0.01, 8, "Filter radius in pixels").slider(0.25, 4))),
      row(&RenderSettings::painterly, at(Stage::resolve, choice("painterly", kPainterlyFilterNames,
                                                                "Painterly filter over the resolved image")
                                                             .labelled("Painterly filter"))),
      row(&RenderSettings::painterly_radius,
          at(Stage::resolve,
             number("painterly_radius", 0.5, 64, "Painterly filter radius, pixels at 1080 lines")
                 .log_slider(0.5, 64))),
      row(&RenderSettings::painterly_sharpness,
          at(Stage::resolve,
             number("painterly_sharpness", 0, 64, "Painterly filter sector sharpness").slider(0, 32))),
      row(&RenderSettings::frame_start,
          at(Stage::layout, integer("frame_start", -1000000, 1000000, "First frame of the shot"))),
      row(&RenderSettings::frame_end,
          at(Stage::layout, integer("frame_end", -1000000, 1000000, "Last frame of the shot (included)"))),
      row(&RenderSettings::fps, at(Stage::layout, number("fps", 0.001, 1000, "Frames per second of playback")
                                                      .slider(1, 120)
                                                      .labelled("Frame rate"))),
      // The frame itself redoes nothing: the compiler diffs the pictures at the two frames
      // (document/animation.h), so a step that moves nothing keeps the samples.
      row(&RenderSettings::frame,
          at(Stage::layout, number("frame", -1000000, 1000000,
                                   "The current frame: what the document shows and a still renders")
                                .labelled("Current frame"))),
      row(&RenderSettings::shutter_open,
          at(Stage::object, number("shutter_open", -1, 1,
                                   "Motion blur: the shutter opens this many frames from the frame's time")
                                .slider(-1, 0))),
      row(&RenderSettings::shutter_close,
          at(Stage::object, number("shutter_close", -1, 1,
                                   "Motion blur: the shutter closes this many frames from the frame's time; "
                                   "equal to shutter_open is no blur")
                                .slider(0, 1)))};
};

// ---------------------------------------------------------------- the document
struct SceneDesc {
  CameraDesc camera;
  RenderSettings render;
  SharedList<MaterialDesc> materials;
  SharedList<ObjectDesc> objects;
  SharedList<LightDesc> lights;
  EnvironmentDesc environment = ConstantEnvironmentDesc{};
  OutlineDesc outlines;
  SharedList<StrokeEmitterDesc> strokes;
  SharedList<TrackDesc> animation;  // keyframed parameters (document/animation.h)
  // Directory that relative asset paths resolve against (the scene file's folder).
  std::filesystem::path base_dir;
  bool operator==(const SceneDesc&) const = default;
};

}  // namespace inkray
