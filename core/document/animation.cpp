// Tracks: paths resolved through the parameter lists, keys interpolated per component.
// docs/architecture.md, "Animation".
#include "core/document/animation.h"

#include "core/document/error_log.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <unordered_map>

namespace inkray {

// Where each named entry of the document's lists is, by its name (the first entry
// of a name, as a search would find): built once for a pass over many tracks, so
// resolving them costs a lookup each, not a search of the list.
struct AnimationNames {
  using Map = std::unordered_map<std::string_view, size_t>;
  Map objects, lights, materials, strokes;
  explicit AnimationNames(const SceneDesc& desc) {
    fill(objects, desc.objects);
    fill(lights, desc.lights);
    fill(materials, desc.materials);
    fill(strokes, desc.strokes);
  }
  template <class Item>
  static void fill(Map& map, const SharedList<Item>& items) {
    map.reserve(items.size());
    for (size_t i = 0; i < items.size(); ++i) map.emplace(items[i].name, i);
  }
};

namespace {

using NameIndex = AnimationNames;
using Path = std::span<const std::string_view>;

// Render settings that shape the shot itself: keyed, they would change what a frame is.
constexpr std::string_view kUnkeyableRender[] = {"width",     "height", "frame",        "frame_start",
                                                 "frame_end", "fps",    "shutter_open", "shutter_close"};

std::vector<std::string_view> split(std::string_view path) {
  std::vector<std::string_view> parts;
  size_t start = 0;
  while (start <= path.size()) {
    const size_t slash = path.find('/', start);
    const size_t end = slash == std::string_view::npos ? path.size() : slash;
    parts.push_back(path.substr(start, end - start));
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  return parts;
}

// What to do with the parameter at the end of a path.
struct Access {
  enum class Op { probe, read, write } op = Op::probe;
  std::vector<double>* out = nullptr;
  std::span<const double> in;
  std::optional<Param> found;
  std::string error;
  const NameIndex* names = nullptr;  // null: entries are searched for
};

template <class T>
constexpr bool is_variant = false;
template <class... Ts>
constexpr bool is_variant<std::variant<Ts...>> = true;

double clamp_to(const Param& p, double x) {
  if (!std::isfinite(x)) x = 0.0;
  return std::clamp(x, std::max(p.min, -3.0e38), std::min(p.max, 3.0e38));
}

// T is const when the walk only reads (Access::Op::probe and read): the writes
// below exist only for a mutable field.
template <class T>
void leaf(Access& a, const Param& p, T& field, std::string_view name) {
  using U = std::remove_const_t<T>;
  constexpr bool writable = !std::is_const_v<T>;
  const int width = key_width(p.kind);
  if (p.kind == ParamKind::group) {
    a.error = in_quotes(name) + " is a group of parameters; name one of them";
    return;
  }
  if (width == 0) {
    a.error =
        in_quotes(name) + " cannot be keyed (only numbers, toggles, choices, points, vectors and colours)";
    return;
  }
  using Op = Access::Op;
  const bool write = a.op == Op::write;
  if constexpr (std::is_same_v<U, float>) {
    if (a.op == Op::read) *a.out = {double(field)};
    if constexpr (writable)
      if (write) field = float(clamp_to(p, a.in[0]));
  } else if constexpr (std::is_same_v<U, int>) {
    if (a.op == Op::read) *a.out = {double(field)};
    if constexpr (writable)
      if (write) field = int(std::lround(clamp_to(p, a.in[0])));
  } else if constexpr (std::is_same_v<U, bool>) {
    if (a.op == Op::read) *a.out = {field ? 1.0 : 0.0};
    if constexpr (writable)
      if (write) field = a.in[0] >= 0.5;
  } else if constexpr (std::is_enum_v<U>) {
    if (a.op == Op::read) *a.out = {double(field)};
    if constexpr (writable)
      if (write) field = U(int(std::lround(clamp_to(p, a.in[0]))));
  } else if constexpr (std::is_same_v<U, Vec3>) {
    if (a.op == Op::read) *a.out = {field.x, field.y, field.z};
    if constexpr (writable)
      if (write)
        for (int i = 0; i < 3; ++i) field[i] = float(clamp_to(p, a.in[size_t(i)]));
  } else if constexpr (std::is_same_v<U, ColorInput>) {
    auto* constant = std::get_if<Color>(&field);
    if (!constant) {
      a.error = in_quotes(name) + " is a texture here; only a constant colour can be keyed";
      return;
    }
    leaf(a, p, *constant, name);
    return;
  } else {
    a.error = in_quotes(name) + " cannot be keyed";
    return;
  }
  a.found = p;
}

template <class T>
void descend(Access& a, const Param& p, T& field, Path rest);

// A list of structs with names and parameter tables (outline line sets).
template <class T>
concept NamedList = requires(T& list) {
  list.begin();
  list[0].name;
}
&&ParamGroup<std::decay_t<decltype(std::declval<T&>()[0])>>;

// Matches the first part of a path against a struct's parameter list.
struct PathVisitor {
  Access* a;
  Path rest;
  bool matched = false;
  template <class T>
  void operator()(const Param& p, T& field) {
    if (matched || p.name != rest[0]) return;
    matched = true;
    descend(*a, p, field, rest.subspan(1));
  }
};

template <class T>
void descend_struct(Access& a, T& desc, Path rest, std::string_view context) {
  if (rest.empty()) {
    a.error = in_quotes(context) + " is a group of parameters; name one of them";
    return;
  }
  PathVisitor visitor{&a, rest};
  visit_params(desc, visitor);
  if (!visitor.matched && a.error.empty())
    a.error = in_quotes(context) + " has no parameter " + in_quotes(rest[0]);
}

template <class T>
void descend(Access& a, const Param& p, T& field, Path rest) {
  if (rest.empty()) return leaf(a, p, field, p.name);
  if constexpr (ParamGroup<T>) {
    descend_struct(a, field, rest, p.name);
  } else if constexpr (is_variant<std::remove_const_t<T>>) {
    std::visit(
        [&](auto& alternative) {
          if constexpr (ParamGroup<std::decay_t<decltype(alternative)>>) {
            descend_struct(a, alternative, rest, p.name);
          } else {
            a.error = in_quotes(p.name) + " has no parameter " + in_quotes(rest[0]);
          }
        },
        field);
  } else if constexpr (NamedList<T>) {
    // A list of named entries (outline line sets): an entry by its name, as objects are.
    for (auto& item : field)
      if (item.name == rest[0]) return descend_struct(a, item, rest.subspan(1), item.name);
    a.error = "no entry named " + in_quotes(rest[0]) + " in " + in_quotes(p.name);
  } else {
    a.error = in_quotes(p.name) + " has no parameter " + in_quotes(rest[0]);
  }
}

template <class Items>
auto by_name(Items& items, std::string_view name, const NameIndex::Map* index) -> decltype(&items[0]) {
  if (index) {
    const auto found = index->find(name);
    return found == index->end() ? nullptr : &items[found->second];
  }
  for (auto& item : items)
    if (item.name == name) return &item;
  return nullptr;
}

constexpr Param kScale = vector("scale", "Scale factors along x, y, z");
constexpr Param kTranslate = vector("translate", "Offset applied last");

template <class Transform>
void descend_transform(Access& a, Transform& t, Path rest) {
  if (rest.empty()) {
    a.error = "\"transform\" is a group; name scale, translate or rotate/INDEX/degrees";
    return;
  }
  if (rest[0] == "scale" && rest.size() == 1) return leaf(a, kScale, t.scale, "scale");
  if (rest[0] == "translate" && rest.size() == 1) return leaf(a, kTranslate, t.translate, "translate");
  if (rest[0] == "rotate" && rest.size() == 3) {
    size_t index = 0;
    const std::string_view digits = rest[1];
    bool ok = !digits.empty() && digits.size() < 6;
    for (char c : digits) {
      ok = ok && c >= '0' && c <= '9';
      index = index * 10 + size_t(c - '0');
    }
    if (!ok || index >= t.rotate.size()) {
      a.error = "\"rotate/" + std::string(digits) + "\": the transform has " +
                std::to_string(t.rotate.size()) + " rotations (numbered from 0)";
      return;
    }
    return descend_struct(a, t.rotate[index], rest.subspan(2), "rotate");
  }
  a.error = "\"transform\" has scale, translate and rotate/INDEX/(degrees|axis), not " + in_quotes(rest[0]);
}

template <class Items, class Next>
void named(Access& a, Items& items, const NameIndex::Map NameIndex::*index, Path rest,
           std::string_view section, Next next) {
  if (rest.empty()) {
    a.error = in_quotes(section) + " needs a name: " + std::string(section) + "/NAME/...";
    return;
  }
  auto* item = by_name(items, rest[0], a.names ? &(a.names->*index) : nullptr);
  if (!item) {
    a.error = "no entry named " + in_quotes(rest[0]) + " in " + in_quotes(section);
    return;
  }
  if (rest.size() == 1) {
    a.error = std::string(section) + "/" + std::string(rest[0]) + " names an entry; add a parameter";
    return;
  }
  next(*item, rest.subspan(1));
}

// Scene is const for a probe or a read, so only a write can change the document.
template <class Scene>
void resolve(Scene& desc, std::string_view path, Access& a) {
  const std::vector<std::string_view> parts = split(path);
  const Path all(parts);
  const std::string_view head = all[0];
  const Path rest = all.subspan(1);
  if (head == "camera") return descend_struct(a, desc.camera, rest, "camera");
  if (head == "render") {
    if (!rest.empty() && std::find(std::begin(kUnkeyableRender), std::end(kUnkeyableRender), rest[0]) !=
                             std::end(kUnkeyableRender)) {
      a.error = "render/" + std::string(rest[0]) + " shapes the whole shot and cannot be keyed";
      return;
    }
    return descend_struct(a, desc.render, rest, "render");
  }
  if (head == "outlines") return descend_struct(a, desc.outlines, rest, "outlines");
  if (head == "environment") return descend(a, group("environment", ""), desc.environment, rest);
  if (head == "objects") {
    return named(a, desc.objects, &NameIndex::objects, rest, "objects", [&](auto& o, Path r) {
      if (r[0] == "transform") return descend_transform(a, o.transform, r.subspan(1));
      if (r[0] == "shape") return descend(a, group("shape", ""), o.shape, r.subspan(1));
      descend_struct(a, o, r, o.name);
    });
  }
  if (head == "lights") {
    return named(a, desc.lights, &NameIndex::lights, rest, "lights",
                 [&](auto& l, Path r) { descend(a, group(l.name, ""), l.data, r); });
  }
  if (head == "materials") {
    return named(a, desc.materials, &NameIndex::materials, rest, "materials", [&](auto& m, Path r) {
      if (r[0] == "lines") return descend(a, group("lines", ""), m.lines, r.subspan(1));
      if (auto* graph = std::get_if<GraphDesc>(&m.data)) {
        if (r[0] != "nodes" || r.size() < 3) {
          a.error =
              "a graph material's parameters are its nodes': materials/" + m.name + "/nodes/NODE_ID/PARAM";
          return;
        }
        for (auto& node : graph->nodes)
          if (node.id == r[1]) return descend(a, group(node.id, ""), node.data, r.subspan(2));
        a.error = "graph material " + in_quotes(m.name) + " has no node with id " + in_quotes(r[1]);
        return;
      }
      descend(a, group(m.name, ""), m.data, r);
    });
  }
  if (head == "strokes") {
    return named(a, desc.strokes, &NameIndex::strokes, rest, "strokes", [&](auto& e, Path r) {
      if (r[0] == "name" || r[0] == "object" || r[0] == "count" || r[0] == "seed") {
        // A stroke keeps its place and looks from frame to frame: what decides which
        // strokes exist is not animated.
        a.error = "strokes/" + e.name + "/" + std::string(r[0]) +
                  " decides which strokes exist and cannot be keyed";
        return;
      }
      descend_struct(a, e, r, e.name);
    });
  }
  a.error =
      "a target starts with camera, render, outlines, environment, objects, lights, materials or strokes, "
      "not " +
      in_quotes(head);
}

// ---------------------------------------------------------------- interpolation

// Slope of component c at key i (value per frame) for bezier easing: the average of the
// secants, zero at the ends and where the key is a peak or a valley, and limited so
// the curve never leaves the range of two neighbouring keys (Fritsch-Carlson).
double auto_slope(const std::vector<KeyDesc>& keys, size_t i, size_t c) {
  if (i == 0 || i + 1 >= keys.size()) return 0.0;
  const double v = keys[i].value[c];
  const double before = (v - keys[i - 1].value[c]) / (keys[i].frame - keys[i - 1].frame);
  const double after = (keys[i + 1].value[c] - v) / (keys[i + 1].frame - keys[i].frame);
  if (before * after <= 0.0) return 0.0;
  const double slope =
      (keys[i + 1].value[c] - keys[i - 1].value[c]) / (keys[i + 1].frame - keys[i - 1].frame);
  const double limit = 3.0 * std::min(std::fabs(before), std::fabs(after));
  return std::copysign(std::min(std::fabs(slope), limit), slope);
}

std::vector<double> value_at(const TrackDesc& track, double frame, bool discrete) {
  const std::vector<KeyDesc>& keys = track.keys;
  if (keys.empty()) return {};
  if (frame <= keys.front().frame) return keys.front().value;
  if (frame >= keys.back().frame) return keys.back().value;
  const auto next = std::upper_bound(keys.begin(), keys.end(), frame,
                                     [](double f, const KeyDesc& k) { return f < k.frame; });
  const size_t i1 = size_t(next - keys.begin()), i0 = i1 - 1;
  const KeyDesc& k0 = keys[i0];
  const KeyDesc& k1 = keys[i1];
  if (discrete || k0.interp == Interpolation::step || k0.value.size() != k1.value.size()) return k0.value;
  const double h = k1.frame - k0.frame;
  const double t = (frame - k0.frame) / h;
  std::vector<double> out(k0.value.size());
  for (size_t c = 0; c < out.size(); ++c) {
    const double a = k0.value[c], b = k1.value[c];
    if (k0.interp == Interpolation::linear) {
      out[c] = a + (b - a) * t;
    } else {
      // Cubic Hermite with the keys' automatic slopes.
      const double m0 = auto_slope(keys, i0, c) * h, m1 = auto_slope(keys, i1, c) * h;
      const double t2 = t * t, t3 = t2 * t;
      out[c] = (2 * t3 - 3 * t2 + 1) * a + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * b + (t3 - t2) * m1;
    }
  }
  return out;
}

bool discrete_kind(ParamKind kind) { return kind == ParamKind::toggle || kind == ParamKind::choice; }

}  // namespace

int key_width(ParamKind kind) {
  switch (kind) {
    case ParamKind::number:
    case ParamKind::integer:
    case ParamKind::toggle:
    case ParamKind::choice:
      return 1;
    case ParamKind::point:
    case ParamKind::direction:
    case ParamKind::vector:
    case ParamKind::color:
    case ParamKind::color_input:
      return 3;
    default:
      return 0;
  }
}

namespace {

std::optional<Param> probe(const SceneDesc& desc, std::string_view path, std::string* error,
                           const NameIndex* names) {
  Access a;
  a.names = names;
  resolve(desc, path, a);
  if (!a.found && error) *error = a.error.empty() ? "cannot resolve " + in_quotes(path) : a.error;
  return a.found;
}

bool write(SceneDesc& desc, std::string_view path, std::span<const double> value, const NameIndex* names) {
  const std::optional<Param> p = probe(desc, path, nullptr, names);
  if (!p || value.size() != size_t(key_width(p->kind))) return false;
  Access a;
  a.op = Access::Op::write;
  a.in = value;
  a.names = names;
  resolve(desc, path, a);
  return a.found.has_value();
}

}  // namespace

std::optional<Param> animation_target(const SceneDesc& desc, std::string_view path, std::string* error) {
  return probe(desc, path, error, nullptr);
}

TargetResolver::TargetResolver(const SceneDesc& desc)
    : desc_(desc), names_(std::make_unique<AnimationNames>(desc)) {}
TargetResolver::~TargetResolver() = default;

std::optional<Param> TargetResolver::target(std::string_view path, std::string* error) const {
  return probe(desc_, path, error, names_.get());
}

bool read_target(const SceneDesc& desc, std::string_view path, std::vector<double>* value) {
  Access a;
  a.op = Access::Op::read;
  a.out = value;
  resolve(desc, path, a);
  return a.found.has_value();
}

bool write_target(SceneDesc& desc, std::string_view path, std::span<const double> value) {
  return write(desc, path, value, nullptr);
}

std::vector<double> track_value(const TrackDesc& track, double frame) {
  return value_at(track, frame, false);
}

void apply_animation(SceneDesc& desc, double frame) {
  if (desc.animation.empty()) return;
  // Keys write values, never names, so the index stays true through the pass.
  const NameIndex names(desc);
  for (const TrackDesc& track : desc.animation) {
    if (track.keys.empty()) continue;
    const std::optional<Param> p = probe(desc, track.target, nullptr, &names);
    if (!p) continue;
    const std::vector<double> value = value_at(track, frame, discrete_kind(p->kind));
    write(desc, track.target, value, &names);
  }
}

SceneDesc scene_at_frame(const SceneDesc& desc, double frame) {
  SceneDesc out = desc;
  apply_animation(out, frame);
  return out;
}

bool animated_between(const SceneDesc& desc, double from, double to) {
  for (const TrackDesc& track : desc.animation) {
    if (track.keys.size() < 2) continue;
    // Constant before the first key and after the last; between, any two keys that
    // differ and whose span meets [from, to] make it move.
    for (size_t i = 0; i + 1 < track.keys.size(); ++i) {
      const KeyDesc& a = track.keys[i];
      const KeyDesc& b = track.keys[i + 1];
      if (b.frame <= from || a.frame >= to) continue;
      if (a.value != b.value) return true;
    }
  }
  return false;
}

std::vector<std::string> check_animation(const SceneDesc& desc) {
  std::vector<std::string> problems;
  if (desc.animation.empty()) return problems;  // the resolver's index of every item is not needed
  // The first track on each target: a later one is reported against it, once, so
  // thousands of tracks on one target cost a line each rather than a line per pair.
  std::unordered_map<std::string_view, size_t> first_on;
  first_on.reserve(desc.animation.size());
  const TargetResolver targets(desc);
  for (size_t t = 0; t < desc.animation.size(); ++t) {
    const TrackDesc& track = desc.animation[t];
    const std::string at = "animation[" + std::to_string(t) + "] (" + in_quotes(track.target) + ")";
    std::string error;
    const std::optional<Param> p = targets.target(track.target, &error);
    if (!p) {
      problems.push_back(at + ": " + error);
      continue;
    }
    if (const auto [first, added] = first_on.emplace(track.target, t); !added)
      problems.push_back(at + ": animation[" + std::to_string(first->second) +
                         "] already animates this target");
    const size_t width = size_t(key_width(p->kind));
    for (size_t k = 0; k < track.keys.size(); ++k) {
      const KeyDesc& key = track.keys[k];
      const std::string key_at = at + ".keys[" + std::to_string(k) + "]";
      if (key.value.size() != width)
        problems.push_back(key_at + ": expected " + (width == 1 ? std::string("one value") : "three values") +
                           " for " + in_quotes(p->name) + ", got " + std::to_string(key.value.size()));
      if (!std::isfinite(key.frame)) problems.push_back(key_at + ": the frame is not a finite number");
      if (k > 0 && !(key.frame > track.keys[k - 1].frame))
        problems.push_back(key_at + ": keys must be in increasing frame order, one per frame; frame " +
                           std::to_string(key.frame) + " follows " + std::to_string(track.keys[k - 1].frame));
    }
  }
  return problems;
}

const TrackDesc* find_track(const SceneDesc& desc, std::string_view path) {
  for (const TrackDesc& track : desc.animation)
    if (track.target == path) return &track;
  return nullptr;
}

bool insert_key(SceneDesc& desc, std::string_view path, double frame, Interpolation interp) {
  std::vector<double> value;
  if (!std::isfinite(frame) || !read_target(desc, path, &value)) return false;
  auto track = std::find_if(desc.animation.begin(), desc.animation.end(),
                            [&](const TrackDesc& t) { return t.target == path; });
  if (track == desc.animation.end()) {
    desc.animation.push_back({std::string(path), {}});
    track = desc.animation.end() - 1;
  }
  auto& keys = track->keys;
  const auto at = std::lower_bound(keys.begin(), keys.end(), frame,
                                   [](const KeyDesc& k, double f) { return k.frame < f; });
  if (at != keys.end() && at->frame == frame) {
    at->value = std::move(value);
  } else {
    keys.insert(at, KeyDesc{frame, std::move(value), interp});
  }
  return true;
}

bool delete_key(SceneDesc& desc, std::string_view path, double frame) {
  for (auto track = desc.animation.begin(); track != desc.animation.end(); ++track) {
    if (track->target != path) continue;
    const auto before = track->keys.size();
    std::erase_if(track->keys, [&](const KeyDesc& k) { return k.frame == frame; });
    if (track->keys.size() == before) return false;
    if (track->keys.empty()) desc.animation.erase(track);
    return true;
  }
  return false;
}

}  // namespace inkray
