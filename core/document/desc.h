// SceneDesc: the editable scene document (docs/architecture.md, "From JSON to
// pixels"). Plain structs with defaults, references by name, serialised to JSON
// by document/json_io. Every struct lists its parameters once in visit_params
// (document/params.h).
// Closed sets are std::variants whose alternatives carry their JSON "type" tag.
#pragma once

#include "core/math/types.h"
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

// ---------------------------------------------------------------- colour inputs
struct ImageTextureDesc {
  static constexpr std::string_view type_name = "image";
  std::string path;     // relative to the scene file; PNG/JPEG/HDR through stb
  Color scale{1.f};     // multiplies the texel
  bool srgb = true;     // 8-bit images are sRGB-encoded unless told otherwise
  bool operator==(const ImageTextureDesc&) const = default;
};
template <class V> void visit_params(ImageTextureDesc& d, V& v) {
  v(required(path("path", "Image file, relative to the scene file")), d.path);
  v(color("scale", 1e6, "Multiplies every texel"), d.scale);
  v(toggle("srgb", "Decode 8-bit texels from sRGB to linear"), d.srgb);
}

struct CheckerTextureDesc {
  static constexpr std::string_view type_name = "checker";
  Color even{0.9f};
  Color odd{0.1f};
  float scale = 10.f;  // squares per unit of uv
  bool operator==(const CheckerTextureDesc&) const = default;
};
template <class V> void visit_params(CheckerTextureDesc& d, V& v) {
  v(color("even", 1e6, "Colour of even squares"), d.even);
  v(color("odd", 1e6, "Colour of odd squares"), d.odd);
  v(number("scale", 1e-6, 1e6, "Squares per unit of texture coordinate"), d.scale);
}

// A colour parameter: a constant (JSON [r,g,b] or a number), or a texture object.
using ColorInput = std::variant<Color, ImageTextureDesc, CheckerTextureDesc>;

// ---------------------------------------------------------------- materials
struct DiffuseDesc {
  static constexpr std::string_view type_name = "diffuse";
  ColorInput albedo = Color(0.8f);
  bool operator==(const DiffuseDesc&) const = default;
};
template <class V> void visit_params(DiffuseDesc& d, V& v) {
  v(color_input("albedo", "Lambertian reflectance"), d.albedo);
}

struct ConductorDesc {
  static constexpr std::string_view type_name = "conductor";
  ColorInput color = Color(0.95f);  // reflectance at normal incidence (F0)
  float roughness = 0.f;            // GGX, perceptual: alpha = roughness^2; 0 is a mirror
  bool operator==(const ConductorDesc&) const = default;
};
template <class V> void visit_params(ConductorDesc& d, V& v) {
  v(color_input("color", "Reflectance at normal incidence (Schlick F0)"), d.color);
  v(number("roughness", 0, 1, "GGX roughness; 0 is a perfect mirror"), d.roughness);
}

struct DielectricDesc {
  static constexpr std::string_view type_name = "dielectric";
  float ior = 1.5f;
  float roughness = 0.f;
  Color tint{1.f};  // multiplies transmitted light
  bool operator==(const DielectricDesc&) const = default;
};
template <class V> void visit_params(DielectricDesc& d, V& v) {
  v(number("ior", 1.0001, 4, "Index of refraction of the inside"), d.ior);
  v(number("roughness", 0, 1, "GGX roughness; 0 is smooth glass"), d.roughness);
  v(color("tint", 1, "Multiplies transmitted light"), d.tint);
}

struct EmissiveDesc {
  static constexpr std::string_view type_name = "emissive";
  ColorInput color = Color(1.f);
  float strength = 1.f;  // radiance = color * strength
  bool two_sided = false;
  bool operator==(const EmissiveDesc&) const = default;
};
template <class V> void visit_params(EmissiveDesc& d, V& v) {
  v(color_input("color", "Emitted colour"), d.color);
  v(number("strength", 0, 1e7, "Radiance scale: radiance = color * strength"), d.strength);
  v(toggle("two_sided", "Emit from both sides (default: the front, along the normal)"), d.two_sided);
}

