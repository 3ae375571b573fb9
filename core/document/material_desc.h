// Descriptions of colour inputs and of every kind of material that is also a
// closure node in a material graph (graph_nodes.h): diffuse, conductor, dielectric,
// emissive, unlit, transparent, toon; and the plain mix of two named materials.
#pragma once

#include "core/document/graph_sockets.h"
#include "core/document/params.h"
#include "core/materials/closure_params.h"
#include "core/materials/toon_params.h"
#include "core/math/types.h"

#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace inkray {

// ---------------------------------------------------------------- colour inputs
// An image texture's file and decoding, alike for a colour input and a graph's image node.
inline constexpr Param kImageFile = required(path("path", "Image file, relative to the scene file"))
                                        .files(FileType::image)
                                        .labelled("Image file");
inline constexpr Param kImageSrgb = toggle("srgb", "Decode 8-bit texels from sRGB to linear");

struct ImageTextureDesc {
  static constexpr std::string_view type_name = "image";
  std::string path;  // relative to the scene file; PNG/JPEG/HDR through stb
  Color scale{1.f};  // multiplies the texel
  bool srgb = true;  // 8-bit images are sRGB-encoded unless told otherwise
  bool operator==(const ImageTextureDesc&) const = default;
};
template <>
struct ParamTable<ImageTextureDesc> {
  static constexpr auto rows = std::tuple{
      row(&ImageTextureDesc::path, kImageFile),
      row(&ImageTextureDesc::scale, color("scale", 1e6, "Multiplies every texel").labelled("Tint")),
      row(&ImageTextureDesc::srgb, kImageSrgb)};
};

struct CheckerTextureDesc {
  static constexpr std::string_view type_name = "checker";
  Color even{0.9f};
  Color odd{0.1f};
  float scale = 10.f;  // squares per unit of uv
  bool operator==(const CheckerTextureDesc&) const = default;
};
template <>
struct ParamTable<CheckerTextureDesc> {
  static constexpr auto rows = std::tuple{
      row(&CheckerTextureDesc::even, color("even", 1e6, "Colour of even squares")),
      row(&CheckerTextureDesc::odd, color("odd", 1e6, "Colour of odd squares")),
      row(&CheckerTextureDesc::scale,
          number("scale", 1e-6, 1e6, "Squares per unit of texture coordinate").log_slider(0.1, 1000))};
};

// A colour parameter: a constant (JSON [r,g,b] or a number), or a texture object.
using ColorInput = std::variant<Color, ImageTextureDesc, CheckerTextureDesc>;

// ---------------------------------------------------------------- materials
// A closure's settings are a block the compiled material shares (closure_params.h,
// toon_params.h; docs/architecture.md, "Parameter tables"): the rows that point into
// it are the whole of their declaration here. Colour inputs are the description's own.
struct DiffuseDesc {
  static constexpr std::string_view type_name = "diffuse";
  static constexpr std::string_view doc = "A Lambertian surface.";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
  ColorInput albedo = Color(0.8f);
  bool operator==(const DiffuseDesc&) const = default;
};
template <>
struct ParamTable<DiffuseDesc> {
  static constexpr auto rows =
      std::tuple{row(&DiffuseDesc::albedo, color_input("albedo", "Lambertian reflectance"))};
};

struct ConductorDesc : ConductorParams {
  static constexpr std::string_view type_name = "conductor";
  static constexpr std::string_view doc = "A metal: GGX microfacets, mirror at roughness 0.";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
  ColorInput color = Color(0.95f);                   // reflectance at normal incidence (F0)
  ConductorDesc() = default;
  // The colour first, as a scene lists it, then the settings in the block's order:
  // ConductorDesc{Color(0.9f), 0.3f} (as an aggregate the block, a base, would come first).
  template <class... Settings>
  explicit ConductorDesc(ColorInput c, Settings... settings)
      : ConductorParams{settings...}, color(std::move(c)) {}
  bool operator==(const ConductorDesc&) const = default;
};
template <>
struct ParamTable<ConductorDesc> {
  static constexpr auto rows = std::tuple{
      row(&ConductorDesc::color, color_input("color", "Reflectance at normal incidence (Schlick F0)")),
      row(&ConductorDesc::roughness, number("roughness", 0, 1, "GGX roughness; 0 is a perfect mirror"))};
};

