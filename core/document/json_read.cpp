// The generic scene reader: one visitor over the parameter tables reads and checks every
// field of every struct, so its messages come from the same Param list as the editor's
// widgets. Checks that span the document (names, references, files) are in scene_checks.
#include "core/document/json_read.h"

#include "core/document/animation.h"
#include "core/document/json_syntax.h"
#include "core/document/scene_checks.h"
#include "core/document/tagged_variant.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <unordered_set>
#include <vector>

namespace inkray {
namespace {

using Json = nlohmann::json;
using KeyList = std::vector<std::string_view>;

// Parameters that belong to the document's structure rather than to a struct's
// parameter table: names of list entries and the object transform.
constexpr Param kMaterialName = required(text("name", "Unique material name"));
constexpr Param kLightName = text("name", "Unique light name");
constexpr Param kMaterialLines = group("lines", "Outline overrides for surfaces of this material");
constexpr Param kScale = vector("scale", "Scale factors along x, y, z; applied first");
constexpr Param kTranslate = vector("translate", "Offset applied last");
constexpr std::string_view kTopLevelKeys[] = {"format",      "version",   "camera",   "render",
                                              "environment", "materials", "objects",  "lights",
                                              "outlines",    "strokes",   "animation"};

// ---------------------------------------------------------------- message helpers
std::string format_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  if (x == std::trunc(x) && std::fabs(x) < 1e15) return std::to_string(static_cast<long long>(x));
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

std::string join(const KeyList& names, std::string_view separator = ", ") {
  std::string out;
  for (std::string_view name : names) {
    if (!out.empty()) out += separator;
    out += name;
  }
  return out;
}

bool is_scalar(const Json& j) { return !j.is_array() && !j.is_object(); }

// What a value was, for "got ..." (short and never recursive: the value may be hostile).
std::string describe(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return j.get<bool>() ? "true" : "false";
    case Json::value_t::number_integer:
      return std::to_string(j.get<std::int64_t>());
    case Json::value_t::number_unsigned:
      return std::to_string(j.get<std::uint64_t>());
    case Json::value_t::number_float:
      return format_number(j.get<double>());
    case Json::value_t::string:
      return in_quotes(j.get_ref<const std::string&>());
    case Json::value_t::object:
      return "an object";
    case Json::value_t::array: {
      if (j.empty()) return "an empty array";
      if (j.size() <= 8 && std::all_of(j.begin(), j.end(), is_scalar)) {
        std::string out = "[";
        for (const Json& e : j) out += (out.size() > 1 ? ", " : "") + describe(e);
        return out + "]";
      }
      return "an array of " + std::to_string(j.size()) + (j.size() == 1 ? " element" : " elements");
    }
    default:
      return "an unsupported value";
  }
}

std::string range_text(const Param& p) {
  const bool low = std::isfinite(p.min), high = std::isfinite(p.max);
  if (low && high) return " in [" + format_number(p.min) + ", " + format_number(p.max) + "]";
  if (low) return " >= " + format_number(p.min);
  if (high) return " <= " + format_number(p.max);
  return "";
}

// Unbounded parameters are still stored as floats. Below the midpoint between FLT_MAX
// and 2^128, a double rounds to a finite float (the writer's 3.4028235e+38 among them).
bool fits_float(double x) { return std::isfinite(x) && std::fabs(x) < 0x1.ffffffp127; }
bool number_ok(const Param& p, double x) { return x >= p.min && x <= p.max && fits_float(x); }
// " in [0, 1]", or for an unbounded parameter the float range it is stored in.
std::string limits_text(const Param& p) {
  const std::string range = range_text(p);
  return range.empty() ? " at most 3.4e+38 in magnitude" : range;
}

// ---------------------------------------------------------------- values
bool read_value(ErrorLog& log, const Param& p, const Json& j, const std::string& at, ColorInput& out);

bool read_value(ErrorLog& log, const Param& p, const Json& j, const std::string& at, float& out) {
  if (!j.is_number() || !number_ok(p, j.get<double>())) {
    log.add(at, "expected a number" + limits_text(p) + ", got " + describe(j));
    return false;
  }
  out = static_cast<float>(j.get<double>());
  return true;
}

bool read_value(ErrorLog& log, const Param& p, const Json& j, const std::string& at, int& out) {
  const auto int_ok = [&](double x) {
    return x == std::trunc(x) && x >= p.min && x <= p.max && std::fabs(x) <= std::numeric_limits<int>::max();
  };
  if (!j.is_number() || !int_ok(j.get<double>())) {
    log.add(at, "expected an integer" + range_text(p) + ", got " + describe(j));
    return false;
  }
  out = static_cast<int>(j.get<double>());
  return true;
}

bool read_value(ErrorLog& log, const Param&, const Json& j, const std::string& at, bool& out) {
  if (!j.is_boolean()) {
    log.add(at, "expected true or false, got " + describe(j));
    return false;
  }
  out = j.get<bool>();
  return true;
}

// Points, vectors, directions and colours; a colour may also be one number (grey).
bool read_value(ErrorLog& log, const Param& p, const Json& j, const std::string& at, Vec3& out) {
  const bool grey_ok = p.kind == ParamKind::color;
  const bool shape_ok = (grey_ok && j.is_number()) ||
                        (j.is_array() && j.size() == 3 &&
                         std::all_of(j.begin(), j.end(), [](const Json& e) { return e.is_number(); }));
  const std::string expected =
      grey_ok ? "expected a number or an array of 3 numbers" : "expected an array of 3 numbers";
  if (!shape_ok) {
    log.add(at, expected + ", got " + describe(j));
    return false;
  }
  Vec3 v;
  for (int i = 0; i < 3; ++i) {
    const double x = j.is_number() ? j.get<double>() : j[static_cast<std::size_t>(i)].get<double>();
    if (!number_ok(p, x)) {
      log.add(at, expected + ", each" + limits_text(p) + ", got " + describe(j));
      return false;
    }
    v[i] = static_cast<float>(x);
  }
  if (p.kind == ParamKind::direction && v == Vec3(0.f)) {
    log.add(at, "expected a non-zero direction, got " + describe(j));
    return false;
  }
  out = v;
  return true;
}

bool read_value(ErrorLog& log, const Param& p, const Json& j, const std::string& at, std::string& out) {
  // "" for an optional name or path means unset, as an absent key does: files written
  // before the writer left unset values out say "ramp_image": "" and must still open.
  // For a required one (a texture's file, a mix's material) the document is whole but
  // cannot render until it is set: the editor writes that while the user chooses.
  if (j.is_string() && j.get_ref<const std::string&>().empty()) {
    out.clear();
    if (p.required && p.kind != ParamKind::path) {  // check_scene reports unset required paths
      log.add_unrenderable(at, "expected a non-empty string, got \"\"");
    }
    return true;
  }
  if (!j.is_string() || j.get_ref<const std::string&>().empty()) {
    const bool is_path = p.kind == ParamKind::path;
    log.add(at, std::string(is_path ? "expected a file path (a non-empty string)"
                                    : "expected a non-empty string") +
                    ", got " + describe(j));
    return false;
  }
  out = j.get_ref<const std::string&>();  // paths are checked against the disk once the whole scene is read
  return true;
}

// Choices: an enum stored by index into Param::choices.
template <class E>
requires std::is_enum_v<E>
bool read_value(ErrorLog& log, const Param& p, const Json& j, const std::string& at, E& out) {
  if (j.is_string()) {
    const std::string& name = j.get_ref<const std::string&>();
    for (std::size_t i = 0; i < p.choices.size(); ++i) {
      if (p.choices[i] == name) {
        out = static_cast<E>(i);
        return true;
      }
    }
  }
  std::string names;
  for (std::string_view c : p.choices) names += (names.empty() ? "" : ", ") + in_quotes(c);
  log.add(at, "expected one of " + names + ", got " + describe(j));
  return false;
}

// Colour lists (ramps): an array of colours.
bool read_value(ErrorLog& log, const Param& p, const Json& j, const std::string& at,
                std::vector<Color>& out) {
  if (!j.is_array() || j.size() > 256) {
    log.add(at, "expected an array of at most 256 colours, got " + describe(j));
    return false;
  }
  Param element = p;
  element.kind = ParamKind::color;
  std::vector<Color> colors(j.size());
  bool ok = true;
  for (std::size_t i = 0; i < j.size(); ++i)
    ok &= read_value(log, element, j[i], element_path(at, i), colors[i]);
  if (ok) out = std::move(colors);
  return ok;
}

template <ParamGroup T>
bool read_value(ErrorLog& log, const Param&, const Json& j, const std::string& at, T& out);
template <ParamGroup T>
bool read_value(ErrorLog& log, const Param& p, const Json& j, const std::string& at, std::vector<T>& out);
bool read_value(ErrorLog& log, const Param& p, const Json& j, const std::string& at,
                std::vector<GraphNodeDesc>& out);

// ---------------------------------------------------------------- structs and variants
// The visitor a struct's parameter table is walked with: reads the key a Param names, if present, and
// records the name so unknown keys can be reported afterwards.
struct ParamReader {
  ErrorLog& log;
  const Json& object;
  const std::string& at;
  KeyList& allowed;

