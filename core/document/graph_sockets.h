// The typed sockets of material-graph nodes (docs/architecture.md, "Material
// graphs"). A node's inputs are the parameters of its list whose kind carries a
// value (numbers, colours, vectors), plus the link-only inputs it declares; its
// outputs are declared beside its type name.
#pragma once

#include "core/document/params.h"

#include <array>
#include <optional>
#include <string_view>

namespace inkray {

enum class SocketType : unsigned char { float_value, color, vector, closure };
inline constexpr std::array<std::string_view, 4> kSocketTypeNames = {"float", "colour", "vector", "closure"};

// What an unlinked link-only input stands for.
enum class Implicit : unsigned char {
  none,      // nothing: the input has no effect unless linked (closures, output overrides)
  uv,        // the hit's texture coordinates (u, v, 0)
  position,  // the hit's object-space position
};

struct SocketDecl {
  std::string_view name;
  SocketType type;
  std::string_view doc;
  Implicit implicit = Implicit::none;
};

inline constexpr std::array<SocketDecl, 1> kClosureOutputs = {
    {{"closure", SocketType::closure, "The surface"}}};

// The socket a parameter of this kind is; nullopt for settings (toggles, choices,
// integers, lists, paths), which are edited on the node but never linked.
constexpr std::optional<SocketType> socket_type_of(ParamKind kind) {
  switch (kind) {
    case ParamKind::number:
      return SocketType::float_value;
    case ParamKind::color:
    case ParamKind::color_input:
      return SocketType::color;
    case ParamKind::point:
    case ParamKind::direction:
    case ParamKind::vector:
      return SocketType::vector;
    default:
      return std::nullopt;
  }
}

// Whether a value of type `from` may feed an input of type `to`: equal types, or
// the implicit conversions between float, colour and vector that Blender makes
// (float -> grey or splat, colour -> luminance, vector -> mean). Closures link
// only to closures.
constexpr bool socket_converts(SocketType from, SocketType to) {
  if (from == to) return true;
  return from != SocketType::closure && to != SocketType::closure;
}

}  // namespace inkray
