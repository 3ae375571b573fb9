// Stroke emitters -> ribbon meshes with brush alpha, built before the scene's
// BVH is committed so the strokes are traced like any other surface.
#include "core/scene/compile_strokes.h"

#include "core/npr/strokes/brush.h"
#include "core/npr/strokes/stroke_color.h"
#include "core/npr/strokes/stroke_mesh.h"
#include "core/npr/strokes/stroke_placement.h"

#include <optional>

namespace inkray {
namespace {

struct BuiltStrokes {
  const StrokeEmitterDesc* emitter = nullptr;
  uint32_t base_object = 0;
  StrokeGeometry geometry;
  std::shared_ptr<AlphaMask> mask;
};

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
std::optional<BuiltStrokes> build_emitter(const SceneDesc& desc, const RenderScene& scene, size_t index,
                                          std::vector<std::string>& errors) {
  const StrokeEmitterDesc& e = desc.strokes[index];
  const std::string where = "strokes[" + std::to_string(index) + "] \"" + e.name + "\": ";
  if (e.count <= 0) return std::nullopt;
  const auto object = compiled_object(scene, e.object);
  if (!object) {
    // A hidden object hides its strokes too; an unknown one is an error.
    if (!described_object(desc, e.object)) errors.push_back(where + "no object named \"" + e.object + "\"");
    return std::nullopt;
  }
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
  const std::vector<SurfacePoint> roots = place_roots(*surface, size_t(e.count), uint32_t(e.seed));
  const std::vector<Color> colors = stroke_colors(scene.materials, scene.objects[*object].material, roots, e);
  BuiltStrokes built{&e, *object, build_stroke_mesh(*surface, roots, colors, e), std::move(mask)};
  built.mask->triangles_per_item = 2 * uint32_t(std::max(e.segments, 1));
  // Every stroke vertex lies within max_lift of the surface; the margin covers
  // the surface curving away from a ribbon's plane beside it.
  built.mask->layer_thickness = 1.5f * built.geometry.max_lift;
  return built;
}

}  // namespace

void compile_strokes(const SceneDesc& desc, RenderScene& scene, std::vector<std::string>& errors) {
  if (desc.strokes.empty()) return;
  // Build everything before adding any: the surfaces refer to the base objects'
  // meshes, which adding shapes may move.
  std::vector<BuiltStrokes> built;
  for (size_t i = 0; i < desc.strokes.size(); ++i)
    if (auto b = build_emitter(desc, scene, i, errors)) built.push_back(std::move(*b));
  if (!errors.empty()) return;
  for (BuiltStrokes& b : built) {
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
    scene.geometry.add(std::move(b.geometry.mesh), std::move(b.mask));
  }
}

}  // namespace inkray
