// SceneDesc: the editable scene document (docs/architecture.md, "From JSON to
// pixels"). Plain structs with defaults, references by name, serialised to JSON
// by document/json_io. Every struct lists its parameters once in visit_params
// (document/params.h).
// Closed sets are std::variants whose alternatives carry their JSON "type" tag.
#pragma once

#include "core/math/types.h"
#include "core/document/animation_desc.h"
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
  bool exclude = false;          // produces no lines
  bool stop_lines = false;       // mirrors/glass: lines are not followed through this surface
  float width_scale = 1.f;
  bool override_color = false;
  Color color{0.f};
  bool operator==(const LineOverrideDesc&) const = default;
};
template <class V> void visit_params(LineOverrideDesc& d, V& v) {
  v(toggle("exclude", "This surface produces no outlines").labelled("No outlines"), d.exclude);
  v(toggle("stop_lines", "Outlines are not seen through this mirror or glass").labelled("Hide lines behind"), d.stop_lines);
  v(number("width_scale", 0, 100, "Multiplies the outline width on this surface").log_slider(0.1, 10), d.width_scale);
  v(toggle("override_color", "Draw this surface's lines in `color`"), d.override_color);
  v(color("color", 1e3, "Line colour when override_color is set").labelled("Line colour"), d.color);
}

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
template <class V> void visit_params(SphereDesc& d, V& v) {
  v(point("center", "Centre in object space"), d.center);
  v(number("radius", 1e-12, 1e12, "Radius in object space").log_slider(0.01, 100), d.radius);
}

struct QuadDesc {
  static constexpr std::string_view type_name = "quad";
  Point3 corner{0.f};
  Vec3 edge_u{1.f, 0.f, 0.f};
  Vec3 edge_v{0.f, 0.f, 1.f};  // normal = normalize(cross(edge_u, edge_v))
  bool operator==(const QuadDesc&) const = default;
};
template <class V> void visit_params(QuadDesc& d, V& v) {
  v(point("corner", "One corner"), d.corner);
  v(vector("edge_u", "First edge from the corner"), d.edge_u);
  v(vector("edge_v", "Second edge; the front faces along cross(edge_u, edge_v)"), d.edge_v);
}

struct BoxDesc {
  static constexpr std::string_view type_name = "box";
  Point3 min{0.f};
  Point3 max{1.f};
  bool operator==(const BoxDesc&) const = default;
};
template <class V> void visit_params(BoxDesc& d, V& v) {
  v(point("min", "Minimum corner"), d.min);
  v(point("max", "Maximum corner"), d.max);
}

struct MeshDesc {
  static constexpr std::string_view type_name = "mesh";
  std::string path;  // Wavefront OBJ, relative to the scene file
  float smooth_angle = 30.f;  // degrees; normals for a file without them (geometry/mesh_normals.h)
  bool operator==(const MeshDesc&) const = default;
};
template <class V> void visit_params(MeshDesc& d, V& v) {
  v(required(path("path", "Wavefront OBJ file, relative to the scene file")).files(FileType::mesh).labelled("OBJ file"), d.path);
  v(number("smooth_angle", 0, 180,
           "For a file without normals: shading is smooth across edges whose faces meet at most this many "
           "degrees apart and sharp at the others. 0 keeps the facets, 180 smooths everything; normals in "
           "the file are used as given")
        .slider(0, 180)
        .labelled("Auto smooth angle"),
    d.smooth_angle);
}

using ShapeVariant = std::variant<SphereDesc, QuadDesc, BoxDesc, MeshDesc>;

// Applied as scale, then each rotation in order, then translate.
struct RotationDesc {
  Vec3 axis{0.f, 1.f, 0.f};
  float degrees = 0.f;  // right-handed about axis
  bool operator==(const RotationDesc&) const = default;
};
template <class V> void visit_params(RotationDesc& d, V& v) {
  v(direction("axis", "Rotation axis"), d.axis);
  v(number("degrees", -1e6, 1e6, "Right-handed angle about the axis").slider(-180, 180).labelled("Angle"), d.degrees);
}

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
template <class V> void visit_params(ObjectDesc& d, V& v) {
  v(text("name", "Unique object name"), d.name);
  v(required(text("material", "Name of the object's material")).refers(Ref::material), d.material);
  v(toggle("visible", "Hidden objects are not rendered"), d.visible);
  v(group("lines", "Outline overrides for this object"), d.lines);
}

