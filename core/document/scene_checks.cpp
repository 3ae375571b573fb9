// Document-wide checks. Asset paths are found generically: a walk over every
// struct's parameter table picks out ParamKind::path fields, so a new texture or shape
// type with a file is checked without a change here.
#include "core/document/scene_checks.h"

#include "core/document/animation.h"
#include "core/document/asset_probe.h"

#include "core/document/tagged_variant.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace inkray {
namespace {

namespace fs = std::filesystem;

// Collects ParamKind::path fields, descending into colour inputs' textures.
struct AssetCollector {
  std::string at;
  std::vector<AssetRef>& out;
  AssetKind kind = AssetKind::image;

  template <class T>
  void operator()(const Param& p, const T& field) {
    if constexpr (std::is_same_v<T, std::string>) {
      // An optional file left unset (a toon's ramp image) is no asset: nothing reads it.
      if (p.kind == ParamKind::path && (p.required || !field.empty()))
        out.push_back({child_path(at, p.name), field, kind, p.required});
    } else if constexpr (std::is_same_v<T, ColorInput>) {
      collect_tagged(child_path(at, p.name), field, out);
    } else if constexpr (std::is_same_v<T, std::vector<GraphNodeDesc>>) {
      for (std::size_t i = 0; i < field.size(); ++i)
        collect_tagged(element_path(child_path(at, p.name), i), field[i].data, out);
    }
  }

  template <class Variant>
  static void collect_tagged(const std::string& path, const Variant& value, std::vector<AssetRef>& out) {
    std::visit(
        [&]<class A>(const A& alternative) {
          if constexpr (Tagged<A>) {
            AssetCollector collector{path, out,
                                     std::is_same_v<A, MeshDesc> ? AssetKind::mesh : AssetKind::image};
            visit_params(alternative, collector);
          }
        },
        value);
  }
};

}  // namespace

namespace {

bool in_scope(const std::vector<bool>* section, std::size_t i) { return !section || (*section)[i]; }

void collect_assets(const SceneDesc& scene, const CheckScope* scope, std::vector<AssetRef>& assets) {
  AssetCollector::collect_tagged("environment", scene.environment, assets);
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    if (!in_scope(scope ? &scope->materials : nullptr, i)) continue;
    AssetCollector::collect_tagged(element_path("materials", i), scene.materials[i].data, assets);
  }
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (!in_scope(scope ? &scope->objects : nullptr, i) || !may_name_files(scene.objects[i].shape)) continue;
    AssetCollector::collect_tagged(element_path("objects", i) + ".shape", scene.objects[i].shape, assets);
  }
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    if (!in_scope(scope ? &scope->lights : nullptr, i)) continue;
    AssetCollector::collect_tagged(element_path("lights", i), scene.lights[i].data, assets);
  }
  // An emitter keeps its brush_image while another brush is chosen; only a used one must exist.
  for (std::size_t i = 0; i < scene.strokes.size(); ++i) {
    if (!in_scope(scope ? &scope->strokes : nullptr, i) || scene.strokes[i].brush != BrushKind::image)
      continue;
    AssetCollector collector{element_path("strokes", i), assets, AssetKind::brush};
    visit_params(scene.strokes[i], collector);
  }
}

}  // namespace

std::vector<AssetRef> collect_assets(const SceneDesc& scene) {
  std::vector<AssetRef> assets;
  collect_assets(scene, nullptr, assets);
  return assets;
}

