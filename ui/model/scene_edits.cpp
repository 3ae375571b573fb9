#include "ui/model/scene_edits.h"

#include "core/compiler/compile_objects.h"
#include "core/document/animation_edit.h"
#include "core/geometry/obj_loader.h"
#include "ui/model/placement.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <vector>

namespace inkray {
namespace {

constexpr std::string_view kDefaultMaterial = "default";

template <class List>
bool name_taken(const List& items, std::string_view name) {
  return std::any_of(items.begin(), items.end(), [&](const auto& item) { return item.name == name; });
}

bool name_taken(const SceneDesc& scene, ItemKind kind, std::string_view name) {
  switch (kind) {
    case ItemKind::object:
      return name_taken(scene.objects, name);
    case ItemKind::light:
      return name_taken(scene.lights, name);
    case ItemKind::material:
      return name_taken(scene.materials, name);
    case ItemKind::emitter:
      return name_taken(scene.strokes, name);
    case ItemKind::line_set:
      return name_taken(scene.outlines.sets, name);
    default:
      return false;
  }
}

// Objects need a material; new ones share one neutral grey.
std::string ensure_default_material(SceneDesc& scene) {
  if (!name_taken(scene.materials, kDefaultMaterial)) {
    scene.materials.push_back({std::string(kDefaultMaterial), DiffuseDesc{Color(0.7f)}, {}});
  }
  return std::string(kDefaultMaterial);
}

Selection add_object(SceneDesc& scene, std::string_view base, ShapeVariant shape, TransformDesc transform) {
  ObjectDesc object;
  object.name = unique_name(scene, ItemKind::object, base);
  object.shape = std::move(shape);
  object.transform = std::move(transform);
  object.material = ensure_default_material(scene);
  scene.objects.push_back(std::move(object));
  return {ItemKind::object, int(scene.objects.size()) - 1};
}

// Objects, lights, materials, emitters and line sets: entries of a list, each under a name of its own.
bool is_named(ItemKind kind) {
  return kind == ItemKind::object || kind == ItemKind::light || kind == ItemKind::material ||
         kind == ItemKind::emitter || kind == ItemKind::line_set;
}

// The section of the document an item is in, as animation paths name it: the list a named
// item is listed in, or the singleton itself.
std::string_view section_of(ItemKind kind) {
  switch (kind) {
    case ItemKind::camera:
      return "camera";
    case ItemKind::render:
      return "render";
    case ItemKind::environment:
      return "environment";
    case ItemKind::outlines:
      return "outlines";
    case ItemKind::object:
      return "objects";
    case ItemKind::light:
      return "lights";
    case ItemKind::material:
      return "materials";
    case ItemKind::emitter:
      return "strokes";
    case ItemKind::line_set:
      return "outlines/sets";
    case ItemKind::none:
      break;
  }
  return {};
}

template <class List>
Selection duplicate_in(SceneDesc& scene, List& items, ItemKind kind, int index) {
  auto copy = items[size_t(index)];
  copy.name = unique_name(scene, kind, copy.name);
  const std::string_view section = section_of(kind);
  copy_tracks(scene, entry_path(section, items[size_t(index)].name), entry_path(section, copy.name));
  items.insert(items.begin() + index + 1, std::move(copy));
  return {kind, index + 1};
}

}  // namespace

std::string unique_name(const SceneDesc& scene, ItemKind kind, std::string_view base) {
  // A copy of "sphere.2" is "sphere.3", not "sphere.2.1".
  std::string stem(base);
  const size_t dot = stem.rfind('.');
  if (dot != std::string::npos && dot + 1 < stem.size() &&
      std::all_of(stem.begin() + long(dot) + 1, stem.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    stem.resize(dot);
  }
  if (stem.empty()) stem = "item";
  if (!name_taken(scene, kind, stem)) return stem;
  for (int i = 1;; ++i) {
    std::string candidate = stem + "." + std::to_string(i);
    if (!name_taken(scene, kind, candidate)) return candidate;
  }
}

Selection add_shape(SceneDesc& scene, NewShape shape) {
  // Shapes are built about their local origin and moved by their transform, so the
  // gizmo's pivot and the object's origin coincide.
  const Placement at = place_in_view(scene);
  // Each fits the placement's sphere: the box by its corners, the quad by its own.
  const float r = 0.5f * at.size;
  TransformDesc transform;
  transform.translate = at.center;
  switch (shape) {
    case NewShape::sphere:
      return add_object(scene, "sphere", SphereDesc{Point3(0.f), r}, transform);
    case NewShape::quad: {
      const float h = r / std::sqrt(2.f);
      const QuadDesc quad{Point3(-h, 0.f, h), Vec3(2.f * h, 0.f, 0.f), Vec3(0.f, 0.f, -2.f * h)};
      return add_object(scene, "quad", quad, transform);
    }
    case NewShape::box: {
      const float h = r / std::sqrt(3.f);
      return add_object(scene, "box", BoxDesc{Point3(-h), Point3(h)}, transform);
    }
  }
  return {};
}

Selection add_mesh(SceneDesc& scene, const std::string& obj_path, bool keep_native_size) {
  std::filesystem::path p(obj_path);
  std::string stored = obj_path;
  if (!scene.base_dir.empty() && p.is_absolute()) {
    // Relative to the scene file, so the document can move with its assets.
    std::error_code ec;
    const std::filesystem::path rel = std::filesystem::relative(p, scene.base_dir, ec);
    if (!ec && !rel.empty()) stored = rel.generic_string();
  }
  TransformDesc transform;
  if (!keep_native_size) {
    const Placement at = place_in_view(scene, kNewMeshFraction);
    std::string error;
    const auto mesh = load_obj(p.is_absolute() || scene.base_dir.empty() ? p : scene.base_dir / p, &error);
    if (mesh && !mesh->positions.empty()) {
      Point3 lo = mesh->positions[0], hi = lo;
      for (const Point3& v : mesh->positions) lo = glm::min(lo, v), hi = glm::max(hi, v);
      transform = fit_bounds(lo, hi, at);
    } else {
      transform.translate = at.center;
    }
  }
  const std::string stem = p.stem().string();
  return add_object(scene, stem.empty() ? "mesh" : stem, MeshDesc{stored}, transform);
}

Selection add_point_light(SceneDesc& scene) {
  LightDesc light;
  light.name = unique_name(scene, ItemKind::light, "light");
  // Above the camera's target, as bright there as the first default light (10 at 3
  // units) was, so a scene in millimetres gets a light that shows.
  const CameraDesc& c = scene.camera;
  const float distance = glm::length(c.look_at - c.look_from);
  const Vec3 forward = distance > 0.f ? (c.look_at - c.look_from) / distance : Vec3(0.f, 0.f, -1.f);
  Vec3 up = c.up - forward * glm::dot(c.up, forward);
  up = glm::length(up) > 1e-6f ? glm::normalize(up) : Vec3(0.f, 1.f, 0.f);
  const float lift = 0.3f * visible_height(c, distance);
  const float intensity = 10.f * (lift / 3.f) * (lift / 3.f);
  light.data = PointLightDesc{c.look_at + up * lift, Color(1.f), std::max(intensity, 1e-6f)};
  scene.lights.push_back(std::move(light));
  return {ItemKind::light, int(scene.lights.size()) - 1};
}

Selection add_stroke_emitter(SceneDesc& scene, const std::string& object) {
  StrokeEmitterDesc emitter;
  emitter.name = unique_name(scene, ItemKind::emitter, "strokes");
  emitter.object = object;
  scene.strokes.push_back(std::move(emitter));
  return {ItemKind::emitter, int(scene.strokes.size()) - 1};
}

Selection add_material(SceneDesc& scene) {
  scene.materials.push_back({unique_name(scene, ItemKind::material, "material"), DiffuseDesc{}, {}});
  return {ItemKind::material, int(scene.materials.size()) - 1};
}

Selection duplicate_item(SceneDesc& scene, const Selection& item) {
  if (!is_valid(scene, item)) return {};
  switch (item.kind) {
    case ItemKind::object:
      return duplicate_in(scene, scene.objects, item.kind, item.index);
    case ItemKind::light:
      return duplicate_in(scene, scene.lights, item.kind, item.index);
    case ItemKind::material:
      return duplicate_in(scene, scene.materials, item.kind, item.index);
    case ItemKind::emitter:
      return duplicate_in(scene, scene.strokes, item.kind, item.index);
    case ItemKind::line_set:
      return duplicate_in(scene, scene.outlines.sets, item.kind, item.index);
    default:
      return {};
  }
}

bool delete_item(SceneDesc& scene, const Selection& item) {
  if (!is_valid(scene, item)) return false;
  const std::string tracks = key_path(scene, item);
  switch (item.kind) {
    case ItemKind::object: {
      const std::string name = scene.objects[size_t(item.index)].name;
      scene.objects.erase(scene.objects.begin() + item.index);
      for (const StrokeEmitterDesc& e : scene.strokes)
        if (e.object == name) delete_tracks(scene, entry_path("strokes", e.name));
      scene.strokes.erase_if([&](const StrokeEmitterDesc& e) { return e.object == name; });
      break;
    }
    case ItemKind::light:
      scene.lights.erase(scene.lights.begin() + item.index);
      break;
    case ItemKind::emitter:
      scene.strokes.erase(scene.strokes.begin() + item.index);
      break;
    case ItemKind::line_set:
      scene.outlines.sets.erase(scene.outlines.sets.begin() + item.index);
      break;
    case ItemKind::material: {
      const std::string& name = scene.materials[size_t(item.index)].name;
      const bool used = std::any_of(scene.objects.begin(), scene.objects.end(),
                                    [&](const ObjectDesc& o) { return o.material == name; });
      if (used) return false;  // objects would point at nothing
      scene.materials.erase(scene.materials.begin() + item.index);
      break;
    }
    default:
      return false;
  }
  delete_tracks(scene, tracks);
  return true;
}

bool rename_item(SceneDesc& scene, const Selection& item, const std::string& name) {
  if (!is_valid(scene, item) || name.empty() || name_taken(scene, item.kind, name)) return false;
  if (!is_named(item.kind)) return false;
  rename_tracks(scene, key_path(scene, item), entry_path(section_of(item.kind), name));
  switch (item.kind) {
    case ItemKind::object: {
      const std::string old = scene.objects[size_t(item.index)].name;
      scene.strokes.update_if([&](const StrokeEmitterDesc& e) { return e.object == old; },
                              [&](StrokeEmitterDesc& e) { e.object = name; });
      scene.objects[size_t(item.index)].name = name;
      return true;
    }
    case ItemKind::material: {
      const std::string old = scene.materials[size_t(item.index)].name;
      scene.objects.update_if([&](const ObjectDesc& o) { return o.material == old; },
                              [&](ObjectDesc& o) { o.material = name; });
      const auto names_old = [&](const MaterialDesc& m) {
        const auto* mix = std::get_if<MixDesc>(&m.data);
        return mix && (mix->a == old || mix->b == old);
      };
      scene.materials.update_if(names_old, [&](MaterialDesc& m) {
        auto& mix = std::get<MixDesc>(m.data);
        if (mix.a == old) mix.a = name;
        if (mix.b == old) mix.b = name;
      });
      scene.materials[size_t(item.index)].name = name;
      return true;
    }
    case ItemKind::light:
      scene.lights[size_t(item.index)].name = name;
      return true;
    case ItemKind::emitter:
      scene.strokes[size_t(item.index)].name = name;
      return true;
    case ItemKind::line_set:
      scene.outlines.sets[size_t(item.index)].name = name;
      return true;
    default:
      return false;
  }
}

std::string key_path(const SceneDesc& scene, const Selection& item, std::string_view param) {
  const std::string_view section = section_of(item.kind);
  if (!is_valid(scene, item) || section.empty()) return {};
  std::string path =
      is_named(item.kind) ? entry_path(section, item_name(scene, item)) : std::string(section) + "/";
  for (char c : param) path += c == '.' ? '/' : c;
  return path;
}

bool set_visible(SceneDesc& scene, const Selection& item, bool visible) {
  if (item.kind != ItemKind::object || !is_valid(scene, item)) return false;
  scene.objects[size_t(item.index)].visible = visible;
  return true;
}

void local_bounds(const ObjectDesc& object, Point3* lo, Point3* hi) {
  *lo = Point3(-1.f), *hi = Point3(1.f);  // meshes: their extent is in the OBJ file
  std::visit(
      [&](const auto& shape) {
        using T = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<T, SphereDesc>) {
          *lo = shape.center - Vec3(shape.radius);
          *hi = shape.center + Vec3(shape.radius);
        } else if constexpr (std::is_same_v<T, QuadDesc>) {
          const Point3 pts[4] = {shape.corner, shape.corner + shape.edge_u, shape.corner + shape.edge_v,
                                 shape.corner + shape.edge_u + shape.edge_v};
          *lo = *hi = pts[0];
          for (const Point3& p : pts) *lo = glm::min(*lo, p), *hi = glm::max(*hi, p);
        } else if constexpr (std::is_same_v<T, BoxDesc>) {
          *lo = glm::min(shape.min, shape.max);
          *hi = glm::max(shape.min, shape.max);
        }
      },
      object.shape);
}

void object_box(const ObjectDesc& object, Point3* lo, Point3* hi) {
  Point3 a, b;
  local_bounds(object, &a, &b);
  const Transform t = transform_from_desc(object.transform);
  *lo = Point3(std::numeric_limits<float>::max());
  *hi = Point3(-std::numeric_limits<float>::max());
  for (int i = 0; i < 8; ++i) {
    const Point3 p = t.point(Point3(i & 1 ? b.x : a.x, i & 2 ? b.y : a.y, i & 4 ? b.z : a.z));
    *lo = glm::min(*lo, p);
    *hi = glm::max(*hi, p);
  }
}

void object_bounds(const ObjectDesc& object, Point3* center, float* radius) {
  Point3 lo, hi;
  object_box(object, &lo, &hi);
  *center = 0.5f * (lo + hi);
  *radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
}

}  // namespace inkray