  template <class T>
  void operator()(const Param& p, T& field) {
    allowed.push_back(p.name);
    const auto it = object.find(std::string(p.name));
    if (it == object.end()) {
      if (p.required) log.add(at, "missing required key \"" + std::string(p.name) + "\"");
      return;
    }
    read_value(log, p, *it, child_path(at, p.name), field);
  }
};

template <class Desc>
void read_params(ErrorLog& log, const Json& object, Desc& desc, const std::string& at, KeyList& allowed) {
  ParamReader reader{log, object, at, allowed};
  visit_params(desc, reader);
}

void check_keys(ErrorLog& log, const Json& object, const std::string& at, const KeyList& allowed);
bool expect_object(ErrorLog& log, const Json& j, const std::string& at, std::string_view what);

// A nested struct (ParamKind::group): an object read with the struct's own parameter list.
template <ParamGroup T>
bool read_value(ErrorLog& log, const Param&, const Json& j, const std::string& at, T& out) {
  if (!expect_object(log, j, at, "an object")) return false;
  KeyList allowed;
  read_params(log, j, out, at, allowed);
  check_keys(log, j, at, allowed);
  return true;
}

// A list of structs (ParamKind::list): an array of objects, each read with the struct's list.
template <ParamGroup T>
bool read_value(ErrorLog& log, const Param&, const Json& j, const std::string& at, std::vector<T>& out) {
  if (!j.is_array()) {
    log.add(at, "expected an array of objects, got " + describe(j));
    return false;
  }
  std::vector<T> items(j.size());
  for (std::size_t i = 0; i < j.size(); ++i) read_value(log, Param{}, j[i], element_path(at, i), items[i]);
  out = std::move(items);
  return true;
}

void check_keys(ErrorLog& log, const Json& object, const std::string& at, const KeyList& allowed) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end()) {
      log.add(at, "unknown key " + in_quotes(it.key()) + " (expected one of: " + join(allowed) + ")");
    }
  }
}