namespace {

void check_assets(const SceneDesc& scene, const fs::path& base_dir, const CheckScope* scope, ErrorLog& log) {
  std::vector<AssetRef> assets;
  collect_assets(scene, scope, assets);
  for (const auto& [at, written, kind, required] : assets) {
    if (written.empty()) {
      // An image texture or mesh the editor has just added, before a file is chosen.
      if (required) log.add_unrenderable(at, "no file given (expected a path relative to the scene file)");
      continue;
    }
    // The OS would see only the part before a NUL, so the file checked would not be the file named.
    if (written.find('\0') != std::string::npos) {
      log.add(at, "expected a file path without NUL characters, got " + in_quotes(written));
      continue;
    }
    const fs::path resolved = base_dir / fs::path(written);
    std::error_code ec;
    const fs::file_status status = fs::status(resolved, ec);
    if (fs::is_regular_file(status)) continue;
    fs::path shown = fs::absolute(resolved, ec);
    shown = ec ? resolved : shown.lexically_normal();
    const std::string problem = fs::exists(status) ? "not a regular file: " : "file not found: ";
    log.add_unrenderable(at, problem + written + " (resolved to " + shown.string() + ")");
  }
}

template <class Item>
void check_unique_names(const SharedList<Item>& items, std::string_view section, std::string_view noun,
                        ErrorLog& log) {
  std::unordered_map<std::string_view, std::size_t> first_use;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].name.empty()) continue;  // reported by the reader as missing or invalid
    const auto [it, inserted] = first_use.emplace(items[i].name, i);
    if (!inserted) {
      log.add_unrenderable(element_path(section, i) + ".name",
                           "duplicate " + std::string(noun) + " name " + in_quotes(items[i].name) +
                               " (also used by " + element_path(section, it->second) + ")");
    }
  }
}

// " (defined: a, b, ...)": the names a reference could have meant.
template <class Item>
std::string defined_names(const SharedList<Item>& items, std::string_view noun) {
  std::unordered_set<std::string_view> names;
  std::string listed;
  for (const Item& item : items) {
    if (item.name.empty() || !names.insert(item.name).second) continue;
    if (names.size() <= 10) listed += (listed.empty() ? "" : ", ") + item.name;
  }
  if (names.empty()) return " (the scene defines no " + std::string(noun) + ")";
  return names.size() > 10 ? " (defined: " + listed + ", ...)" : " (defined: " + listed + ")";
}

template <class Item>
std::unordered_set<std::string_view> name_set(const SharedList<Item>& items) {
  std::unordered_set<std::string_view> names;
  for (const Item& item : items) names.insert(item.name);
  return names;
}

void check_material_references(const SceneDesc& scene, const CheckScope* scope, ErrorLog& log) {
  // The names only once a reference is checked: an edit of the camera or a light pays
  // nothing for them.
  std::optional<std::unordered_set<std::string_view>> names;
  const auto check = [&](const std::string& name, const auto& at) {
    if (name.empty()) return;
    if (!names) names = name_set(scene.materials);
    if (!names->contains(name))
      log.add_unrenderable(
          at(), "no material named " + in_quotes(name) + defined_names(scene.materials, "materials"));
  };
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (!in_scope(scope ? &scope->objects : nullptr, i)) continue;
    check(scene.objects[i].material, [&] { return element_path("objects", i) + ".material"; });
  }
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const auto* mix = std::get_if<MixDesc>(&scene.materials[i].data);
    if (!mix || !in_scope(scope ? &scope->materials : nullptr, i)) continue;
    check(mix->a, [&] { return element_path("materials", i) + ".a"; });
    check(mix->b, [&] { return element_path("materials", i) + ".b"; });
  }
}

// A mix's sides as material indices (the first of a name), -1 where the side is
// not a mix: only mixes can close a cycle.
std::vector<std::array<int, 2>> mix_graph(const SceneDesc& scene) {
  std::unordered_map<std::string_view, int> index;
  for (std::size_t i = 0; i < scene.materials.size(); ++i) index.emplace(scene.materials[i].name, int(i));
  auto mix_named = [&](const std::string& name) {
    const auto it = index.find(name);
    return it != index.end() && std::holds_alternative<MixDesc>(scene.materials[std::size_t(it->second)].data)
               ? it->second
               : -1;
  };
  std::vector<std::array<int, 2>> sides(scene.materials.size(), {-1, -1});
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    if (const auto* mix = std::get_if<MixDesc>(&scene.materials[i].data))
      sides[i] = {mix_named(mix->a), mix_named(mix->b)};
  }
  return sides;
}

