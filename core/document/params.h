// One parameter table per description struct (docs/architecture.md, "Parameter tables"):
// `ParamTable<Desc>::rows` names every editable field once, as a member pointer with
// its range, default, stage and doc. JSON reading and writing, checks, cache keys,
// stage diffs, animation paths and the editor's widgets are all walks over it.
#pragma once

#include <array>
#include <limits>
#include <span>
#include <string_view>
#include <tuple>
#include <type_traits>

namespace inkray {

enum class ParamKind {
  number,       // float
  integer,      // int
  toggle,       // bool
  point,        // Point3
  direction,    // Vec3, normalised when used
  vector,       // Vec3 (scale, edge vectors)
  color,        // Color, linear RGB
  color_input,  // ColorInput: constant colour, image texture or checker
  text,         // std::string (names, references)
  path,         // std::string, a file path relative to the scene file
  choice,       // an enum with a name table
  color_list,   // std::vector<Color>, e.g. a colour ramp
  group,        // a nested struct with its own parameter table (a JSON object)
  list,         // std::vector of a struct with its own parameter table (a JSON array of objects)
  nodes,        // a material graph's nodes (graph_desc.h): a JSON array of tagged objects with ids
};

// Every position, offset and edge vector stays within this distance of the origin.
// Embree's rays accept origins up to about 1.8e18 (beyond, Debian's build aborts);
// compile_scene bounds the transformed geometry far below that (kMaxWorldCoordinate).
inline constexpr double kMaxCoordinate = 1e9;

// What a change to a parameter makes stale, from the cheapest to the dearest.
// Each entry of a parameter list has one: its own (`at`), or that of the section
// of the document it belongs to (docs/architecture.md, "Stages").
enum class Stage : unsigned char {
  inherit,   // the section's: materials[i] material, objects[i] object, lights and environment light, ...
  layout,    // where the editor draws things (a graph's node positions): nothing is redone
  limits,    // render limits (samples, time): rendering goes on
  resolve,   // re-composite the accumulated film: line colours and opacity, painterly filter
  camera,    // camera rays: accumulation restarts, nothing is rebuilt
  sampling,  // what every sample computes (depth, seed, clamp, pixel filter, which lines): restart
  film,      // resolution: accumulation restarts at the new size
  material,  // one material's table entry, and the colours of strokes painted from it
  light,     // the light list and the environment
  object,    // one object's placement, visibility, material, overrides: the top-level BVH
  geometry,  // one object's shape or mesh file: its own BVH
  strokes,   // one stroke emitter: its strokes grow again
};
inline constexpr int kStageCount = int(Stage::strokes) + 1;
inline constexpr std::array<std::string_view, kStageCount> kStageNames = {
    "inherit", "layout",   "limits", "resolve", "camera",   "sampling",
    "film",    "material", "light",  "object",  "geometry", "strokes"};

// What a text parameter names: the editor offers the names that exist.
enum class Ref : unsigned char { none, material, object, light };
// What a path parameter names: the editor's browse dialog shows only these files.
enum class FileType : unsigned char { none, image, mesh, brush };

struct Param {
  std::string_view name;
  std::string_view doc;
  ParamKind kind = ParamKind::number;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  std::span<const std::string_view> choices = {};  // names for ParamKind::choice, indexed by enum value
  bool required = false;                           // a JSON reader reports it when absent
  Stage stage = Stage::inherit;                    // what a change to it makes stale

  // How the editor presents it; JSON, checks and stages ignore these.
  std::string_view label = {};  // empty: derived from the name (param_text.h)
  // What a slider spans, inside [min, max]; a typed value may use the whole hard range.
  // Infinite: the hard range.
  double soft_min = -std::numeric_limits<double>::infinity();
  double soft_max = std::numeric_limits<double>::infinity();
  bool logarithmic = false;  // scale-like quantities: each step multiplies
  Ref refers_to = Ref::none;
  FileType file_type = FileType::none;

