#include "core/document/graph_reference.h"

#include "core/document/graph_desc.h"
#include "core/document/json_write.h"

#include <cmath>
#include <sstream>
#include <type_traits>

namespace inkray {
namespace {

std::string number_text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

std::string value_text(const Param&, float v) { return number_text(double(float_to_json_number(v))); }
std::string value_text(const Param&, int v) { return std::to_string(v); }
std::string value_text(const Param&, bool v) { return v ? "true" : "false"; }
std::string value_text(const Param&, const Vec3& v) {
  return "[" + number_text(float_to_json_number(v.x)) + ", " + number_text(float_to_json_number(v.y)) + ", " +
         number_text(float_to_json_number(v.z)) + "]";
}
std::string value_text(const Param&, const std::string& s) { return s.empty() ? "unset" : "\"" + s + "\""; }
std::string value_text(const Param& p, const ColorInput& c) {
  if (const Color* k = std::get_if<Color>(&c)) return value_text(p, *k);
  return "a texture";
}
template <class E>
requires std::is_enum_v<E> std::string value_text(const Param& p, E e) {
  return size_t(e) < p.choices.size() ? "\"" + std::string(p.choices[size_t(e)]) + "\"" : "?";
}
template <class T>
std::string value_text(const Param&, const std::vector<T>& list) {
  return std::to_string(list.size()) + (list.size() == 1 ? " entry" : " entries");
}

std::string range_text(const Param& p) {
  if (p.kind == ParamKind::choice) {
    std::string names;
    for (std::string_view c : p.choices) names += (names.empty() ? "" : ", ") + std::string(c);
    return names;
  }
  const bool low = std::isfinite(p.min), high = std::isfinite(p.max);
  if (low && high) return "[" + number_text(p.min) + ", " + number_text(p.max) + "]";
  return "";
}

struct Rows {
  std::string* out;
  template <class F>
  void operator()(const Param& p, F& field) {
    const auto socket = socket_type_of(p.kind);
    const std::string kind = socket ? std::string(kSocketTypeNames[size_t(*socket)]) + " input" : "setting";
    *out += "| `" + std::string(p.name) + "` | " + kind + " | " + value_text(p, field) + " | " +
            range_text(p) + " | " + std::string(p.doc) + " |\n";
  }
};

std::string_view category_of(std::string_view type) {
  for (std::string_view t : {"value", "rgb", "geometry", "light_input", "fresnel", "layer_weight"})
    if (t == type) return "input";
  for (std::string_view t : {"image_texture", "checker_texture", "noise_texture", "voronoi_texture"})
    if (t == type) return "texture";
  for (std::string_view t : {"output"})
    if (t == type) return "output";
  for (std::string_view t : {"color_ramp", "math", "map_range", "mix_color", "vector_math", "hue_saturation",
                             "convert_color", "separate", "combine"})
    if (t == type) return "converter";
  return "closure";
}

}  // namespace

std::string node_reference_markdown() {
  std::string out;
  for (std::string_view category : {"output", "input", "texture", "converter", "closure"}) {
    out += "#### " + std::string(1, char(std::toupper(category[0]))) + std::string(category.substr(1)) +
           " nodes\n\n";
    for_each_alternative<NodeVariant>([&]<class T>(std::type_identity<T>) {
      if (category_of(T::type_name) != category) return;
      out += "##### `\"" + std::string(T::type_name) + "\"`\n\n" + std::string(T::doc) + "\n\n";
      std::string rows;
      T defaults{};
      Rows visitor{&rows};
      visit_params(defaults, visitor);
      if constexpr (requires { T::link_inputs; }) {
        for (const SocketDecl& s : T::link_inputs)
          rows += "| `" + std::string(s.name) + "` | " + std::string(kSocketTypeNames[size_t(s.type)]) +
                  " input, link only | " +
                  (s.implicit == Implicit::uv         ? "the hit's uv"
                   : s.implicit == Implicit::position ? "the hit's position"
                                                      : "unlinked: no effect") +
                  " | | " + std::string(s.doc) + " |\n";
      }
      if (!rows.empty())
        out += "| input | kind | default | range | meaning |\n|---|---|---|---|---|\n" + rows + "\n";
      if (!T::outputs.empty()) {
        out += "Outputs: ";
        bool first = true;
        for (const SocketDecl& s : T::outputs) {
          out += std::string(first ? "" : "; ") + "`" + std::string(s.name) + "` (" +
                 std::string(kSocketTypeNames[size_t(s.type)]) + "): " + std::string(s.doc);
          first = false;
        }
        out += ".\n\n";
      }
    });
  }
  return out;
}

}  // namespace inkray