bool expect_object(ErrorLog& log, const Json& j, const std::string& at, std::string_view what) {
  if (j.is_object()) return true;
  log.add(at, "expected " + std::string(what) + ", got " + describe(j));
  return false;
}

// Picks the alternative named by "type" and reads its parameters from the same object.
// False when the type is missing or unknown (the object's other keys are then unchecked).
template <class Variant>
bool read_tagged(ErrorLog& log, const Json& object, Variant& out, const std::string& at,
                 std::string_view noun, KeyList& allowed) {
  allowed.push_back("type");
  const std::string types = type_name_list<Variant>();
  const auto type = object.find("type");
  if (type == object.end()) {
    log.add(at, "missing required key \"type\" (the " + std::string(noun) + " type, one of: " + types + ")");
    return false;
  }
  if (!type->is_string()) {
    log.add(child_path(at, "type"),
            "expected a " + std::string(noun) + " type (one of: " + types + "), got " + describe(*type));
    return false;
  }
  if (!emplace_by_type_name(out, type->get_ref<const std::string&>())) {
    log.add(child_path(at, "type"), "unknown " + std::string(noun) + " type " + describe(*type) +
                                        " (expected one of: " + types + ")");
    return false;
  }
  std::visit(
      [&]<class T>(T& alternative) {
        if constexpr (Tagged<T>) read_params(log, object, alternative, at, allowed);
      },
      out);
  return true;
}