struct UnlitDesc {
  static constexpr std::string_view type_name = "unlit";
  ColorInput color = Color(1.f);
  bool operator==(const UnlitDesc&) const = default;
};
template <class V> void visit_params(UnlitDesc& d, V& v) {
  v(color_input("color", "Colour returned to any ray that hits; ignores light"), d.color);
}

struct TransparentDesc {
  static constexpr std::string_view type_name = "transparent";
  Color tint{1.f};
  bool operator==(const TransparentDesc&) const = default;
};
template <class V> void visit_params(TransparentDesc& d, V& v) {
  v(color("tint", 1, "Multiplies light passing straight through"), d.tint);
}

// Cel shading: light from the scene's lights (with shadows) quantised into
// bands or mapped through a ramp, plus a specular band and a rim light.
enum class ToonRampAxis { none, depth, facing };
inline constexpr std::array<std::string_view, 3> kToonRampAxisNames = {"none", "depth", "facing"};

struct ToonDesc {
  static constexpr std::string_view type_name = "toon";
  ColorInput color = Color(0.8f);      // lit colour
  Color shadow_color{0.25f};           // multiplies `color` in the darkest band
  int bands = 2;                        // 2 = a single cel threshold
  float threshold = 0.5f;               // cel threshold on normalised light (first band edge)
  float softness = 0.02f;               // width of the transition between bands
  std::vector<Color> ramp;              // when non-empty: light level -> colour, evenly spaced stops
  std::string ramp_image;               // optional 2D ramp (X-toon): u = light, v = ramp_axis
  ToonRampAxis ramp_axis = ToonRampAxis::none;
  float ramp_near = 1.f, ramp_far = 20.f;  // depth range mapped to v for ramp_axis depth
  bool specular = true;
  Color specular_color{1.f};
  float specular_size = 0.1f;           // Blinn-Phong threshold: larger is a bigger highlight
  float shininess = 40.f;
  bool rim = false;
  Color rim_color{1.f};
  float rim_width = 0.3f;               // facing-ratio band width
  float rim_threshold = 0.5f;
  bool receive_indirect = false;        // add indirect light (bands stay on direct light)
  bool bounce_indirect = true;          // other surfaces see it as diffuse
  bool operator==(const ToonDesc&) const = default;
};
template <class V> void visit_params(ToonDesc& d, V& v) {
  v(color_input("color", "Lit colour"), d.color);
  v(color("shadow_color", 1, "Multiplies the colour in the darkest band"), d.shadow_color);
  v(integer("bands", 2, 16, "Number of light bands; 2 is a single cel threshold"), d.bands);
  v(number("threshold", 0, 1, "Cel threshold: light level where the first band starts"), d.threshold);
  v(number("softness", 0, 0.5, "Width of the transition between bands"), d.softness);
  v(color_list("ramp", "Colour ramp over the light level (evenly spaced); replaces bands when set"), d.ramp);
  v(path("ramp_image", "2D ramp image: u = light level, v = ramp_axis (X-toon)"), d.ramp_image);
  v(choice("ramp_axis", kToonRampAxisNames, "Second axis of the 2D ramp"), d.ramp_axis);
  v(number("ramp_near", 0, 1e9, "Depth mapped to v = 0 when ramp_axis is depth"), d.ramp_near);
  v(number("ramp_far", 0, 1e9, "Depth mapped to v = 1 when ramp_axis is depth"), d.ramp_far);
  v(toggle("specular", "Add a hard specular band"), d.specular);
  v(color("specular_color", 1e3, "Colour of the specular band"), d.specular_color);
  v(number("specular_size", 0, 1, "Size of the specular band"), d.specular_size);
  v(number("shininess", 1, 1e4, "Blinn-Phong exponent the band is cut from"), d.shininess);
  v(toggle("rim", "Add a rim light"), d.rim);
  v(color("rim_color", 1e3, "Colour of the rim light"), d.rim_color);
  v(number("rim_width", 0, 1, "Width of the rim in facing ratio"), d.rim_width);
  v(number("rim_threshold", 0, 1, "Rim appears where 1 - facing ratio exceeds this"), d.rim_threshold);
  v(toggle("receive_indirect", "Add indirect light from the path tracer"), d.receive_indirect);
  v(toggle("bounce_indirect", "Other surfaces receive light bounced off this one"), d.bounce_indirect);
}

