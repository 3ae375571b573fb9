// Descriptions of colour inputs and of every kind of material that is also a
// closure node in a material graph (graph_nodes.h): diffuse, conductor, dielectric,
// emissive, unlit, transparent, toon; and the plain mix of two named materials.
#pragma once

#include "core/document/graph_sockets.h"
#include "core/document/params.h"
#include "core/math/types.h"

#include <array>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace inkray {

// ---------------------------------------------------------------- colour inputs
struct ImageTextureDesc {
  static constexpr std::string_view type_name = "image";
  std::string path;     // relative to the scene file; PNG/JPEG/HDR through stb
  Color scale{1.f};     // multiplies the texel
  bool srgb = true;     // 8-bit images are sRGB-encoded unless told otherwise
  bool operator==(const ImageTextureDesc&) const = default;
};
template <class V> void visit_params(ImageTextureDesc& d, V& v) {
  v(required(path("path", "Image file, relative to the scene file")).files(FileType::image).labelled("Image file"), d.path);
  v(color("scale", 1e6, "Multiplies every texel").labelled("Tint"), d.scale);
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
  v(number("scale", 1e-6, 1e6, "Squares per unit of texture coordinate").log_slider(0.1, 1000), d.scale);
}

// A colour parameter: a constant (JSON [r,g,b] or a number), or a texture object.
using ColorInput = std::variant<Color, ImageTextureDesc, CheckerTextureDesc>;

// ---------------------------------------------------------------- materials
struct DiffuseDesc {
  static constexpr std::string_view type_name = "diffuse";
  static constexpr std::string_view doc = "A Lambertian surface.";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
  ColorInput albedo = Color(0.8f);
  bool operator==(const DiffuseDesc&) const = default;
};
template <class V> void visit_params(DiffuseDesc& d, V& v) {
  v(color_input("albedo", "Lambertian reflectance"), d.albedo);
}

struct ConductorDesc {
  static constexpr std::string_view type_name = "conductor";
  static constexpr std::string_view doc = "A metal: GGX microfacets, mirror at roughness 0.";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
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
  static constexpr std::string_view doc = "Glass: smooth or rough (GGX) refraction.";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
  float ior = 1.5f;
  float roughness = 0.f;
  Color tint{1.f};  // multiplies transmitted light
  bool operator==(const DielectricDesc&) const = default;
};
template <class V> void visit_params(DielectricDesc& d, V& v) {
  v(number("ior", 1.0001, 4, "Index of refraction of the inside").slider(1.0001, 2.5), d.ior);
  v(number("roughness", 0, 1, "GGX roughness; 0 is smooth glass"), d.roughness);
  v(color("tint", 1, "Multiplies transmitted light"), d.tint);
}

struct EmissiveDesc {
  static constexpr std::string_view type_name = "emissive";
  static constexpr std::string_view doc = "A surface that emits light.";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
  ColorInput color = Color(1.f);
  float strength = 1.f;  // radiance = color * strength
  bool two_sided = false;
  bool operator==(const EmissiveDesc&) const = default;
};
template <class V> void visit_params(EmissiveDesc& d, V& v) {
  v(color_input("color", "Emitted colour"), d.color);
  v(number("strength", 0, 1e7, "Radiance scale: radiance = color * strength").log_slider(0.01, 1e4), d.strength);
  v(toggle("two_sided", "Emit from both sides (default: the front, along the normal)"), d.two_sided);
}

struct UnlitDesc {
  static constexpr std::string_view type_name = "unlit";
  static constexpr std::string_view doc = "Its colour whatever the light (flat shading).";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
  ColorInput color = Color(1.f);
  bool operator==(const UnlitDesc&) const = default;
};
template <class V> void visit_params(UnlitDesc& d, V& v) {
  v(color_input("color", "Colour returned to any ray that hits; ignores light"), d.color);
}

struct TransparentDesc {
  static constexpr std::string_view type_name = "transparent";
  static constexpr std::string_view doc = "Lets light straight through, tinted.";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
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
  static constexpr std::string_view doc = "Cel shading: light quantised into bands or a ramp, a specular band and a rim.";
  static constexpr auto& outputs = kClosureOutputs;  // a closure node in graphs
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
  float environment = 0.25f;            // the sky counts as a light of this fraction of its strength
  bool environment_shadows = false;     // the sky is shadowed (one more shadow ray per sample)
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
  v(path("ramp_image", "2D ramp image: u = light level, v = ramp_axis (X-toon)").files(FileType::image), d.ramp_image);
  v(choice("ramp_axis", kToonRampAxisNames, "Second axis of the 2D ramp"), d.ramp_axis);
  v(number("ramp_near", 0, 1e9, "Depth mapped to v = 0 when ramp_axis is depth").log_slider(0.1, 1000), d.ramp_near);
  v(number("ramp_far", 0, 1e9, "Depth mapped to v = 1 when ramp_axis is depth").log_slider(0.1, 1000), d.ramp_far);
  v(toggle("specular", "Add a hard specular band"), d.specular);
  v(color("specular_color", 1e3, "Colour of the specular band"), d.specular_color);
  v(number("specular_size", 0, 1, "Size of the specular band"), d.specular_size);
  v(number("shininess", 1, 1e4, "Blinn-Phong exponent the band is cut from").log_slider(1, 1000), d.shininess);
  v(toggle("rim", "Add a rim light"), d.rim);
  v(color("rim_color", 1e3, "Colour of the rim light"), d.rim_color);
  v(number("rim_width", 0, 1, "Width of the rim in facing ratio"), d.rim_width);
  v(number("rim_threshold", 0, 1, "Rim appears where 1 - facing ratio exceeds this"), d.rim_threshold);
  v(number("environment", 0, 16,
           "How much the environment adds to the light level: it counts as a light of this fraction of its "
           "strength (0: none, 1: as bright as it is)")
        .slider(0, 1)
        .labelled("Environment light"),
    d.environment);
  v(toggle("environment_shadows", "Shadow the environment light: one more shadow ray per sample"),
    d.environment_shadows);
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
  v(required(text("a", "Material used where the factor is 0")).refers(Ref::material).labelled("Material A"), d.a);
  v(required(text("b", "Material used where the factor is 1")).refers(Ref::material).labelled("Material B"), d.b);
  v(color_input("factor", "Blend weight (luminance of a colour or texture)").labelled("Blend"), d.factor);
}

}  // namespace inkray