// A value that is nothing but a tagged variant: {"type": ..., parameters...}.
template <class Variant>
void read_tagged_object(ErrorLog& log, const Json& j, Variant& out, const std::string& at,
                        std::string_view noun) {
  if (!expect_object(log, j, at, "an object with a \"type\" key")) return;
  KeyList allowed;
  if (read_tagged(log, j, out, at, noun, allowed)) check_keys(log, j, at, allowed);
}

bool read_value(ErrorLog& log, const Param& p, const Json& j, const std::string& at, ColorInput& out) {
  if (j.is_object()) {
    read_tagged_object(log, j, out, at, "texture");
    return true;
  }
  if (j.is_number() || j.is_array()) {
    Param constant = p;
    constant.kind = ParamKind::color;
    Color c;
    if (!read_value(log, constant, j, at, c)) return false;
    out = c;
    return true;
  }
  log.add(at, "expected a number or an array of 3 numbers (or a texture object with \"type\": " +
                  type_name_list<ColorInput>() + "), got " + describe(j));
  return false;
}

// A graph's nodes: objects with an "id", a "type" and that node type's parameters.
// Ids are checked against each other by the graph's validation (material_graph_checks).
bool read_value(ErrorLog& log, const Param&, const Json& j, const std::string& at,
                std::vector<GraphNodeDesc>& out) {
  if (!j.is_array()) {
    log.add(at, "expected an array of node objects ({\"id\": ..., \"type\": ..., ...}), got " + describe(j));
    return false;
  }
  constexpr Param kNodeId = required(text("id", "Node id, unique within the graph"));
  std::vector<GraphNodeDesc> nodes(j.size());
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string node_at = element_path(at, i);
    if (!expect_object(log, j[i], node_at, "a node object ({\"id\": ..., \"type\": ..., ...})")) continue;
    KeyList allowed;
    ParamReader{log, j[i], node_at, allowed}(kNodeId, nodes[i].id);
    if (read_tagged(log, j[i], nodes[i].data, node_at, "node", allowed))
      check_keys(log, j[i], node_at, allowed);
  }
  out = std::move(nodes);
  return true;
}

template <class Desc>
void read_struct(ErrorLog& log, const Json& j, Desc& desc, const std::string& at) {
  if (!expect_object(log, j, at, "an object")) return;
  KeyList allowed;
  read_params(log, j, desc, at, allowed);
  check_keys(log, j, at, allowed);
}