  constexpr Param labelled(std::string_view text) const {
    Param p = *this;
    p.label = text;
    return p;
  }
  constexpr Param slider(double lo, double hi) const {
    Param p = *this;
    p.soft_min = lo;
    p.soft_max = hi;
    return p;
  }
  constexpr Param log_slider(double lo, double hi) const {
    Param p = slider(lo, hi);
    p.logarithmic = true;
    return p;
  }
  constexpr Param refers(Ref what) const {
    Param p = *this;
    p.refers_to = what;
    return p;
  }
  constexpr Param files(FileType type) const {
    Param p = *this;
    p.file_type = type;
    return p;
  }
};

// Helpers to keep parameter lists short and readable. The editor's presentation is
// added with Param's members: number("width", 0, 1000, "...").log_slider(0.1, 20).
constexpr Param number(std::string_view name, double min, double max, std::string_view doc) {
  return {name, doc, ParamKind::number, min, max};
}
constexpr Param integer(std::string_view name, double min, double max, std::string_view doc) {
  return {name, doc, ParamKind::integer, min, max};
}
constexpr Param toggle(std::string_view name, std::string_view doc) { return {name, doc, ParamKind::toggle}; }
constexpr Param point(std::string_view name, std::string_view doc) {
  return {name, doc, ParamKind::point, -kMaxCoordinate, kMaxCoordinate};
}
constexpr Param direction(std::string_view name, std::string_view doc) {
  return {name, doc, ParamKind::direction};
}
constexpr Param vector(std::string_view name, std::string_view doc) {
  return {name, doc, ParamKind::vector, -kMaxCoordinate, kMaxCoordinate};
}
constexpr Param color(std::string_view name, double max, std::string_view doc) {
  return {name, doc, ParamKind::color, 0.0, max};
}
constexpr Param color_input(std::string_view name, std::string_view doc) {
  return {name, doc, ParamKind::color_input, 0.0, 1.0};
}
constexpr Param text(std::string_view name, std::string_view doc) { return {name, doc, ParamKind::text}; }
constexpr Param path(std::string_view name, std::string_view doc) { return {name, doc, ParamKind::path}; }
constexpr Param choice(std::string_view name, std::span<const std::string_view> names, std::string_view doc) {
  return {name, doc, ParamKind::choice, 0, double(names.size() - 1), names};
}
constexpr Param color_list(std::string_view name, std::string_view doc) {
  return {name, doc, ParamKind::color_list, 0.0, 1e6};
}
constexpr Param group(std::string_view name, std::string_view doc) { return {name, doc, ParamKind::group}; }
constexpr Param list(std::string_view name, std::string_view doc) { return {name, doc, ParamKind::list}; }
constexpr Param required(Param p) {
  p.required = true;
  return p;
}
constexpr Param at(Stage stage, Param p) {
  p.stage = stage;
  return p;
}

// ---------------------------------------------------------------- parameter tables
// One row of a struct's parameter list: a pointer to the member and its Param. The
// member may belong to a base of the struct (ToonDesc's rows point into ToonParams,
// the block the compiled material shares).
template <class Owner, class T>
struct ParamRow {
  using owner_type = Owner;
  using value_type = T;
  T Owner::*member;
  Param param;
};
template <class Owner, class T>
constexpr ParamRow<Owner, T> row(T Owner::*member, Param param) {
  return {member, param};
}

// ParamTable<S>::rows is S's parameter list: a tuple of ParamRow, in the order JSON
// writes them and the editor shows them. Specialised after each description struct;
// there is no general definition, so a struct without a list is not a ParamGroup.
template <class S>
struct ParamTable;

// A struct with its own parameter list: walkers treat it as a nested group.
template <class T>
concept ParamGroup = requires {
  ParamTable<std::remove_const_t<T>>::rows;
};

// Calls f(param, field) for each row of desc's list in order; the field is const
// when desc is, so a walk that only reads needs neither a copy nor a cast.
template <class D, class F>
requires ParamGroup<D>
constexpr void for_each_param(D& desc, F&& f) {
  std::apply([&](const auto&... r) { (f(r.param, desc.*(r.member)), ...); },
             ParamTable<std::remove_const_t<D>>::rows);
}

// Calls f(param, field_of_a, field_of_b) for each row: two values of one struct side by side.
template <ParamGroup S, class F>
constexpr void for_each_param_pair(const S& a, const S& b, F&& f) {
  std::apply([&](const auto&... r) { (f(r.param, a.*(r.member), b.*(r.member)), ...); }, ParamTable<S>::rows);
}

// Calls f(param, type_tag) for each row without a value: f receives
// std::type_identity<FieldType>.
template <ParamGroup S, class F>
constexpr void for_each_param_decl(F&& f) {
  std::apply(
      [&](const auto&... r) {
        (f(r.param, std::type_identity<typename std::decay_t<decltype(r)>::value_type>{}), ...);
      },
      ParamTable<S>::rows);
}

// The visitor form: v(param, field) for each row, as JSON reading and writing, checks
// and the editor's widgets call it.
template <class D, class V>
requires ParamGroup<D>
constexpr void visit_params(D& desc, V& v) { for_each_param(desc, v); }

// Named sets of values a struct may start from (a line style's "ink" or "pencil"):
// the editor shows a Preset menu above such a struct's widgets. There is no general
// definition: a struct without presets has none.
template <class S>
struct ParamPresets;
template <class S>
concept HasPresets = requires(S& s, std::string_view name) {
  ParamPresets<S>::names.size();
  ParamPresets<S>::apply(name, s);
};

}  // namespace inkray