// Each cycle is reported once, at the reference that closes it, with the chain
// of names; depth-first search with an explicit stack, as a file may chain
// thousands of mixes.
void check_mix_cycles(const SceneDesc& scene, const CheckScope* scope, ErrorLog& log) {
  // Within a scope (names unchanged) only a changed mix can close a cycle.
  if (scope) {
    bool mix_changed = false;
    for (std::size_t i = 0; i < scene.materials.size() && !mix_changed; ++i)
      mix_changed = scope->materials[i] && std::holds_alternative<MixDesc>(scene.materials[i].data);
    if (!mix_changed) return;
  }
  const std::vector<std::array<int, 2>> sides = mix_graph(scene);
  enum : char { unseen, open, closed };
  std::vector<char> state(sides.size(), unseen);
  struct Frame {
    int node;
    int next_side;
  };
  std::vector<Frame> stack;
  for (std::size_t root = 0; root < sides.size(); ++root) {
    if (state[root] != unseen || !std::holds_alternative<MixDesc>(scene.materials[root].data)) continue;
    stack.push_back({int(root), 0});
    state[root] = open;
    while (!stack.empty()) {
      const int node = stack.back().node;
      const int side = stack.back().next_side++;
      if (side == 2) {
        state[std::size_t(node)] = closed;
        stack.pop_back();
        continue;
      }
      const int target = sides[std::size_t(node)][std::size_t(side)];
      if (target < 0) continue;
      if (state[std::size_t(target)] == unseen) {
        state[std::size_t(target)] = open;
        stack.push_back({target, 0});
        continue;
      }
      if (state[std::size_t(target)] != open) continue;
      const std::string at = element_path("materials", std::size_t(node)) + (side == 0 ? ".a" : ".b");
      if (target == node) {
        log.add_unrenderable(
            at, "mix " + in_quotes(scene.materials[std::size_t(node)].name) + " refers to itself");
        continue;
      }
      std::string chain;
      auto from = std::find_if(stack.begin(), stack.end(), [&](const Frame& f) { return f.node == target; });
      for (; from != stack.end(); ++from)
        chain += in_quotes(scene.materials[std::size_t(from->node)].name) + " -> ";
      log.add_unrenderable(at, "mixes refer to each other in a cycle: " + chain +
                                   in_quotes(scene.materials[std::size_t(target)].name));
    }
  }
}

std::string shown(float x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

void check_strokes(const SceneDesc& scene, const CheckScope* scope, ErrorLog& log) {
  // The object names only when some emitter is checked: a scene of many objects
  // and no strokes does not pay for them.
  std::string known;
  std::unordered_set<std::string_view> objects;
  bool listed = false;
  for (std::size_t i = 0; i < scene.strokes.size(); ++i) {
    if (!in_scope(scope ? &scope->strokes : nullptr, i)) continue;
    if (!std::exchange(listed, true)) {
      known = defined_names(scene.objects, "objects");
      objects = name_set(scene.objects);
    }
    const StrokeEmitterDesc& e = scene.strokes[i];
    const std::string at = element_path("strokes", i);
    if (!e.object.empty() && !objects.contains(e.object))
      log.add_unrenderable(at + ".object", "no object named " + in_quotes(e.object) + known);
    if (e.brush == BrushKind::image && e.brush_image.empty())
      log.add_unrenderable(at + ".brush_image", "required when brush is \"image\"");
    if (e.width_min > e.width_max)
      log.add_unrenderable(at + ".width_min", "must not exceed width_max (" + shown(e.width_min) + " > " +
                                                  shown(e.width_max) + ")");
    if (e.length_min > e.length_max)
      log.add_unrenderable(at + ".length_min", "must not exceed length_max (" + shown(e.length_min) + " > " +
                                                   shown(e.length_max) + ")");
  }
  // One budget across emitters: each may be modest and all of them together not.
  long long vertices = 0;
  for (std::size_t i = 0; i < scene.strokes.size(); ++i) {
    vertices += stroke_vertex_count(scene.strokes[i]);
    if (vertices > kMaxStrokeVertices) {
      log.add_unrenderable(
          element_path("strokes", i) + ".count",
          "the strokes up to this emitter need " + std::to_string(vertices) +
              " vertices (count x 2 x (segments + 1), summed over emitters); a scene may have at most " +
              std::to_string(kMaxStrokeVertices) + " (about 6 GiB of memory)");
      break;
    }
  }
}

template <class Item>
void name_items(SharedList<Item>& items, std::string_view prefix) {
  std::unordered_set<std::string> taken;
  for (const Item& item : items) taken.insert(item.name);
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (!items[i].name.empty()) continue;
    const std::string base = std::string(prefix) + "_" + std::to_string(i);
    std::string name = base;
    for (int k = 1; taken.contains(name); ++k) name = base + "_" + std::to_string(k);
    taken.insert(name);
    items[i].name = std::move(name);
  }
}

}  // namespace