// ---------------------------------------------------------------- document sections
void read_transform(ErrorLog& log, const Json& j, TransformDesc& t, const std::string& at) {
  if (!expect_object(log, j, at, "an object with keys scale, rotate, translate")) return;
  KeyList allowed = {"scale", "rotate", "translate"};
  if (const auto it = j.find("scale"); it != j.end()) {
    const std::string scale_at = child_path(at, "scale");
    Vec3 scale;
    // A zero factor makes the transform singular: normals and inverse rays would be NaN.
    if (read_value(log, kScale, *it, scale_at, scale)) {
      if (scale.x == 0.f || scale.y == 0.f || scale.z == 0.f) {
        log.add(scale_at, "expected non-zero scale factors, got " + describe(*it));
      } else {
        t.scale = scale;
      }
    }
  }
  if (const auto it = j.find("rotate"); it != j.end()) {
    const std::string rotate_at = child_path(at, "rotate");
    if (!it->is_array()) {
      log.add(rotate_at,
              "expected an array of rotations ({\"axis\": [x, y, z], \"degrees\": a}), got " + describe(*it));
    } else {
      for (std::size_t i = 0; i < it->size(); ++i) {
        RotationDesc rotation;
        read_struct(log, (*it)[i], rotation, element_path(rotate_at, i));
        t.rotate.push_back(rotation);
      }
    }
  }
  if (const auto it = j.find("translate"); it != j.end()) {
    read_value(log, kTranslate, *it, child_path(at, "translate"), t.translate);
  }
  check_keys(log, j, at, allowed);
}

void read_material(ErrorLog& log, const Json& j, MaterialDesc& m, const std::string& at) {
  if (!expect_object(log, j, at, "a material object ({\"name\": ..., \"type\": ..., ...})")) return;
  KeyList allowed;
  ParamReader{log, j, at, allowed}(kMaterialName, m.name);
  ParamReader{log, j, at, allowed}(kMaterialLines, m.lines);
  if (read_tagged(log, j, m.data, at, "material", allowed)) check_keys(log, j, at, allowed);
}

void read_light(ErrorLog& log, const Json& j, LightDesc& l, const std::string& at) {
  if (!expect_object(log, j, at, "a light object ({\"type\": ..., ...})")) return;
  KeyList allowed;
  ParamReader{log, j, at, allowed}(kLightName, l.name);
  if (read_tagged(log, j, l.data, at, "light", allowed)) check_keys(log, j, at, allowed);
}

void read_object(ErrorLog& log, const Json& j, ObjectDesc& o, const std::string& at) {
  if (!expect_object(log, j, at, "an object ({\"material\": ..., \"shape\": ..., ...})")) return;
  KeyList allowed;
  read_params(log, j, o, at, allowed);
  allowed.push_back("shape");
  allowed.push_back("transform");
  if (const auto it = j.find("shape"); it != j.end()) {
    read_tagged_object(log, *it, o.shape, child_path(at, "shape"), "shape");
  }
  if (const auto it = j.find("transform"); it != j.end()) {
    read_transform(log, *it, o.transform, child_path(at, "transform"));
  }
  check_keys(log, j, at, allowed);
}

// False when cancelled.
template <class Item, class ReadItem>
bool read_list(ErrorLog& log, const Json& doc, std::string_view key, SharedList<Item>& items,
               ReadItem read_item, const Cancel& cancel) {
  const auto it = doc.find(std::string(key));
  if (it == doc.end()) return true;
  if (!it->is_array()) {
    log.add(key, "expected an array, got " + describe(*it));
    return true;
  }
  items.reserve(it->size());
  for (std::size_t i = 0; i < it->size(); ++i) {
    if ((i & 1023) == 1023 && cancel.requested()) {
      log.add("", kCancelledReading);
      return false;
    }
    Item item;
    read_item(log, (*it)[i], item, element_path(key, i));
    items.push_back(std::move(item));  // even when broken, so indices in messages match the file
  }
  return true;
}

void read_header(ErrorLog& log, const Json& doc) {
  const std::string format_name = in_quotes(kSceneFormatName);
  if (const auto it = doc.find("format"); it == doc.end()) {
    log.add("", "missing required key \"format\" (expected " + format_name + ")");
  } else if (!it->is_string() || it->get_ref<const std::string&>() != kSceneFormatName) {
    log.add("format", "expected " + format_name + ", got " + describe(*it));
  }
  const std::string supported = "(supported: " + std::to_string(kSceneFormatVersion) + ")";
  if (const auto it = doc.find("version"); it == doc.end()) {
    log.add("", "missing required key \"version\" " + supported);
  } else if (!it->is_number() || it->get<double>() != std::trunc(it->get<double>())) {
    log.add("version", "expected an integer " + supported + ", got " + describe(*it));
  } else if (it->get<double>() > kSceneFormatVersion) {
    log.add("version",
            "version " + describe(*it) + " is newer than this build of inkray supports " + supported);
  } else if (it->get<double>() < kSceneFormatVersion) {
    log.add("version", "unsupported version " + describe(*it) + " " + supported);
  }
}

