// The node types of material graphs (docs/scene-format.md, "a material built from nodes").
// Each is a plain struct with a JSON type name, its declared outputs, any
// link-only inputs, and one parameter list: the parameters whose kind carries a
// value are its input sockets (graph_sockets.h), the rest are settings.
// The closure nodes are the plain materials of material_desc.h.
#pragma once

#include "core/document/graph_sockets.h"
#include "core/document/material_desc.h"
#include "core/materials/shader_ops.h"

#include <array>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace inkray {

// The parameter table of a node whose inputs are all links.
struct NoParams {
  static constexpr std::tuple<> rows{};
};

// ---------------------------------------------------------------- output
struct OutputNode {
  static constexpr std::string_view type_name = "output";
  static constexpr std::string_view doc =
      "The material: its surface, and optional overrides of its outlines and stroke colours.";
  static constexpr std::array<SocketDecl, 0> outputs = {};
  static constexpr std::array<SocketDecl, 4> link_inputs = {{
      {"surface", SocketType::closure, "The material's surface"},
      {"line_color", SocketType::color,
       "Colour of outlines drawn on this surface (unlinked: the outline colour)"},
      {"line_width", SocketType::float_value, "Multiplies the outline width on this surface (unlinked: 1)"},
      {"stroke_color", SocketType::color,
       "Colour stroke emitters paint this surface with (unlinked: its albedo)"},
  }};
  bool operator==(const OutputNode&) const = default;
};
template <>
struct ParamTable<OutputNode> : NoParams {};

// ---------------------------------------------------------------- constants
struct ValueNode {
  static constexpr std::string_view type_name = "value";
  static constexpr std::string_view doc = "A number.";
  static constexpr std::array<SocketDecl, 1> outputs = {{{"value", SocketType::float_value, "The number"}}};
  float value = 0.5f;
  bool operator==(const ValueNode&) const = default;
};
template <>
struct ParamTable<ValueNode> {
  static constexpr auto rows = std::tuple{row(&ValueNode::value, number("value", -1e9, 1e9, "The number"))};
};

struct RgbNode {
  static constexpr std::string_view type_name = "rgb";
  static constexpr std::string_view doc = "A colour.";
  static constexpr std::array<SocketDecl, 1> outputs = {{{"color", SocketType::color, "The colour"}}};
  Color color{0.8f};
  bool operator==(const RgbNode&) const = default;
};
template <>
struct ParamTable<RgbNode> {
  static constexpr auto rows = std::tuple{row(&RgbNode::color, color("color", 1e6, "The colour"))};
};

// ---------------------------------------------------------------- textures
struct ImageTextureNode {
  static constexpr std::string_view type_name = "image_texture";
  static constexpr std::string_view doc =
      "An image file looked up at texture coordinates (repeating, bilinear).";
  static constexpr std::array<SocketDecl, 2> outputs = {
      {{"color", SocketType::color, "Texel colour"},
       {"alpha", SocketType::float_value, "Texel alpha (1 without)"}}};
  static constexpr std::array<SocketDecl, 1> link_inputs = {
      {{"vector", SocketType::vector, "Texture coordinates (unlinked: the hit's uv)", Implicit::uv}}};
  std::string path;
  bool srgb = true;
  bool operator==(const ImageTextureNode&) const = default;
};
template <>
struct ParamTable<ImageTextureNode> {
  static constexpr auto rows =
      std::tuple{row(&ImageTextureNode::path, kImageFile), row(&ImageTextureNode::srgb, kImageSrgb)};
};