struct DielectricDesc : DielectricParams {
  static constexpr std::string_view type_name = "dielectric";
  static constexpr std::string_view doc = "Glass: smooth or rough (GGX) refraction.";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
  bool operator==(const DielectricDesc&) const = default;
};
template <>
struct ParamTable<DielectricDesc> {
  static constexpr auto rows = std::tuple{
      row(&DielectricDesc::ior,
          number("ior", 1.0001, 4, "Index of refraction of the inside").slider(1.0001, 2.5)),
      row(&DielectricDesc::roughness, number("roughness", 0, 1, "GGX roughness; 0 is smooth glass")),
      row(&DielectricDesc::tint, color("tint", 1, "Multiplies transmitted light"))};
};

struct EmissiveDesc : EmissiveParams {
  static constexpr std::string_view type_name = "emissive";
  static constexpr std::string_view doc = "A surface that emits light.";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
  ColorInput color = Color(1.f);
  EmissiveDesc() = default;
  // The colour first, as a scene lists it, then the settings in the block's order:
  // EmissiveDesc{Color(1.f), 5.f, true} (as an aggregate the block, a base, would come first).
  template <class... Settings>
  explicit EmissiveDesc(ColorInput c, Settings... settings)
      : EmissiveParams{settings...}, color(std::move(c)) {}
  bool operator==(const EmissiveDesc&) const = default;
};
template <>
struct ParamTable<EmissiveDesc> {
  static constexpr auto rows = std::tuple{
      row(&EmissiveDesc::color, color_input("color", "Emitted colour")),
      row(&EmissiveDesc::strength,
          number("strength", 0, 1e7, "Radiance scale: radiance = color * strength").log_slider(0.01, 1e4)),
      row(&EmissiveDesc::two_sided,
          toggle("two_sided", "Emit from both sides (default: the front, along the normal)"))};
};

struct UnlitDesc {
  static constexpr std::string_view type_name = "unlit";
  static constexpr std::string_view doc = "Its colour whatever the light (flat shading).";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
  ColorInput color = Color(1.f);
  bool operator==(const UnlitDesc&) const = default;
};
template <>
struct ParamTable<UnlitDesc> {
  static constexpr auto rows = std::tuple{
      row(&UnlitDesc::color, color_input("color", "Colour returned to any ray that hits; ignores light"))};
};

struct TransparentDesc : TransparentParams {
  static constexpr std::string_view type_name = "transparent";
  static constexpr std::string_view doc = "Lets light straight through, tinted.";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
  bool operator==(const TransparentDesc&) const = default;
};
template <>
struct ParamTable<TransparentDesc> {
  static constexpr auto rows =
      std::tuple{row(&TransparentDesc::tint, color("tint", 1, "Multiplies light passing straight through"))};
};

// Cel shading: light from the scene's lights (with shadows) quantised into
// bands or mapped through a ramp, plus a specular band and a rim light. The
// settings are the block the compiled material shares (ToonParams); the rows of
// the table below that point into it are the whole of their declaration here.
inline constexpr std::array<std::string_view, 3> kToonRampAxisNames = {"none", "depth", "facing"};