// ---------------------------------------------------------------- animation
// A key's value is read as its target parameter is, so it gets the same checks and
// messages; the target must therefore resolve first, against the rest of the document.
enum class AnyChoice : int {};

bool read_key_value(ErrorLog& log, const Param& p, const Json& j, const std::string& at,
                    std::vector<double>& out) {
  switch (p.kind) {
    case ParamKind::number: {
      float f = 0.f;
      if (!read_value(log, p, j, at, f)) return false;
      out = {double(f)};
      return true;
    }
    case ParamKind::integer: {
      int i = 0;
      if (!read_value(log, p, j, at, i)) return false;
      out = {double(i)};
      return true;
    }
    case ParamKind::toggle: {
      bool b = false;
      if (!read_value(log, p, j, at, b)) return false;
      out = {b ? 1.0 : 0.0};
      return true;
    }
    case ParamKind::choice: {
      AnyChoice c{};
      if (!read_value(log, p, j, at, c)) return false;
      out = {double(int(c))};
      return true;
    }
    default: {
      Param vec = p;
      if (p.kind == ParamKind::color_input) vec = color(p.name, 1e6, p.doc);
      Vec3 v(0.f);
      if (key_width(p.kind) != 3 || !read_value(log, vec, j, at, v)) return false;
      out = {double(v.x), double(v.y), double(v.z)};
      return true;
    }
  }
}

// The numbers of a value whose target does not resolve, kept so the file round-trips.
std::vector<double> raw_key_value(const Json& j) {
  if (j.is_boolean()) return {j.get<bool>() ? 1.0 : 0.0};
  if (j.is_number()) return {j.get<double>()};
  std::vector<double> out;
  if (j.is_array())
    for (const Json& e : j)
      if (e.is_number()) out.push_back(e.get<double>());
  return out;
}

constexpr Param kKeyFrame = required(number("frame", -1e6, 1e6, "Frame of the key"));
constexpr Param kKeyInterp = choice("interp", kInterpolationNames, "Interpolation towards the next key");