// ---------------------------------------------------------------- lights
struct PointLightDesc {
  static constexpr std::string_view type_name = "point";
  Point3 position{0.f};
  Color color{1.f};
  float intensity = 1.f;  // radiant intensity scale (W/sr)
  bool operator==(const PointLightDesc&) const = default;
};
template <class V> void visit_params(PointLightDesc& d, V& v) {
  v(point("position", "Position"), d.position);
  v(color("color", 1e6, "Colour"), d.color);
  v(number("intensity", 0, 1e9, "Radiant intensity: color * intensity per steradian").log_slider(0.1, 1e4), d.intensity);
}

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
template <class V> void visit_params(SpotLightDesc& d, V& v) {
  v(point("position", "Position"), d.position);
  v(point("target", "Point the spot aims at"), d.target);
  v(color("color", 1e6, "Colour"), d.color);
  v(number("intensity", 0, 1e9, "Radiant intensity on the axis").log_slider(0.1, 1e4), d.intensity);
  v(number("cone_angle", 0.01, 90, "Half-angle in degrees where the light ends").slider(1, 90), d.cone_angle);
  v(number("falloff_angle", 0, 90, "Half-angle in degrees where the smooth falloff starts"), d.falloff_angle);
}

struct DirectionalLightDesc {
  static constexpr std::string_view type_name = "directional";
  Vec3 direction{0.f, -1.f, 0.f};  // direction the light travels
  Color color{1.f};
  float intensity = 1.f;  // irradiance on a surface facing the light
  bool operator==(const DirectionalLightDesc&) const = default;
};
template <class V> void visit_params(DirectionalLightDesc& d, V& v) {
  v(direction("direction", "Direction the light travels"), d.direction);
  v(color("color", 1e6, "Colour"), d.color);
  v(number("intensity", 0, 1e9, "Irradiance on a surface facing the light").log_slider(0.01, 100), d.intensity);
}

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
template <class V> void visit_params(ConstantEnvironmentDesc& d, V& v) {
  v(color("color", 1e6, "Radiance arriving from every direction"), d.color);
}

struct GradientEnvironmentDesc {
  static constexpr std::string_view type_name = "gradient";
  Color zenith{0.5f, 0.7f, 1.f};
  Color horizon{1.f};
  Color nadir{0.2f};
  bool operator==(const GradientEnvironmentDesc&) const = default;
};
template <class V> void visit_params(GradientEnvironmentDesc& d, V& v) {
  v(color("zenith", 1e6, "Radiance straight up (+y)"), d.zenith);
  v(color("horizon", 1e6, "Radiance at the horizon"), d.horizon);
  v(color("nadir", 1e6, "Radiance straight down (-y)"), d.nadir);
}

using EnvironmentDesc = std::variant<ConstantEnvironmentDesc, GradientEnvironmentDesc>;

// ---------------------------------------------------------------- camera, render
struct CameraDesc {
  Point3 look_from{0.f, 0.f, 5.f};
  Point3 look_at{0.f};
  Vec3 up{0.f, 1.f, 0.f};
  float vfov = 40.f;           // vertical field of view, degrees
  float aperture = 0.f;        // lens diameter; 0 is a pinhole
  float focus_distance = 0.f;  // 0 focuses on look_at
  bool operator==(const CameraDesc&) const = default;
};
template <class V> void visit_params(CameraDesc& d, V& v) {
  v(point("look_from", "Eye position"), d.look_from);
  v(point("look_at", "Point at the image centre"), d.look_at);
  v(direction("up", "Up direction"), d.up);
  v(number("vfov", 0.01, 179, "Vertical field of view in degrees").slider(5, 120).labelled("Field of view"), d.vfov);
  v(number("aperture", 0, 1e6, "Lens diameter; 0 is a pinhole").log_slider(0.001, 10), d.aperture);
  v(number("focus_distance", 0, 1e12, "Distance in focus; 0 focuses on look_at").log_slider(0.1, 1000), d.focus_distance);
}