// Blend of two other materials by a factor (a number or a texture's luminance).
struct MixDesc {
  static constexpr std::string_view type_name = "mix";
  std::string a;  // material names
  std::string b;
  ColorInput factor = Color(0.5f);  // 0 = all a, 1 = all b
  bool operator==(const MixDesc&) const = default;
};
template <class V> void visit_params(MixDesc& d, V& v) {
  v(required(text("a", "Material used where the factor is 0")), d.a);
  v(required(text("b", "Material used where the factor is 1")), d.b);
  v(color_input("factor", "Blend weight (luminance of a colour or texture)"), d.factor);
}

using MaterialVariant = std::variant<DiffuseDesc, ConductorDesc, DielectricDesc, EmissiveDesc, UnlitDesc,
                                     TransparentDesc, ToonDesc, MixDesc>;

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
  v(toggle("exclude", "This surface produces no outlines"), d.exclude);
  v(toggle("stop_lines", "Outlines are not seen through this mirror or glass"), d.stop_lines);
  v(number("width_scale", 0, 100, "Multiplies the outline width on this surface"), d.width_scale);
  v(toggle("override_color", "Draw this surface's lines in `color`"), d.override_color);
  v(color("color", 1e3, "Line colour when override_color is set"), d.color);
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
  v(number("radius", 1e-12, 1e12, "Radius in object space"), d.radius);
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
  bool operator==(const MeshDesc&) const = default;
};
template <class V> void visit_params(MeshDesc& d, V& v) {
  v(required(path("path", "Wavefront OBJ file, relative to the scene file")), d.path);
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
  v(number("degrees", -1e6, 1e6, "Right-handed angle about the axis"), d.degrees);
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
  v(required(text("material", "Name of the object's material")), d.material);
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
  v(number("intensity", 0, 1e9, "Radiant intensity: color * intensity per steradian"), d.intensity);
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
  v(number("intensity", 0, 1e9, "Radiant intensity on the axis"), d.intensity);
  v(number("cone_angle", 0.01, 90, "Half-angle in degrees where the light ends"), d.cone_angle);
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
  v(number("intensity", 0, 1e9, "Irradiance on a surface facing the light"), d.intensity);
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
  v(number("vfov", 0.01, 179, "Vertical field of view in degrees"), d.vfov);
  v(number("aperture", 0, 1e6, "Lens diameter; 0 is a pinhole"), d.aperture);
  v(number("focus_distance", 0, 1e12, "Distance in focus; 0 focuses on look_at"), d.focus_distance);
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
  bool operator==(const RenderSettings&) const = default;
};
template <class V> void visit_params(RenderSettings& d, V& v) {
  v(at(Stage::film, integer("width", 1, 16384, "Image width in pixels")), d.width);
  v(at(Stage::film, integer("height", 1, 16384, "Image height in pixels")), d.height);
  v(at(Stage::limits, integer("spp", 1, 1 << 20, "Samples per pixel")), d.spp);
  v(at(Stage::limits, number("time_limit", 0, 1e7, "Stop after this many seconds; 0 means no limit")), d.time_limit);
  v(at(Stage::sampling, integer("max_depth", 1, 1024, "Maximum path length in bounces")), d.max_depth);
  v(at(Stage::sampling, integer("seed", 0, 2147483647, "Seed of every random decision")), d.seed);
  v(at(Stage::sampling, number("clamp", 0, 1e9, "Clamp sample luminance to this value; 0 is off")), d.clamp);
  v(at(Stage::sampling, choice("filter", kPixelFilterNames, "Pixel reconstruction filter")), d.filter);
  v(at(Stage::sampling, number("filter_radius", 0.01, 8, "Filter radius in pixels")), d.filter_radius);
  v(at(Stage::resolve, choice("painterly", kPainterlyFilterNames, "Painterly filter over the resolved image")), d.painterly);
  v(at(Stage::resolve, number("painterly_radius", 0.5, 64, "Painterly filter radius, pixels at 1080 lines")), d.painterly_radius);
  v(at(Stage::resolve, number("painterly_sharpness", 0, 64, "Painterly filter sector sharpness")), d.painterly_sharpness);
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
  // Directory that relative asset paths resolve against (the scene file's folder).
  std::filesystem::path base_dir;
  bool operator==(const SceneDesc&) const = default;
};

}  // namespace inkray