struct ToonDesc : ToonParams {
  static constexpr std::string_view type_name = "toon";
  static constexpr std::string_view doc =
      "Cel shading: light quantised into bands or a ramp, a specular band and a rim.";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
  ColorInput color = Color(0.8f);                    // lit colour
  std::vector<Color> ramp;  // when non-empty: light level -> colour, evenly spaced stops
  std::string ramp_image;   // optional 2D ramp (X-toon): u = light, v = ramp_axis
  bool operator==(const ToonDesc&) const = default;
};
template <>
struct ParamTable<ToonDesc> {
  static constexpr auto rows = std::tuple{
      row(&ToonDesc::color, color_input("color", "Lit colour")),
      row(&ToonDesc::shadow_color, color("shadow_color", 1, "Multiplies the colour in the darkest band")),
      row(&ToonDesc::bands, integer("bands", 2, 16, "Number of light bands; 2 is a single cel threshold")),
      row(&ToonDesc::threshold,
          number("threshold", 0, 1, "Cel threshold: light level where the first band starts")),
      row(&ToonDesc::softness, number("softness", 0, 0.5, "Width of the transition between bands")),
      row(&ToonDesc::ramp,
          color_list("ramp", "Colour ramp over the light level (evenly spaced); replaces bands when set")),
      row(&ToonDesc::ramp_image, path("ramp_image", "2D ramp image: u = light level, v = ramp_axis (X-toon)")
                                     .files(FileType::image)),
      row(&ToonDesc::ramp_axis, choice("ramp_axis", kToonRampAxisNames, "Second axis of the 2D ramp")),
      row(&ToonDesc::ramp_near,
          number("ramp_near", 0, 1e9, "Depth mapped to v = 0 when ramp_axis is depth").log_slider(0.1, 1000)),
      row(&ToonDesc::ramp_far,
          number("ramp_far", 0, 1e9, "Depth mapped to v = 1 when ramp_axis is depth").log_slider(0.1, 1000)),
      row(&ToonDesc::specular, toggle("specular", "Add a hard specular band")),
      row(&ToonDesc::specular_color, color("specular_color", 1e3, "Colour of the specular band")),
      row(&ToonDesc::specular_size, number("specular_size", 0, 1, "Size of the specular band")),
      row(&ToonDesc::shininess,
          number("shininess", 1, 1e4, "Blinn-Phong exponent the band is cut from").log_slider(1, 1000)),
      row(&ToonDesc::rim, toggle("rim", "Add a rim light")),
      row(&ToonDesc::rim_color, color("rim_color", 1e3, "Colour of the rim light")),
      row(&ToonDesc::rim_width, number("rim_width", 0, 1, "Width of the rim in facing ratio")),
      row(&ToonDesc::rim_threshold,
          number("rim_threshold", 0, 1, "Rim appears where 1 - facing ratio exceeds this")),
      row(&ToonDesc::environment, number("environment", 0, 16,
                                         "How much the environment adds to the light level: it counts as a "
                                         "light of this fraction of its "
                                         "strength (0: none, 1: as bright as it is)")
                                      .slider(0, 1)
                                      .labelled("Environment light")),
      row(&ToonDesc::environment_shadows,
          toggle("environment_shadows", "Shadow the environment light: one more shadow ray per sample")),
      row(&ToonDesc::receive_indirect, toggle("receive_indirect", "Add indirect light from the path tracer")),
      row(&ToonDesc::bounce_indirect,
          toggle("bounce_indirect", "Other surfaces receive light bounced off this one"))};
};

// Blend of two other materials by a factor (a number or a texture's luminance).
struct MixDesc {
  static constexpr std::string_view type_name = "mix";
  std::string a;  // material names
  std::string b;
  ColorInput factor = Color(0.5f);  // 0 = all a, 1 = all b
  bool operator==(const MixDesc&) const = default;
};
template <>
struct ParamTable<MixDesc> {
  static constexpr auto rows = std::tuple{
      row(&MixDesc::a, required(text("a", "Material used where the factor is 0"))
                           .refers(Ref::material)
                           .labelled("Material A")),
      row(&MixDesc::b, required(text("b", "Material used where the factor is 1"))
                           .refers(Ref::material)
                           .labelled("Material B")),
      row(&MixDesc::factor,
          color_input("factor", "Blend weight (luminance of a colour or texture)").labelled("Blend"))};
};

}  // namespace inkray
