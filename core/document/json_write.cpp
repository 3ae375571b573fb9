// The generic scene writer: a walk over the parameter tables turns each field into JSON
// by its C++ type (and, for choices, its Param's name table).
#include "core/document/json_write.h"

#include "core/document/animation.h"
#include "core/document/tagged_variant.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <system_error>
#include <type_traits>

namespace inkray {

double float_to_json_number(float f) {
  if (!std::isfinite(f)) return f;  // dumped as null, which the reader rejects
  char buffer[64];
  const auto written = std::to_chars(buffer, buffer + sizeof buffer, f);  // shortest round-trip form
  double d = 0.0;
  const auto parsed = std::from_chars(buffer, written.ptr, d);
  // Decimal -> double -> float rounds twice; keep the exact value if that ever changes f.
  if (written.ec != std::errc() || parsed.ec != std::errc() || static_cast<float>(d) != f) return f;
  return d;
}

namespace {

using Json = nlohmann::ordered_json;

Json value_json(const Param& p, const ColorInput& c);

Json value_json(const Param&, float f) { return float_to_json_number(f); }
Json value_json(const Param&, int i) { return i; }
Json value_json(const Param&, bool b) { return b; }
Json value_json(const Param&, const std::string& s) { return s; }
Json value_json(const Param&, const Vec3& v) {
  return Json::array({float_to_json_number(v.x), float_to_json_number(v.y), float_to_json_number(v.z)});
}
template <class E>
requires std::is_enum_v<E> Json value_json(const Param& p, E e) {
  const auto index = static_cast<std::size_t>(e);
  // An out-of-range value is kept as a number; the reader will name the valid choices.
  if (index < p.choices.size()) return std::string(p.choices[index]);
  return static_cast<long long>(e);
}

Json value_json(const Param&, const std::vector<Color>& colors) {
  Json list = Json::array();
  for (const Color& c : colors) list.push_back(value_json(Param{}, c));
  return list;
}

template <class Desc>
void write_params(Json& object, const Desc& desc);
template <class Variant>
void write_tagged(Json& object, const Variant& value);

// A list of structs: an array of objects.
template <ParamGroup T>
Json value_json(const Param&, const std::vector<T>& items) {
  Json list = Json::array();
  for (const T& item : items) {
    Json object = Json::object();
    write_params(object, item);
    list.push_back(std::move(object));
  }
  return list;
}

// A graph's nodes: the id first, then the type and its parameters.
Json value_json(const Param&, const std::vector<GraphNodeDesc>& nodes) {
  Json list = Json::array();
  for (const GraphNodeDesc& node : nodes) {
    Json object = Json::object();
    object["id"] = node.id;
    write_tagged(object, node.data);
    list.push_back(std::move(object));
  }
  return list;
}

// A nested struct (ParamKind::group) is written as an object of its own parameters.
template <ParamGroup T>
Json value_json(const Param&, const T& group) {
  Json object = Json::object();
  write_params(object, group);
  return object;
}

struct ParamWriter {
  Json& object;
  template <class T>
  void operator()(const Param& p, const T& field) {
    // An optional name or path that is unset is left out rather than written as "",
    // which the reader refuses for what must be a non-empty string.
    if constexpr (std::is_same_v<T, std::string>) {
      if (field.empty() && !p.required) return;
    }
    object[std::string(p.name)] = value_json(p, field);
  }
};

template <class Desc>
void write_params(Json& object, const Desc& desc) {
  ParamWriter writer{object};
  visit_params(desc, writer);
}

// Adds "type" and the alternative's parameters to an object.
template <class Variant>
void write_tagged(Json& object, const Variant& value) {
  std::visit(
      [&]<class T>(const T& alternative) {
        if constexpr (Tagged<T>) {
          object["type"] = std::string(T::type_name);
          write_params(object, alternative);
        }
      },
      value);
}

template <class Variant>
Json tagged_json(const Variant& value) {
  Json object = Json::object();
  write_tagged(object, value);
  return object;
}

template <class Desc>
Json struct_json(const Desc& desc) {
  Json object = Json::object();
  write_params(object, desc);
  return object;
}

Json value_json(const Param& p, const ColorInput& c) {
  if (const Color* constant = std::get_if<Color>(&c)) return value_json(p, *constant);
  return tagged_json(c);
}

Json transform_json(const TransformDesc& t) {
  Json object = Json::object();
  object["scale"] = value_json(Param{}, t.scale);
  Json rotations = Json::array();
  for (const RotationDesc& r : t.rotate) rotations.push_back(struct_json(r));
  object["rotate"] = std::move(rotations);
  object["translate"] = value_json(Param{}, t.translate);
  return object;
}

std::string dump_plain(const Json& value) {
  return value.dump(-1, ' ', false, Json::error_handler_t::replace);
}

// Recursion is bounded by the document's own shape: we only format what we wrote.
void append_pretty(std::string& out, const Json& value, std::size_t indent) {
  const bool is_object = value.is_object();
  if (!is_object && !value.is_array()) {
    out += dump_plain(value);
    return;
  }
  if (value.empty()) {
    out += is_object ? "{}" : "[]";
    return;
  }
  const bool inline_array =
      !is_object && std::none_of(value.begin(), value.end(), [](const Json& e) { return e.is_structured(); });
  if (inline_array) {
    out += '[';
    for (std::size_t i = 0; i < value.size(); ++i) out += (i ? ", " : "") + dump_plain(value[i]);
    out += ']';
    return;
  }
  out += is_object ? "{\n" : "[\n";
  bool first = true;
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (!first) out += ",\n";
    first = false;
    out.append(indent + 2, ' ');
    if (is_object) out += dump_plain(Json(it.key())) + ": ";
    append_pretty(out, it.value(), indent + 2);
  }
  out += '\n';
  out.append(indent, ' ');
  out += is_object ? '}' : ']';
}

// A key's value as its parameter is written: a number, true/false, a choice's name or
// an array of three. A track whose target does not resolve keeps its numbers.
Json key_value_json(const std::optional<Param>& p, const std::vector<double>& value) {
  const auto number = [&](double x) {
    if (p && p->kind == ParamKind::integer) return Json(static_cast<long long>(std::llround(x)));
    return Json(float_to_json_number(static_cast<float>(x)));
  };
  if (value.size() == 1) {
    if (p && p->kind == ParamKind::toggle) return value[0] >= 0.5;
    if (p && p->kind == ParamKind::choice) {
      const auto index = static_cast<std::size_t>(std::llround(value[0]));
      if (index < p->choices.size()) return std::string(p->choices[index]);
    }
    return number(value[0]);
  }
  Json list = Json::array();
  for (double x : value) list.push_back(number(x));
  return list;
}

Json animation_json(const SceneDesc& scene) {
  Json tracks = Json::array();
  const TargetResolver targets(scene);
  for (const TrackDesc& track : scene.animation) {
    const std::optional<Param> p = targets.target(track.target, nullptr);
    Json keys = Json::array();
    for (const KeyDesc& key : track.keys) {
      Json object = Json::object();
      object["frame"] = key.frame;
      object["value"] = key_value_json(p, key.value);
      object["interp"] = std::string(kInterpolationNames[static_cast<std::size_t>(key.interp)]);
      keys.push_back(std::move(object));
    }
    Json object = Json::object();
    object["target"] = track.target;
    object["keys"] = std::move(keys);
    tracks.push_back(std::move(object));
  }
  return tracks;
}

}  // namespace