struct CheckerNode {
  static constexpr std::string_view type_name = "checker_texture";
  static constexpr std::string_view doc = "A checkerboard in texture space.";
  static constexpr std::array<SocketDecl, 2> outputs = {
      {{"color", SocketType::color, "Square colour"}, {"fac", SocketType::float_value, "1 on odd squares"}}};
  static constexpr std::array<SocketDecl, 1> link_inputs = {
      {{"vector", SocketType::vector, "Texture coordinates (unlinked: the hit's uv)", Implicit::uv}}};
  Color color1{0.9f};
  Color color2{0.1f};
  float scale = 10.f;
  bool operator==(const CheckerNode&) const = default;
};
template <>
struct ParamTable<CheckerNode> {
  static constexpr auto rows =
      std::tuple{row(&CheckerNode::color1, color("color1", 1e6, "Colour of even squares")),
                 row(&CheckerNode::color2, color("color2", 1e6, "Colour of odd squares")),
                 row(&CheckerNode::scale, number("scale", 0, 1e6, "Squares per unit").log_slider(0.1, 1000))};
};

enum class NoiseType { value, gradient };
inline constexpr std::array<std::string_view, 2> kNoiseTypeNames = {"value", "gradient"};

struct NoiseNode {
  static constexpr std::string_view type_name = "noise_texture";
  static constexpr std::string_view doc = "Fractal value or gradient (Perlin) noise in 3D.";
  static constexpr std::array<SocketDecl, 2> outputs = {
      {{"fac", SocketType::float_value, "Noise in [0, 1]"},
       {"color", SocketType::color, "Three decorrelated noises"}}};
  static constexpr std::array<SocketDecl, 1> link_inputs = {
      {{"vector", SocketType::vector, "Where to evaluate (unlinked: the object-space position)",
        Implicit::position}}};
  NoiseType noise = NoiseType::gradient;
  int octaves = 4;
  float scale = 5.f;
  float roughness = 0.5f;
  float distortion = 0.f;
  bool operator==(const NoiseNode&) const = default;
};
template <>
struct ParamTable<NoiseNode> {
  static constexpr auto rows = std::tuple{
      row(&NoiseNode::noise, choice("noise", kNoiseTypeNames, "Value noise or gradient (Perlin) noise")),
      row(&NoiseNode::octaves, integer("octaves", 1, 16, "Octaves of fractal detail")),
      row(&NoiseNode::scale, number("scale", 0, 1e6, "Features per unit").log_slider(0.1, 100)),
      row(&NoiseNode::roughness, number("roughness", 0, 1, "Amplitude of each octave relative to the last")),
      row(&NoiseNode::distortion,
          number("distortion", 0, 1e3, "Warps the lookup by another noise").slider(0, 10))};
};

struct VoronoiNode {
  static constexpr std::string_view type_name = "voronoi_texture";
  static constexpr std::string_view doc = "Cells around jittered points (Worley F1).";
  static constexpr std::array<SocketDecl, 3> outputs = {
      {{"distance", SocketType::float_value, "To the nearest cell point"},
       {"color", SocketType::color, "Random colour per cell"},
       {"position", SocketType::vector, "The nearest cell point"}}};
  static constexpr std::array<SocketDecl, 1> link_inputs = {
      {{"vector", SocketType::vector, "Where to evaluate (unlinked: the object-space position)",
        Implicit::position}}};
  float scale = 5.f;
  float randomness = 1.f;
  bool operator==(const VoronoiNode&) const = default;
};
template <>
struct ParamTable<VoronoiNode> {
  static constexpr auto rows =
      std::tuple{row(&VoronoiNode::scale, number("scale", 0, 1e6, "Cells per unit").log_slider(0.1, 100)),
                 row(&VoronoiNode::randomness,
                     number("randomness", 0, 1, "How far cell points stray from a regular grid"))};
};

// ---------------------------------------------------------------- converters
enum class RampMode { constant, linear, ease };
inline constexpr std::array<std::string_view, 3> kRampModeNames = {"constant", "linear", "ease"};

struct RampStopDesc {
  float position = 0.f;
  Color color{0.f};
  bool operator==(const RampStopDesc&) const = default;
};
template <>
struct ParamTable<RampStopDesc> {
  static constexpr auto rows =
      std::tuple{row(&RampStopDesc::position, number("position", 0, 1, "Where the stop sits on the ramp")),
                 row(&RampStopDesc::color, color("color", 1e6, "Colour at the stop"))};
};

