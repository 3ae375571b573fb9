// Stroke emitters -> ribbon meshes with brush alpha, built before the scene's
// BVH is committed so the strokes are traced like any other surface.
#include "core/compiler/compile_strokes.h"

#include "core/compiler/compile_materials.h"
#include "core/npr/strokes/brush.h"
#include "core/npr/strokes/stroke_color.h"
#include "core/npr/strokes/stroke_mesh.h"
#include "core/npr/strokes/stroke_placement.h"
#include "core/document/param_key.h"

#include <algorithm>
#include <optional>

namespace inkray {
namespace {

// What an emitter's strokes are, whatever they are painted with and whatever brush
// paints them: placement and ribbons depend only on the emitter's shape parameters,
// its object's shape and placement and the scene's folder, so they are kept in the
// asset cache and an edit elsewhere in the document (a material, a light, the
// outlines, the brush) does not regrow them. Another paint is cached too, under the
// colours' own inputs (the object's material and the emitter's colour jitter): a
// colour per stroke (MeshPaint), which hits read in place of the mesh's vertex
// colours. The brush is the instance's (EmbreeScene::add), read from the asset cache
// by every compile.
struct StrokeShape {
  std::vector<SurfacePoint> roots;
  std::vector<uint32_t> first_vertex;  // stroke i owns vertices [first_vertex[i], first_vertex[i + 1])
  std::shared_ptr<const std::vector<uint32_t>> stroke_of_triangle;
  // The ribbons and their alpha layout (each triangle's brush coordinates, the paint
  // layer), without a texture. Its mesh is painted as painted_key says (the paint of
  // its first compile): while that paint holds, no MeshPaint.
  std::shared_ptr<const ShapeBvh> bvh;
  std::string painted_key;
};

// The stroke each triangle of a stroke mesh belongs to: the one owning its first vertex.
std::shared_ptr<const std::vector<uint32_t>> stroke_of_triangle(const TriangleMesh& mesh,
                                                                const std::vector<uint32_t>& first_vertex) {
  auto strokes = std::make_shared<std::vector<uint32_t>>(mesh.triangle_count());
  for (size_t t = 0; t < strokes->size(); ++t) {
    const auto owner = std::upper_bound(first_vertex.begin(), first_vertex.end(), mesh.indices[3 * t]);
    (*strokes)[t] = uint32_t(std::max<std::ptrdiff_t>(owner - first_vertex.begin() - 1, 0));
  }
  return strokes;
}

struct BuiltStrokes {
  const StrokeEmitterDesc* emitter = nullptr;
  uint32_t base_object = 0;
  std::string key;
  std::shared_ptr<const StrokeShape> shape;
  // The brush its alpha test reads, found in the asset cache by its parameters and its
  // image's stamp (an image changed on disk, or found, is a new brush).
  std::shared_ptr<const AlphaTexture> brush;
  bool stand_in = false;  // its brush image could not be read: painted in the stand-in checker
};

// Everything a StrokeShape depends on: the emitter without its name, colour jitter,
// visibility and brush.
std::string shape_key(const SceneDesc& desc, const StrokeEmitterDesc& e, const std::string& object_key) {
  StrokeEmitterDesc shape_only = e;
  shape_only.name.clear();
  shape_only.hue_jitter = shape_only.saturation_jitter = shape_only.value_jitter = 0.f;
  shape_only.indirect = false;  // where the instance is seen, not what it is
  // The brush's coverage is the alpha test's (its texture), not the ribbons'.
  const StrokeEmitterDesc any_brush;
  shape_only.brush = any_brush.brush;
  shape_only.brush_image = any_brush.brush_image;
  shape_only.bristles = any_brush.bristles;
  shape_only.pressure = any_brush.pressure;
  return "strokes|" + desc.base_dir.string() + "|" + param_key(shape_only) + "|" + object_key;
}

// Everything the colours depend on beyond the shape: the jitter, and the material
// under the strokes (all materials when it is a mix, which may reach any).
std::string paint_key(const SceneDesc& desc, const StrokeEmitterDesc& e, const std::string& material) {
  std::string key = "painted|";
  append_key(key, e.hue_jitter);
  append_key(key, e.saturation_jitter);
  append_key(key, e.value_jitter);
  const auto under = std::find_if(desc.materials.begin(), desc.materials.end(),
                                  [&](const MaterialDesc& m) { return m.name == material; });
  const bool mix = under != desc.materials.end() && std::holds_alternative<MixDesc>(under->data);
  for (const MaterialDesc& m : desc.materials) {
    if (m.name != material && !mix) continue;
    append_key(key, m.name);
    append_key(key, m.data);
  }
  return key;
}

std::optional<uint32_t> compiled_object(const World& world, const std::string& name) {
  for (uint32_t o = 0; o < world.objects.size(); ++o)
    if (world.objects[o].name == name) return o;
  return std::nullopt;
}

bool described_object(const SceneDesc& desc, const std::string& name) {
  for (const ObjectDesc& o : desc.objects)
    if (o.name == name) return true;
  return false;
}

// Builds one emitter's strokes; nullopt when there is nothing to build or on an
// error (appended to errors).
std::optional<BuiltStrokes> build_emitter(const SceneDesc& desc, const World& world,
                                          std::span<const StrokeAnchor> anchors, size_t index,
                                          StrokeBuild& build, std::vector<std::string>& errors) {
  const Cancel& cancel = build.cancel;
  const StrokeEmitterDesc& e = desc.strokes[index];
  const std::string where = "strokes[" + std::to_string(index) + "] \"" + e.name + "\": ";
  if (e.count <= 0) return std::nullopt;
  const auto object = compiled_object(world, e.object);
  if (!object) {
    // A hidden object hides its strokes too; an unknown one is an error.
    if (!described_object(desc, e.object)) errors.push_back(where + "no object named \"" + e.object + "\"");
    return std::nullopt;
  }
  // The brush first: one that cannot be read grows no strokes.
  std::string error;
  const auto brush = build.assets.brush(e, desc.base_dir, &error);
  if (!brush) {
    errors.push_back(where + error);
    return std::nullopt;
  }
  BuiltStrokes built{&e,      *object, shape_key(desc, e, anchors[*object].key),
                     nullptr, brush,   brush == stand_in_brush()};
  built.shape = build.assets.find<StrokeShape>(built.key);
  if (!built.shape) {
    const auto surface = StrokeSurface::from_shape(*anchors[*object].world, &error);
    if (!surface) {
      errors.push_back(where + "object \"" + e.object + "\": " + error);
      return std::nullopt;
    }
    auto mask = std::make_shared<AlphaMask>();  // the layout; the brush is the instance's
    auto shape = std::make_shared<StrokeShape>();
    shape->roots = place_roots(*surface, size_t(e.count), uint32_t(e.seed), nullptr, cancel);
    if (cancel.requested()) return std::nullopt;
    // Painted in the colours of this compile, which later compiles reuse while they hold.
    const RenderObject& base = world.objects[*object];
    const std::vector<Color> colors =
        stroke_colors(world.materials, base.material, shape->roots, e, anchors[*object].to_object);
    StrokeGeometry geometry = build_stroke_mesh(*surface, shape->roots, colors, e, cancel);
    if (cancel.requested()) return std::nullopt;  // unfinished ribbons are never cached
    mask->triangles = std::move(geometry.alpha);
    // Every stroke vertex lies within max_lift of the surface; the margin covers
    // the surface curving away from a ribbon's plane beside it.
    mask->layer_thickness = 1.5f * geometry.max_lift;
    mask->paint = true;  // its object casts the shadow; the later stroke lies on top
    mask->quads = true;  // stroke_mesh.h: cells of two triangles
    shape->first_vertex = std::move(geometry.first_vertex);
    shape->stroke_of_triangle = stroke_of_triangle(geometry.mesh, shape->first_vertex);
    shape->painted_key = built.key + "|" + paint_key(desc, e, world.material_names[base.material]);
    shape->bvh = std::make_shared<const ShapeBvh>(std::make_shared<const Shape>(std::move(geometry.mesh)),
                                                  std::move(mask));
    ++build.counters.shape_bvhs;
    ++build.counters.stroke_paints;
    built.shape = build.assets.keep<StrokeShape>(built.key, std::move(shape));
    ++build.counters.stroke_sets;
  }
  return built;
}

}  // namespace

void compile_strokes(const SceneDesc& desc, World& world, std::span<const StrokeAnchor> anchors,
                     StrokeBuild& build, std::vector<std::string>& errors) {
  if (desc.strokes.empty()) return;
  // Build everything before adding any: the surfaces refer to the base objects'
  // meshes, which adding shapes may move.
  std::vector<BuiltStrokes> built;
  for (size_t i = 0; i < desc.strokes.size() && !build.cancel.requested(); ++i)
    if (auto b = build_emitter(desc, world, anchors, i, build, errors)) built.push_back(std::move(*b));
  if (!errors.empty() || build.cancel.requested()) return;
  for (BuiltStrokes& b : built) {
    const uint32_t material = uint32_t(world.materials.size());
    // Unlit, the stand-in ignores the paint: 2 x 2 squares a stroke.
    world.materials.push_back(b.stand_in ? stand_in_material(2.f)
                                         : Material(DiffuseMaterial{ConstantTexture{Color(1.f)}}));
    world.material_names.push_back(b.emitter->name + ".strokes");
    // Copy the base object's record so whatever else it carries (its outline
    // overrides) applies to its strokes too.
    RenderObject object = world.objects[b.base_object];
    object.name = b.emitter->name;
    object.material = material;
    object.light = -1;
    const StrokeAnchor& anchor = anchors[b.base_object];
    if (anchor.moving) object.local_to_object = anchor.to_object;  // their BVH lies where they grew
    const uint32_t base_material = world.objects[b.base_object].material;
    world.objects.push_back(std::move(object));
    const std::string key = b.key + "|" + paint_key(desc, *b.emitter, world.material_names[base_material]);
    std::shared_ptr<const MeshPaint> paint;
    if (key != b.shape->painted_key) {
      const std::string paint_entry = key + "|paint";
      paint = build.assets.find<MeshPaint>(paint_entry);
      if (!paint) {
        paint = build.assets.keep<MeshPaint>(
            paint_entry,
            std::make_shared<const MeshPaint>(MeshPaint{
                b.shape->stroke_of_triangle, stroke_colors(world.materials, base_material, b.shape->roots,
                                                           *b.emitter, anchors[b.base_object].to_object)}));
        ++build.counters.stroke_paints;
      }
    }
    // The ribbons' mesh is what hits read, in the paint of their first compile or in
    // `paint`; their BVH traces it, unchanged by a repaint. Strokes lie where they
    // grew: in world space.
    const std::shared_ptr<const Shape>& painted = b.shape->bvh->shared_shape();
    const Transform& move = anchor.rest_to_now;
    if (anchor.moving) {
      // Paint on an object that moves while the shutter is open moves with it: the
      // ribbons grown at rest are placed as the object stands at each ray's instant
      // (docs/architecture.md, "Motion blur"), so they stay on its surface. Hits read
      // the painted mesh there; shape() reads the strokes where the frame has them.
      std::shared_ptr<const Shape> at_frame = painted;
      if (!move.is_identity()) {
        const std::string placed_key = b.key + "|placed|" + param_key(move.m);
        at_frame = build.assets.find<Shape>(placed_key);
        if (!at_frame)
          at_frame = build.assets.keep<Shape>(
              placed_key, std::make_shared<const Shape>(transformed(std::get<TriangleMesh>(*painted), move)));
      }
      world.geometry.add_moving(b.shape->bvh, anchor.rest_to_open, anchor.rest_to_close, painted, at_frame,
                                b.emitter->indirect, paint, b.brush);
      continue;
    }
    if (move.is_identity()) {
      world.geometry.add(b.shape->bvh, Transform{}, painted, b.emitter->indirect, paint, b.brush);
      continue;
    }
    // An object that moved since its rest carries its strokes along: the ribbons are
    // placed where it is now, in world space like every paint (the paint query reads
    // paint BVHs directly), and traced by a BVH of their own.
    const std::string moved_key = b.key + "|moved|" + param_key(move.m);
    auto moved = build.assets.find<ShapeBvh>(moved_key);
    if (!moved) {
      TriangleMesh mesh = std::get<TriangleMesh>(*painted);
      for (Point3& p : mesh.positions) p = move.point(p);
      for (Normal3& n : mesh.normals) n = glm::normalize(move.normal(n));
      auto mask = std::make_shared<AlphaMask>(*b.shape->bvh->mask());
      const glm::vec3 stretch(glm::length(move.vector(Vec3(1.f, 0.f, 0.f))),
                              glm::length(move.vector(Vec3(0.f, 1.f, 0.f))),
                              glm::length(move.vector(Vec3(0.f, 0.f, 1.f))));
      mask->layer_thickness *= std::max({stretch.x, stretch.y, stretch.z, 1.f});
      moved = build.assets.keep<ShapeBvh>(
          moved_key,
          std::make_shared<const ShapeBvh>(std::make_shared<const Shape>(std::move(mesh)), std::move(mask)));
      ++build.counters.shape_bvhs;
    }
    world.geometry.add(moved, Transform{}, moved->shared_shape(), b.emitter->indirect, paint, b.brush);
  }
}

}  // namespace inkray
