// Document-wide checks. Asset paths are found generically: a visitor over every
// struct's visit_params picks out ParamKind::path fields, so a new texture or shape
// type with a file is checked without a change here.
#include "core/scene/scene_checks.h"

#include "core/scene/tagged_variant.h"

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

struct AssetRef {
  std::string at;       // JSON path of the key
  std::string written;  // the path as written
};

// Collects ParamKind::path fields, descending into colour inputs' textures.
struct AssetCollector {
  std::string at;
  std::vector<AssetRef>& out;

  template <class T>
  void operator()(const Param& p, T& field) {
    if constexpr (std::is_same_v<T, std::string>) {
      if (p.kind == ParamKind::path) out.push_back({child_path(at, p.name), field});
    } else if constexpr (std::is_same_v<T, ColorInput>) {
      collect_tagged(child_path(at, p.name), field, out);
    }
  }

  template <class Variant>
  static void collect_tagged(const std::string& path, const Variant& value, std::vector<AssetRef>& out) {
    std::visit(
        [&]<class A>(const A& alternative) {
          if constexpr (Tagged<A>) {
            A copy = alternative;  // visit_params takes a mutable struct
            AssetCollector collector{path, out};
            visit_params(copy, collector);
          }
        },
        value);
  }
};

std::vector<AssetRef> collect_assets(const SceneDesc& scene) {
  std::vector<AssetRef> assets;
  AssetCollector::collect_tagged("environment", scene.environment, assets);
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    AssetCollector::collect_tagged(element_path("materials", i), scene.materials[i].data, assets);
  }
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    AssetCollector::collect_tagged(element_path("objects", i) + ".shape", scene.objects[i].shape, assets);
  }
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    AssetCollector::collect_tagged(element_path("lights", i), scene.lights[i].data, assets);
  }
  return assets;
}

void check_assets(const SceneDesc& scene, const fs::path& base_dir, ErrorLog& log) {
  for (const auto& [at, written] : collect_assets(scene)) {
    if (written.empty()) continue;  // reported by the reader as a missing or invalid value
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
    log.add(at, problem + written + " (resolved to " + shown.string() + ")");
  }
}

template <class Item>
void check_unique_names(const std::vector<Item>& items, std::string_view section, std::string_view noun,
                        ErrorLog& log) {
  std::unordered_map<std::string_view, std::size_t> first_use;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].name.empty()) continue;  // reported by the reader as missing or invalid
    const auto [it, inserted] = first_use.emplace(items[i].name, i);
    if (!inserted) {
      log.add(element_path(section, i) + ".name", "duplicate " + std::string(noun) + " name " +
                                                      in_quotes(items[i].name) + " (also used by " +
                                                      element_path(section, it->second) + ")");
    }
  }
}

void check_material_references(const SceneDesc& scene, ErrorLog& log) {
  std::unordered_set<std::string_view> names;
  std::string listed;
  for (const MaterialDesc& m : scene.materials) {
    if (m.name.empty() || !names.insert(m.name).second) continue;
    if (names.size() <= 10) listed += (listed.empty() ? "" : ", ") + m.name;
  }
  const std::string known = names.empty()       ? " (the scene defines no materials)"
                            : names.size() > 10 ? " (defined: " + listed + ", ...)"
                                                : " (defined: " + listed + ")";
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const std::string& name = scene.objects[i].material;
    if (!name.empty() && !names.contains(name)) {
      log.add(element_path("objects", i) + ".material", "no material named " + in_quotes(name) + known);
    }
  }
}

template <class Item>
void name_items(std::vector<Item>& items, std::string_view prefix) {
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
}

// Geometry that has no direction: a spot aimed at its own position, a camera
// looking at its own eye, an up vector along the view direction.
void check_degenerate_directions(const SceneDesc& scene, ErrorLog& log) {
  const CameraDesc& c = scene.camera;
  const Vec3 view = c.look_at - c.look_from;
  if (glm::length(view) == 0.f) {
    log.add("camera.look_at", "must differ from camera.look_from (the view has no direction)");
  } else if (glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) < 1e-6f) {
    log.add("camera.up", "must not be parallel to the view direction (look_at - look_from)");
  }
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const auto* spot = std::get_if<SpotLightDesc>(&scene.lights[i].data);
    if (spot && glm::length(spot->target - spot->position) == 0.f)
      log.add("lights[" + std::to_string(i) + "].target", "must differ from the spot light's position");
  }
}

void check_scene(const SceneDesc& scene, const fs::path& base_dir, ErrorLog& log) {
  const long long pixels = static_cast<long long>(scene.render.width) * scene.render.height;
  if (pixels > kMaxImagePixels) {
    log.add("render", "image size " + std::to_string(scene.render.width) + " x " +
                          std::to_string(scene.render.height) + " = " + std::to_string(pixels) +
                          " pixels is over the limit of " + std::to_string(kMaxImagePixels) +
                          " (8192 x 8192)");
  }
  check_unique_names(scene.materials, "materials", "material", log);
  check_unique_names(scene.objects, "objects", "object", log);
  check_unique_names(scene.lights, "lights", "light", log);
  check_material_references(scene, log);
  check_assets(scene, base_dir, log);
  check_degenerate_directions(scene, log);
}

}  // namespace inkray