struct ColorRampNode {
  static constexpr std::string_view type_name = "color_ramp";
  static constexpr std::string_view doc = "Maps a number to a colour through stops.";
  static constexpr std::array<SocketDecl, 1> outputs = {
      {{"color", SocketType::color, "The ramp's colour at fac"}}};
  float fac = 0.5f;
  RampMode interpolation = RampMode::linear;
  std::vector<RampStopDesc> stops = {{0.f, Color(0.f)}, {1.f, Color(1.f)}};
  bool operator==(const ColorRampNode&) const = default;
};
template <>
struct ParamTable<ColorRampNode> {
  static constexpr auto rows = std::tuple{
      row(&ColorRampNode::fac,
          number("fac", -1e9, 1e9, "Position on the ramp, clamped to [0, 1]").slider(0, 1)),
      row(&ColorRampNode::interpolation,
          choice("interpolation", kRampModeNames, "How colours between stops are blended")),
      row(&ColorRampNode::stops, list("stops", "Stops: {\"position\": p, \"color\": c}, in any order"))};
};

// The compiled program runs the same operations: a node's choice is its instruction's mode.
using MathOp = ShaderMath;
inline constexpr std::array<std::string_view, 11> kMathOpNames = {
    "add",     "subtract", "multiply",   "divide",       "power",    "minimum",
    "maximum", "clamp",    "smoothstep", "greater_than", "less_than"};

// a op b; clamp keeps a within [b, c]; smoothstep rises from b to c over a;
// greater_than and less_than are steps (1 or 0) comparing a with b.
struct MathNode {
  static constexpr std::string_view type_name = "math";
  static constexpr std::string_view doc = "Arithmetic on numbers.";
  static constexpr std::array<SocketDecl, 1> outputs = {{{"value", SocketType::float_value, "The result"}}};
  MathOp operation = MathOp::add;
  bool clamp_result = false;
  float a = 0.5f, b = 0.5f, c = 1.f;
  bool operator==(const MathNode&) const = default;
};
template <>
struct ParamTable<MathNode> {
  static constexpr auto rows = std::tuple{
      row(&MathNode::operation, choice("operation", kMathOpNames, "What to compute")),
      row(&MathNode::clamp_result, toggle("clamp_result", "Clamp the result to [0, 1]")),
      row(&MathNode::a, number("a", -1e9, 1e9, "First operand")),
      row(&MathNode::b,
          number("b", -1e9, 1e9, "Second operand (the lower bound or edge for clamp and smoothstep)")),
      row(&MathNode::c, number("c", -1e9, 1e9, "Upper bound or edge for clamp and smoothstep"))};
};

// Linear remap of value from [from_min, from_max] to [to_min, to_max].
struct MapRangeNode {
  static constexpr std::string_view type_name = "map_range";
  static constexpr std::string_view doc = "Remaps a number from one range to another.";
  static constexpr std::array<SocketDecl, 1> outputs = {
      {{"value", SocketType::float_value, "The remapped value"}}};
  bool clamp_result = true;
  float value = 0.5f, from_min = 0.f, from_max = 1.f, to_min = 0.f, to_max = 1.f;
  bool operator==(const MapRangeNode&) const = default;
};
template <>
struct ParamTable<MapRangeNode> {
  static constexpr auto rows = std::tuple{
      row(&MapRangeNode::clamp_result, toggle("clamp_result", "Keep the result within [to_min, to_max]")),
      row(&MapRangeNode::value, number("value", -1e9, 1e9, "The value to remap")),
      row(&MapRangeNode::from_min, number("from_min", -1e9, 1e9, "Maps to to_min")),
      row(&MapRangeNode::from_max, number("from_max", -1e9, 1e9, "Maps to to_max")),
      row(&MapRangeNode::to_min, number("to_min", -1e9, 1e9, "Lower end of the output range")),
      row(&MapRangeNode::to_max, number("to_max", -1e9, 1e9, "Upper end of the output range"))};
};