std::string format_scene_json(const nlohmann::ordered_json& doc) {
  std::string out;
  append_pretty(out, doc, 0);
  out += '\n';
  return out;
}

nlohmann::ordered_json write_scene_document(const SceneDesc& scene) {
  Json doc = Json::object();
  doc["format"] = std::string(kSceneFormatName);
  doc["version"] = kSceneFormatVersion;
  doc["camera"] = struct_json(scene.camera);
  doc["render"] = struct_json(scene.render);
  doc["environment"] = tagged_json(scene.environment);

  Json materials = Json::array();
  for (const MaterialDesc& m : scene.materials) {
    Json object = Json::object();
    object["name"] = m.name;
    write_tagged(object, m.data);
    object["lines"] = value_json(Param{}, m.lines);
    materials.push_back(std::move(object));
  }
  doc["materials"] = std::move(materials);

  Json objects = Json::array();
  for (const ObjectDesc& o : scene.objects) {
    Json object = struct_json(o);
    object["shape"] = tagged_json(o.shape);
    object["transform"] = transform_json(o.transform);
    objects.push_back(std::move(object));
  }
  doc["objects"] = std::move(objects);

  Json lights = Json::array();
  for (const LightDesc& l : scene.lights) {
    Json object = Json::object();
    object["name"] = l.name;
    write_tagged(object, l.data);
    lights.push_back(std::move(object));
  }
  doc["lights"] = std::move(lights);
  doc["outlines"] = struct_json(scene.outlines);

  Json strokes = Json::array();
  for (const StrokeEmitterDesc& e : scene.strokes) strokes.push_back(struct_json(e));
  doc["strokes"] = std::move(strokes);
  if (!scene.animation.empty()) doc["animation"] = animation_json(scene);
  return doc;
}

}  // namespace inkray