void name_unnamed(SceneDesc& scene) {
  name_items(scene.objects, "object");
  name_items(scene.lights, "light");
  name_items(scene.strokes, "strokes");
}

// Geometry that has no direction: a spot aimed at its own position, a camera
// looking at its own eye, an up vector along the view direction.
void check_degenerate_directions(const SceneDesc& scene, const CheckScope* scope, ErrorLog& log) {
  const CameraDesc& c = scene.camera;
  const Vec3 view = c.look_at - c.look_from;
  if (glm::length(view) == 0.f) {
    log.add_unrenderable("camera.look_at", "must differ from camera.look_from (the view has no direction)");
  } else if (glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) < 1e-6f) {
    log.add_unrenderable("camera.up", "must not be parallel to the view direction (look_at - look_from)");
  }
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const auto* spot = std::get_if<SpotLightDesc>(&scene.lights[i].data);
    if (!in_scope(scope ? &scope->lights : nullptr, i)) continue;
    if (spot && glm::length(spot->target - spot->position) == 0.f)
      log.add_unrenderable("lights[" + std::to_string(i) + "].target",
                           "must differ from the spot light's position");
  }
}

bool CheckScope::empty() const {
  for (const std::vector<bool>* section : {&materials, &objects, &lights, &strokes})
    if (std::find(section->begin(), section->end(), true) != section->end()) return false;
  return true;
}

namespace {

template <class Item>
bool same_names(const SharedList<Item>& a, const SharedList<Item>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!a.shares(b, i) && a[i].name != b[i].name) return false;
  return true;
}

template <class Item>
std::vector<bool> changed(const SharedList<Item>& before, const SharedList<Item>& after) {
  std::vector<bool> out(after.size());
  for (std::size_t i = 0; i < after.size(); ++i)
    out[i] = !after.shares(before, i) && !(before[i] == after[i]);
  return out;
}

}  // namespace

bool same_names(const SceneDesc& a, const SceneDesc& b) {
  return a.base_dir == b.base_dir && same_names(a.materials, b.materials) &&
         same_names(a.objects, b.objects) && same_names(a.lights, b.lights) &&
         same_names(a.strokes, b.strokes);
}

CheckScope changed_items(const SceneDesc& before, const SceneDesc& after) {
  return {changed(before.materials, after.materials), changed(before.objects, after.objects),
          changed(before.lights, after.lights), changed(before.strokes, after.strokes)};
}

void check_scene(const SceneDesc& scene, const fs::path& base_dir, ErrorLog& log, const CheckScope* scope) {
  const long long pixels = static_cast<long long>(scene.render.width) * scene.render.height;
  if (pixels > kMaxImagePixels) {
    log.add_unrenderable("render", "image size " + std::to_string(scene.render.width) + " x " +
                                       std::to_string(scene.render.height) + " = " + std::to_string(pixels) +
                                       " pixels is over the limit of " + std::to_string(kMaxImagePixels) +
                                       " (8192 x 8192)");
  }
  if (!scope) {  // a scope's documents have the names of one already checked
    check_unique_names(scene.materials, "materials", "material", log);
    check_unique_names(scene.objects, "objects", "object", log);
    check_unique_names(scene.lights, "lights", "light", log);
    check_unique_names(scene.strokes, "strokes", "stroke emitter", log);
  }
  check_material_references(scene, scope, log);
  check_mix_cycles(scene, scope, log);
  check_strokes(scene, scope, log);
  check_assets(scene, base_dir, scope, log);
  check_degenerate_directions(scene, scope, log);
  if (scene.render.frame_end < scene.render.frame_start)
    log.add_unrenderable("render.frame_end", "must not be before render.frame_start (" +
                                                 std::to_string(scene.render.frame_start) + ")");
  if (scene.render.shutter_close < scene.render.shutter_open)
    log.add_unrenderable("render.shutter_close", "must not be before render.shutter_open");
  for (const std::string& problem : check_animation(scene)) log.add_unrenderable("", problem);
}

}  // namespace inkray