enum class BlendOp { mix, multiply, screen, overlay, add };
inline constexpr std::array<std::string_view, 5> kBlendOpNames = {"mix", "multiply", "screen", "overlay",
                                                                  "add"};

struct MixColorNode {
  static constexpr std::string_view type_name = "mix_color";
  static constexpr std::string_view doc = "Blends two colours.";
  static constexpr std::array<SocketDecl, 1> outputs = {{{"color", SocketType::color, "The blend"}}};
  BlendOp blend = BlendOp::mix;
  bool clamp_result = false;
  float fac = 0.5f;
  Color a{0.5f};
  Color b{0.5f};
  bool operator==(const MixColorNode&) const = default;
};
template <>
struct ParamTable<MixColorNode> {
  static constexpr auto rows =
      std::tuple{row(&MixColorNode::blend, choice("blend", kBlendOpNames, "How b is laid over a")),
                 row(&MixColorNode::clamp_result, toggle("clamp_result", "Clamp the result to [0, 1]")),
                 row(&MixColorNode::fac, number("fac", 0, 1, "Strength of b")),
                 row(&MixColorNode::a, color("a", 1e6, "Bottom colour")),
                 row(&MixColorNode::b, color("b", 1e6, "Top colour"))};
};

using VectorOp = ShaderVector;
inline constexpr std::array<std::string_view, 8> kVectorOpNames = {"add",   "subtract",  "multiply", "dot",
                                                                   "cross", "normalize", "length",   "scale"};

struct VectorMathNode {
  static constexpr std::string_view type_name = "vector_math";
  static constexpr std::string_view doc = "Arithmetic on vectors.";
  static constexpr std::array<SocketDecl, 2> outputs = {
      {{"vector", SocketType::vector, "Vector results"},
       {"value", SocketType::float_value, "dot and length"}}};
  VectorOp operation = VectorOp::add;
  Vec3 a{0.f};
  Vec3 b{0.f};
  float scale = 1.f;
  bool operator==(const VectorMathNode&) const = default;
};
template <>
struct ParamTable<VectorMathNode> {
  static constexpr auto rows =
      std::tuple{row(&VectorMathNode::operation, choice("operation", kVectorOpNames, "What to compute")),
                 row(&VectorMathNode::a, vector("a", "First operand")),
                 row(&VectorMathNode::b, vector("b", "Second operand")),
                 row(&VectorMathNode::scale, number("scale", -1e9, 1e9, "Factor for scale"))};
};

struct HsvNode {
  static constexpr std::string_view type_name = "hue_saturation";
  static constexpr std::string_view doc = "Shifts hue and scales saturation and value.";
  static constexpr std::array<SocketDecl, 1> outputs = {
      {{"color", SocketType::color, "The adjusted colour"}}};
  float hue = 0.5f, saturation = 1.f, value = 1.f, fac = 1.f;
  Color color{0.8f};
  bool operator==(const HsvNode&) const = default;
};
template <>
struct ParamTable<HsvNode> {
  static constexpr auto rows = std::tuple{
      row(&HsvNode::hue, number("hue", 0, 1, "Hue shift; 0.5 keeps the hue")),
      row(&HsvNode::saturation, number("saturation", 0, 1e3, "Multiplies saturation").slider(0, 2)),
      row(&HsvNode::value, number("value", 0, 1e3, "Multiplies value").slider(0, 2)),
      row(&HsvNode::fac, number("fac", 0, 1, "Blend of the adjusted colour over the input")),
      row(&HsvNode::color, color("color", 1e6, "The colour to adjust"))};
};

enum class ColorConversion { rgb_to_hsv, hsv_to_rgb };
inline constexpr std::array<std::string_view, 2> kColorConversionNames = {"rgb_to_hsv", "hsv_to_rgb"};

