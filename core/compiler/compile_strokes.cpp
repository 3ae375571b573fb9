// Stroke emitters -> ribbon meshes with brush alpha, built before the scene's
// BVH is committed so the strokes are traced like any other surface.
#include "core/compiler/compile_strokes.h"

#include "core/npr/strokes/brush.h"
#include "core/npr/strokes/stroke_color.h"
#include "core/npr/strokes/stroke_mesh.h"
#include "core/npr/strokes/stroke_placement.h"
#include "core/document/json_write.h"

#include <map>
#include <mutex>
#include <optional>

namespace inkray {
namespace {

// What an emitter's strokes are, whatever they are painted with: placement,
// ribbons and brush depend only on the emitter, its object and the scene's
// folder, so they are kept between compiles and an edit elsewhere in the
// document (a material, a light, the outlines) does not regrow them (DESIGN
// principle 3). Colours are recomputed on every compile.
struct StrokeShape {
  std::vector<SurfacePoint> roots;
  StrokeGeometry geometry;
  std::shared_ptr<const AlphaMask> mask;
};

// The shapes the last compile used, by key. Compiles on several threads (the
// viewport and an export) share it under the lock; keeping only the last
// compile's entries bounds the memory to one scene's strokes.
class StrokeShapeCache {
 public:
  std::shared_ptr<const StrokeShape> find(const std::string& key) {
    const std::lock_guard lock(mutex_);
    const auto it = shapes_.find(key);
    return it == shapes_.end() ? nullptr : it->second;
  }
  void keep_only(std::map<std::string, std::shared_ptr<const StrokeShape>> used) {
    const std::lock_guard lock(mutex_);
    shapes_ = std::move(used);
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const StrokeShape>> shapes_;
};

StrokeShapeCache& shape_cache() {
  static StrokeShapeCache cache;
  return cache;
}

struct BuiltStrokes {
  const StrokeEmitterDesc* emitter = nullptr;
  uint32_t base_object = 0;
  std::string key;
  std::shared_ptr<const StrokeShape> shape;
  std::vector<Color> colors;
};

// Everything a StrokeShape depends on, as text.
std::string shape_key(const nlohmann::ordered_json& doc, const SceneDesc& desc, size_t emitter,
                      uint32_t object_source) {
  return desc.base_dir.string() + "\n" + doc["strokes"][emitter].dump() + "\n" +
         doc["objects"][object_source].dump();
}

std::optional<uint32_t> compiled_object(const RenderScene& scene, const std::string& name) {
  for (uint32_t o = 0; o < scene.objects.size(); ++o)
    if (scene.objects[o].name == name) return o;
  return std::nullopt;
}

bool described_object(const SceneDesc& desc, const std::string& name) {
  for (const ObjectDesc& o : desc.objects)
    if (o.name == name) return true;
  return false;
}

// Builds one emitter's strokes; nullopt when there is nothing to build or on an
// error (appended to errors).
std::optional<BuiltStrokes> build_emitter(const SceneDesc& desc, const nlohmann::ordered_json& doc,
                                          const RenderScene& scene, size_t index, std::vector<std::string>& errors,
                                          const Cancel& cancel) {
  const StrokeEmitterDesc& e = desc.strokes[index];
  const std::string where = "strokes[" + std::to_string(index) + "] \"" + e.name + "\": ";
  if (e.count <= 0) return std::nullopt;
  const auto object = compiled_object(scene, e.object);
  if (!object) {
    // A hidden object hides its strokes too; an unknown one is an error.
    if (!described_object(desc, e.object)) errors.push_back(where + "no object named \"" + e.object + "\"");
    return std::nullopt;
  }
  BuiltStrokes built{&e, *object, shape_key(doc, desc, index, scene.objects[*object].source), nullptr, {}};
  built.shape = shape_cache().find(built.key);
  if (!built.shape) {
    std::string error;
    const auto surface = StrokeSurface::from_shape(scene.geometry.shape(*object), &error);
    if (!surface) {
      errors.push_back(where + "object \"" + e.object + "\": " + error);
      return std::nullopt;
    }
    auto mask = make_brush_mask(e, desc.base_dir, &error);
    if (!mask) {
      errors.push_back(where + error);
      return std::nullopt;
    }
    auto shape = std::make_shared<StrokeShape>();
    shape->roots = place_roots(*surface, size_t(e.count), uint32_t(e.seed), nullptr, cancel);
    if (cancel.requested()) return std::nullopt;
    // Colours are painted in below; the ribbons are built white.
    const std::vector<Color> white(shape->roots.size(), Color(1.f));
    shape->geometry = build_stroke_mesh(*surface, shape->roots, white, e, cancel);
    if (cancel.requested()) return std::nullopt;  // unfinished ribbons are never cached
    mask->triangles_per_item = 2 * uint32_t(std::max(e.segments, 1));
    // Every stroke vertex lies within max_lift of the surface; the margin covers
    // the surface curving away from a ribbon's plane beside it.
    mask->layer_thickness = 1.5f * shape->geometry.max_lift;
    shape->mask = std::move(mask);
    built.shape = std::move(shape);
  }
  built.colors = stroke_colors(scene.materials, scene.objects[*object].material, built.shape->roots, e);
  return built;
}

}  // namespace

void compile_strokes(const SceneDesc& desc, RenderScene& scene, std::vector<std::string>& errors,
                     const Cancel& cancel) {
  if (desc.strokes.empty()) return;
  const nlohmann::ordered_json doc = write_scene_document(desc);
  // Build everything before adding any: the surfaces refer to the base objects'
  // meshes, which adding shapes may move.
  std::vector<BuiltStrokes> built;
  for (size_t i = 0; i < desc.strokes.size() && !cancel.requested(); ++i)
    if (auto b = build_emitter(desc, doc, scene, i, errors, cancel)) built.push_back(std::move(*b));
  if (!errors.empty() || cancel.requested()) return;
  std::map<std::string, std::shared_ptr<const StrokeShape>> used;
  for (BuiltStrokes& b : built) {
    used[b.key] = b.shape;
    const uint32_t material = uint32_t(scene.materials.size());
    scene.materials.push_back(DiffuseMaterial{ConstantTexture{Color(1.f)}});
    scene.material_names.push_back(b.emitter->name + ".strokes");
    // Copy the base object's record so whatever else it carries (its outline
    // overrides) applies to its strokes too.
    RenderObject object = scene.objects[b.base_object];
    object.name = b.emitter->name;
    object.material = material;
    object.light = -1;
    scene.objects.push_back(std::move(object));
    // Stroke i owns the same number of consecutive vertices (stroke_mesh.h).
    TriangleMesh mesh = b.shape->geometry.mesh;
    const size_t per_stroke = b.colors.empty() ? 0 : mesh.colors.size() / b.colors.size();
    for (size_t i = 0; i < b.colors.size(); ++i)
      std::fill_n(mesh.colors.begin() + std::ptrdiff_t(i * per_stroke), per_stroke, b.colors[i]);
    scene.geometry.add(std::move(mesh), b.shape->mask);
  }
  shape_cache().keep_only(std::move(used));
}

}  // namespace inkray