void read_track(ErrorLog& log, const TargetResolver& targets, const Json& j, TrackDesc& track,
                const std::string& at) {
  if (!expect_object(log, j, at,
                     "a track ({\"target\": \"objects/NAME/transform/translate\", \"keys\": [...]})"))
    return;
  check_keys(log, j, at, {"target", "keys"});
  const auto target = j.find("target");
  if (target == j.end() || !target->is_string() || target->get_ref<const std::string&>().empty()) {
    log.add(child_path(at, "target"),
            "expected a parameter path such as \"objects/ball/transform/translate\", got " +
                (target == j.end() ? std::string("nothing") : describe(*target)));
    return;
  }
  track.target = target->get_ref<const std::string&>();
  // An unknown target is reported by check_scene (check_animation), as other references are.
  const std::optional<Param> p = targets.target(track.target, nullptr);
  const auto keys = j.find("keys");
  const std::string keys_at = child_path(at, "keys");
  if (keys == j.end() || !keys->is_array() || keys->empty()) {
    log.add(keys_at, "expected a non-empty array of keys ({\"frame\": f, \"value\": v}), got " +
                         (keys == j.end() ? std::string("nothing") : describe(*keys)));
    return;
  }
  for (std::size_t k = 0; k < keys->size(); ++k) {
    const Json& key_json = (*keys)[k];
    const std::string key_at = element_path(keys_at, k);
    if (!expect_object(log, key_json, key_at, "a key ({\"frame\": f, \"value\": v, \"interp\": \"bezier\"})"))
      continue;
    check_keys(log, key_json, key_at, {"frame", "value", "interp"});
    KeyDesc key;
    const auto frame = key_json.find("frame");
    if (frame == key_json.end()) {
      log.add(key_at, "missing required key \"frame\"");
      continue;
    }
    float f = 0.f;
    if (!read_value(log, kKeyFrame, *frame, child_path(key_at, "frame"), f)) continue;
    key.frame = frame->get<double>();
    if (const auto interp = key_json.find("interp"); interp != key_json.end())
      read_value(log, kKeyInterp, *interp, child_path(key_at, "interp"), key.interp);
    const auto value = key_json.find("value");
    if (value == key_json.end()) {
      log.add(key_at, "missing required key \"value\"");
      continue;
    }
    if (p) {
      if (!read_key_value(log, *p, *value, child_path(key_at, "value"), key.value)) continue;
    } else {
      key.value = raw_key_value(*value);
    }
    if (!track.keys.empty() && !(key.frame > track.keys.back().frame)) {
      log.add(child_path(key_at, "frame"), "keys must be in increasing frame order, one per frame: frame " +
                                               format_number(key.frame) + " follows frame " +
                                               format_number(track.keys.back().frame));
      continue;
    }
    track.keys.push_back(std::move(key));
  }
}

void read_animation(ErrorLog& log, const Json& doc, SceneDesc& scene) {
  const auto it = doc.find("animation");
  if (it == doc.end()) return;
  if (!it->is_array()) {
    log.add("animation", "expected an array of tracks, got " + describe(*it));
    return;
  }
  // The lists are read by now; tracks are resolved against them through one index and
  // checked for a shared target with a set, so many tracks take linear time.
  const TargetResolver targets(scene);
  std::unordered_set<std::string> animated;
  for (std::size_t i = 0; i < it->size(); ++i) {
    TrackDesc track;
    const std::string at = element_path("animation", i);
    read_track(log, targets, (*it)[i], track, at);
    if (!track.target.empty() && !animated.insert(track.target).second)
      log.add(child_path(at, "target"), "another track already animates " + in_quotes(track.target));
    scene.animation.push_back(std::move(track));
  }
}

}  // namespace

void read_scene_document(const nlohmann::json& doc, const std::filesystem::path& base_dir, SceneDesc& scene,
                         ErrorLog& log, const Cancel& cancel) {
  if (!doc.is_object()) {
    log.add("", "expected a JSON object at the top level, got " + describe(doc));
    return;
  }
  read_header(log, doc);
  check_keys(log, doc, "", KeyList(std::begin(kTopLevelKeys), std::end(kTopLevelKeys)));

  if (const auto it = doc.find("camera"); it != doc.end()) read_struct(log, *it, scene.camera, "camera");
  if (const auto it = doc.find("render"); it != doc.end()) read_struct(log, *it, scene.render, "render");
  if (const auto it = doc.find("environment"); it != doc.end()) {
    read_tagged_object(log, *it, scene.environment, "environment", "environment");
  }
  if (!read_list(log, doc, "materials", scene.materials, read_material, cancel) ||
      !read_list(log, doc, "objects", scene.objects, read_object, cancel) ||
      !read_list(log, doc, "lights", scene.lights, read_light, cancel))
    return;
  if (const auto it = doc.find("outlines"); it != doc.end())
    read_struct(log, *it, scene.outlines, "outlines");
  const auto read_emitter = [](ErrorLog& l, const Json& j, StrokeEmitterDesc& e, const std::string& at) {
    read_struct(l, j, e, at);
  };
  if (!read_list(log, doc, "strokes", scene.strokes, read_emitter, cancel)) return;

  name_unnamed(scene);
  read_animation(log, doc, scene);
  check_scene(scene, base_dir, log);
}

}  // namespace inkray