struct ConvertColorNode {
  static constexpr std::string_view type_name = "convert_color";
  static constexpr std::string_view doc = "Converts between RGB and HSV.";
  static constexpr std::array<SocketDecl, 1> outputs = {
      {{"color", SocketType::color, "The converted triple"}}};
  ColorConversion conversion = ColorConversion::rgb_to_hsv;
  Color color{0.8f};
  bool operator==(const ConvertColorNode&) const = default;
};
template <>
struct ParamTable<ConvertColorNode> {
  static constexpr auto rows =
      std::tuple{row(&ConvertColorNode::conversion,
                     choice("conversion", kColorConversionNames, "Direction of the conversion")),
                 row(&ConvertColorNode::color, color("color", 1e6, "RGB, or (h, s, v) in [0, 1]"))};
};

struct SeparateNode {
  static constexpr std::string_view type_name = "separate";
  static constexpr std::string_view doc = "Splits a vector or colour into its components.";
  static constexpr std::array<SocketDecl, 3> outputs = {
      {{"x", SocketType::float_value, "First component (red)"},
       {"y", SocketType::float_value, "Second component (green)"},
       {"z", SocketType::float_value, "Third component (blue)"}}};
  Vec3 vector{0.f};
  bool operator==(const SeparateNode&) const = default;
};
template <>
struct ParamTable<SeparateNode> {
  static constexpr auto rows = std::tuple{row(&SeparateNode::vector, vector("vector", "A vector or colour"))};
};

struct CombineNode {
  static constexpr std::string_view type_name = "combine";
  static constexpr std::string_view doc = "Builds a vector and a colour from three numbers.";
  static constexpr std::array<SocketDecl, 2> outputs = {
      {{"vector", SocketType::vector, "(x, y, z)"}, {"color", SocketType::color, "(x, y, z) as RGB"}}};
  float x = 0.f, y = 0.f, z = 0.f;
  bool operator==(const CombineNode&) const = default;
};
template <>
struct ParamTable<CombineNode> {
  static constexpr auto rows =
      std::tuple{row(&CombineNode::x, number("x", -1e9, 1e9, "First component (red)")),
                 row(&CombineNode::y, number("y", -1e9, 1e9, "Second component (green)")),
                 row(&CombineNode::z, number("z", -1e9, 1e9, "Third component (blue)"))};
};

// ---------------------------------------------------------------- the hit
struct GeometryNode {
  static constexpr std::string_view type_name = "geometry";
  static constexpr std::string_view doc =
      "The hit: position, normals, uv, view, facing ratio, ids, depth, a random number per object.";
  static constexpr std::array<SocketDecl, 11> outputs = {{
      {"position", SocketType::vector, "World-space position"},
      {"normal", SocketType::vector, "Shading normal, towards the viewer"},
      {"true_normal", SocketType::vector, "Geometric normal, towards the viewer"},
      {"uv", SocketType::vector, "Texture coordinates (u, v, 0)"},
      {"incoming", SocketType::vector, "Towards the viewer"},
      {"facing", SocketType::float_value, "Facing ratio: dot(normal, incoming), 1 facing the viewer"},
      {"object_id", SocketType::float_value, "Index of the object in the scene"},
      {"material_id", SocketType::float_value, "Index of the material in the scene"},
      {"depth", SocketType::float_value, "Distance along the path from the camera"},
      {"random", SocketType::float_value, "A random number per object in [0, 1)"},
      {"object_position", SocketType::vector,
       "Position in the object's own space: fixed to the object as it moves"},
  }};
  bool operator==(const GeometryNode&) const = default;
};
template <>
struct ParamTable<GeometryNode> : NoParams {};