enum class PixelFilter { box, gaussian };
inline constexpr std::array<std::string_view, 2> kPixelFilterNames = {"box", "gaussian"};

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
template <class V> void visit_params(RenderSettings& d, V& v) {
  v(at(Stage::film, integer("width", 1, 16384, "Image width in pixels").log_slider(64, 8192)), d.width);
  v(at(Stage::film, integer("height", 1, 16384, "Image height in pixels").log_slider(64, 8192)), d.height);
  v(at(Stage::limits, integer("spp", 1, 1 << 20, "Samples per pixel").log_slider(1, 16384)), d.spp);
  v(at(Stage::limits, number("time_limit", 0, 1e7, "Stop after this many seconds; 0 means no limit").log_slider(1, 3600)), d.time_limit);
  v(at(Stage::sampling, integer("max_depth", 1, 1024, "Maximum path length in bounces").slider(1, 64)), d.max_depth);
  v(at(Stage::sampling, integer("seed", 0, 2147483647, "Seed of every random decision")), d.seed);
  v(at(Stage::sampling, number("clamp", 0, 1e9, "Clamp sample luminance to this value; 0 is off").log_slider(1, 1e4).labelled("Clamp luminance")), d.clamp);
  v(at(Stage::sampling, choice("filter", kPixelFilterNames, "Pixel reconstruction filter").labelled("Pixel filter")), d.filter);
  v(at(Stage::sampling, number("filter_radius", 0.01, 8, "Filter radius in pixels").slider(0.25, 4)), d.filter_radius);
  v(at(Stage::resolve, choice("painterly", kPainterlyFilterNames, "Painterly filter over the resolved image").labelled("Painterly filter")), d.painterly);
  v(at(Stage::resolve, number("painterly_radius", 0.5, 64, "Painterly filter radius, pixels at 1080 lines").log_slider(0.5, 64)), d.painterly_radius);
  v(at(Stage::resolve, number("painterly_sharpness", 0, 64, "Painterly filter sector sharpness").slider(0, 32)), d.painterly_sharpness);
  v(at(Stage::layout, integer("frame_start", -1000000, 1000000, "First frame of the shot")), d.frame_start);
  v(at(Stage::layout, integer("frame_end", -1000000, 1000000, "Last frame of the shot (included)")), d.frame_end);
  v(at(Stage::layout, number("fps", 0.001, 1000, "Frames per second of playback").slider(1, 120).labelled("Frame rate")), d.fps);
  // The frame itself redoes nothing: the compiler diffs the pictures at the two frames
  // (document/animation.h), so a step that moves nothing keeps the samples.
  v(at(Stage::layout, number("frame", -1000000, 1000000, "The current frame: what the document shows and a still renders").labelled("Current frame")), d.frame);
  v(at(Stage::object, number("shutter_open", -1, 1, "Motion blur: the shutter opens this many frames from the frame's time").slider(-1, 0)), d.shutter_open);
  v(at(Stage::object, number("shutter_close", -1, 1, "Motion blur: the shutter closes this many frames from the frame's time; equal to shutter_open is no blur").slider(0, 1)), d.shutter_close);
}

// ---------------------------------------------------------------- the document
struct SceneDesc {
  CameraDesc camera;
  RenderSettings render;
  std::vector<MaterialDesc> materials;
  std::vector<ObjectDesc> objects;
  std::vector<LightDesc> lights;
  EnvironmentDesc environment = ConstantEnvironmentDesc{};
  OutlineDesc outlines;
  std::vector<StrokeEmitterDesc> strokes;
  std::vector<TrackDesc> animation;  // keyframed parameters (document/animation.h)
  // Directory that relative asset paths resolve against (the scene file's folder).
  std::filesystem::path base_dir;
  bool operator==(const SceneDesc&) const = default;
};

}  // namespace inkray