// Toon work: the light a cel shader quantises, traced only when a graph uses it.
struct LightInputNode {
  static constexpr std::string_view type_name = "light_input";
  static constexpr std::string_view doc = "The strongest light at the hit, for cel shading by hand.";
  static constexpr std::array<SocketDecl, 3> outputs = {{
      {"n_dot_l", SocketType::float_value,
       "Cosine between the normal and the strongest light (clamped at 0)"},
      {"shadow", SocketType::float_value, "1 where the strongest light is seen, 0 in its shadow"},
      {"color", SocketType::color, "The strongest light's colour (brightest channel 1)"},
  }};
  bool operator==(const LightInputNode&) const = default;
};
template <>
struct ParamTable<LightInputNode> : NoParams {};

struct FresnelNode {
  static constexpr std::string_view type_name = "fresnel";
  static constexpr std::string_view doc = "Dielectric reflectance for the view angle.";
  static constexpr std::array<SocketDecl, 1> outputs = {
      {{"fac", SocketType::float_value, "Dielectric reflectance"}}};
  float ior = 1.45f;
  bool operator==(const FresnelNode&) const = default;
};
template <>
struct ParamTable<FresnelNode> {
  static constexpr auto rows =
      std::tuple{row(&FresnelNode::ior, number("ior", 1, 10, "Index of refraction").slider(1, 3))};
};

struct LayerWeightNode {
  static constexpr std::string_view type_name = "layer_weight";
  static constexpr std::string_view doc = "Rim factors from the view angle.";
  static constexpr std::array<SocketDecl, 2> outputs = {
      {{"fresnel", SocketType::float_value, "Fresnel-like rim"},
       {"facing", SocketType::float_value, "1 - facing ratio, shaped"}}};
  float blend = 0.5f;
  bool operator==(const LayerWeightNode&) const = default;
};
template <>
struct ParamTable<LayerWeightNode> {
  static constexpr auto rows =
      std::tuple{row(&LayerWeightNode::blend, number("blend", 0, 1, "Where the rim rises"))};
};

// ---------------------------------------------------------------- closures
// Picks a or b per sample with probability fac of b: the blend costs no more than either.
struct MixClosureNode {
  static constexpr std::string_view type_name = "mix_closure";
  static constexpr std::string_view doc = "Picks surface a or b per sample, b with probability fac.";
  static constexpr auto& outputs = kClosureOutputs;
  static constexpr std::array<SocketDecl, 2> link_inputs = {
      {{"a", SocketType::closure, "Where fac is 0"}, {"b", SocketType::closure, "Where fac is 1"}}};
  float fac = 0.5f;
  bool operator==(const MixClosureNode&) const = default;
};
template <>
struct ParamTable<MixClosureNode> {
  static constexpr auto rows = std::tuple{row(&MixClosureNode::fac, number("fac", 0, 1, "Weight of b"))};
};

// The sum of two surfaces (a rim emission over a toon base): one is picked per sample and weighted by 2.
struct AddClosureNode {
  static constexpr std::string_view type_name = "add_closure";
  static constexpr std::string_view doc = "The sum of two surfaces.";
  static constexpr auto& outputs = kClosureOutputs;
  static constexpr std::array<SocketDecl, 2> link_inputs = {
      {{"a", SocketType::closure, "One surface"}, {"b", SocketType::closure, "The other"}}};
  bool operator==(const AddClosureNode&) const = default;
};
template <>
struct ParamTable<AddClosureNode> : NoParams {};

using NodeVariant =
    std::variant<OutputNode, ValueNode, RgbNode, ImageTextureNode, CheckerNode, NoiseNode, VoronoiNode,
                 ColorRampNode, MathNode, MapRangeNode, MixColorNode, VectorMathNode, HsvNode,
                 ConvertColorNode, SeparateNode, CombineNode, GeometryNode, LightInputNode, FresnelNode,
                 LayerWeightNode, DiffuseDesc, ConductorDesc, DielectricDesc, EmissiveDesc, UnlitDesc,
                 TransparentDesc, ToonDesc, MixClosureNode, AddClosureNode>;

}  // namespace inkray
