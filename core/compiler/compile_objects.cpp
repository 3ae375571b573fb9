#include "core/compiler/compile_objects.h"

#include "core/compiler/compile.h"
#include "core/document/param_key.h"
#include "core/geometry/mesh_features.h"
#include "core/geometry/mesh_normals.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace inkray {
namespace {

void shape_bounds(const Shape& shape, Point3* lo, Point3* hi) {
  if (const auto* sphere = std::get_if<Sphere>(&shape)) return sphere->bounds(lo, hi);
  const TriangleMesh& mesh = std::get<TriangleMesh>(shape);
  *lo = Point3(std::numeric_limits<float>::infinity());
  *hi = -*lo;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    *lo = glm::min(*lo, mesh.positions[v]);
    *hi = glm::max(*hi, mesh.positions[v]);
  }
}

// Empty when bounds lie within kMaxWorldCoordinate, else why not.
std::string extent_problem(const Point3& lo, const Point3& hi) {
  const float reach = std::max(max_component(glm::abs(lo)), max_component(glm::abs(hi)));
  if (std::isfinite(reach) && reach <= kMaxWorldCoordinate) return {};
  char text[160];
  std::snprintf(text, sizeof text,
                "after its transform the shape reaches %g units from the origin; the limit is %g "
                "(scale it down or move it closer)",
                double(reach), double(kMaxWorldCoordinate));
  return text;
}

std::string world_extent_problem(const Shape& shape) {
  Point3 lo, hi;
  shape_bounds(shape, &lo, &hi);
  return extent_problem(lo, hi);
}

// Bounds of object-space bounds [lo, hi] moved by `t`: of their eight corners.
void moved_bounds(const Transform& t, Point3* lo, Point3* hi) {
  const Point3 a = *lo, b = *hi;
  *lo = Point3(std::numeric_limits<float>::infinity());
  *hi = -*lo;
  for (int c = 0; c < 8; ++c) {
    const Point3 p = t.point(Point3(c & 1 ? b.x : a.x, c & 2 ? b.y : a.y, c & 4 ? b.z : a.z));
    *lo = glm::min(*lo, p);
    *hi = glm::max(*hi, p);
  }
}

// The mesh of a mesh-like shape in object space; null with *error for an unreadable file.
std::shared_ptr<const Shape> object_space_mesh(const ShapeVariant& shape, ObjectBuild& build,
                                               std::string* error) {
  return std::visit(
      [&](const auto& s) -> std::shared_ptr<const Shape> {
        using T = std::decay_t<decltype(s)>;
        const Transform identity;
        if constexpr (std::is_same_v<T, QuadDesc>) {
          return std::make_shared<const Shape>(make_quad(s.corner, s.edge_u, s.edge_v, identity));
        } else if constexpr (std::is_same_v<T, BoxDesc>) {
          return std::make_shared<const Shape>(
              make_box(glm::min(s.min, s.max), glm::max(s.min, s.max), identity));
        } else if constexpr (std::is_same_v<T, MeshDesc>) {
          const auto data = build.assets.mesh(build.base_dir / s.path, error);
          if (!data) return nullptr;
          if (needs_auto_smooth(*data, s.smooth_angle)) {
            TriangleMeshData smooth = auto_smooth(*data, s.smooth_angle);
            return std::make_shared<const Shape>(make_mesh(std::move(smooth.positions),
                                                           std::move(smooth.normals), std::move(smooth.uvs),
                                                           std::move(smooth.indices), identity));
          }
          return std::make_shared<const Shape>(
              make_mesh(data->positions, data->normals, data->uvs, data->indices, identity));
        } else {
          static_assert(std::is_same_v<T, SphereDesc>, "a new shape type needs a case here");
          return nullptr;  // spheres are placed analytically
        }
      },
      shape);
}

// Whether a transform keeps the angles between faces: rotation, uniform scale,
// reflection and translation do; a non-uniform scale or a shear bends them.
bool keeps_angles(const Transform& t) {
  const Mat3 linear(t.m);
  const Mat3 gram = glm::transpose(linear) * linear;
  const float scale = (gram[0][0] + gram[1][1] + gram[2][2]) / 3.f;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::abs(gram[i][j] - (i == j ? scale : 0.f)) > 1e-5f * scale) return false;
  return scale > 0.f;
}

// Places an object-space shape's BVH by the object's transform; `from` is the BVH's
// key, `features_key` names the object-space shape's feature edges.
std::shared_ptr<const PlacedShape> place_mesh(std::shared_ptr<const ShapeBvh> bvh, const Transform& to_world,
                                              const std::string& key, const std::string& from,
                                              const std::string& features_key, ObjectBuild& build) {
  auto placed = std::make_shared<PlacedShape>();
  placed->bvh = std::move(bvh);
  placed->to_world = to_world;
  placed->features_in_world = !keeps_angles(to_world);
  placed->features_key = placed->features_in_world ? "features|" + key : features_key;
  if (to_world.is_identity()) {
    placed->world = placed->bvh->shared_shape();
  } else {
    placed->world =
        std::make_shared<const Shape>(transformed(std::get<TriangleMesh>(placed->bvh->shape()), to_world));
    ++build.counters.placements;
  }
  placed->problem = world_extent_problem(*placed->world);
  // A mesh's BVH is kept while a placement of it is.
  return build.assets.keep<PlacedShape>(key, std::move(placed), {from});
}

// What stands in for a mesh that cannot be read. Under keys of its own, never the
// file's, so the file is read as soon as it can be.
std::shared_ptr<const PlacedShape> place_stand_in(const ObjectDesc& object, ObjectBuild& build,
                                                  std::string* key) {
  *key = "placed|stand-in box|" + param_key(object.transform);
  if (auto found = build.assets.find<PlacedShape>(*key)) return found;
  const std::string bvh_key = "bvh|stand-in box";
  auto bvh = build.assets.find<ShapeBvh>(bvh_key);
  if (!bvh) {
    const Point3 half(0.5f);
    bvh = build.assets.keep(bvh_key, std::make_shared<const ShapeBvh>(
                                         std::make_shared<const Shape>(make_box(-half, half, Transform{}))));
    ++build.counters.shape_bvhs;
  }
  return place_mesh(std::move(bvh), transform_from_desc(object.transform), *key, bvh_key,
                    "features|" + bvh_key, build);
}

}  // namespace

Transform transform_from_desc(const TransformDesc& desc) {
  Transform t = Transform::scale(desc.scale);
  for (const RotationDesc& r : desc.rotate) t = Transform::rotate(r.degrees, r.axis) * t;
  return Transform::translate(desc.translate) * t;
}

std::shared_ptr<const PlacedShape> place_object(const ObjectDesc& object, ObjectBuild& build,
                                                std::string* key, std::string* error) {
  // A mesh is known by its file's stamp, so a file changed on disk is read again,
  // and by its smooth angle. `source_key` is what the shape was made from: the file
  // as read (the cache's key for it), kept while the BVH is so that another smooth
  // angle reads no file. Feature edges depend on positions only: not on the angle.
  std::string shape_key, source_key;
  if (const auto* mesh = std::get_if<MeshDesc>(&object.shape)) {
    const auto stamp = file_stamp(build.base_dir / mesh->path);
    source_key = "mesh|" + (stamp ? *stamp : (build.base_dir / mesh->path).string());
    shape_key = source_key + "|smooth ";
    append_key(shape_key, mesh->smooth_angle);
  } else {
    shape_key = source_key = "shape|" + param_key(object.shape);
  }
  *key = "placed|" + shape_key + "|" + param_key(object.transform);
  if (auto found = build.assets.find<PlacedShape>(*key)) return found;

  const Transform to_world = transform_from_desc(object.transform);
  if (const auto* sphere = std::get_if<SphereDesc>(&object.shape)) {
    // Spheres are intersected analytically under their transform, in a one-primitive
    // BVH: rebuilding it costs no more than moving an instance.
    auto placed = std::make_shared<PlacedShape>();
    auto shape = std::make_shared<const Shape>(Sphere{sphere->center, sphere->radius, to_world});
    placed->bvh = std::make_shared<const ShapeBvh>(shape);
    placed->world = std::move(shape);
    ++build.counters.shape_bvhs;
    placed->problem = world_extent_problem(*placed->world);
    return build.assets.keep<PlacedShape>(*key, std::move(placed));
  }
  const std::string bvh_key = "bvh|" + shape_key;
  auto bvh = build.assets.find<ShapeBvh>(bvh_key);
  if (!bvh) {
    auto shape = object_space_mesh(object.shape, build, error);
    if (!shape) return build.stand_ins ? place_stand_in(object, build, key) : nullptr;
    std::vector<std::string> from;
    if (source_key != shape_key) from.push_back(source_key);
    bvh = build.assets.keep(bvh_key, std::make_shared<const ShapeBvh>(std::move(shape)), std::move(from));
    ++build.counters.shape_bvhs;
  }
  return place_mesh(std::move(bvh), to_world, *key, bvh_key, "features|" + source_key, build);
}

MovingShape place_moving(const ObjectDesc& object, const PlacedShape& placed, const TransformDesc& open,
                         const TransformDesc& close, ObjectBuild& build) {
  MovingShape moving{placed.bvh, transform_from_desc(open), transform_from_desc(close), {}};
  if (const auto* sphere = std::get_if<SphereDesc>(&object.shape)) {
    const std::string key = "bvh|object space|shape|" + param_key(object.shape);
    moving.bvh = build.assets.find<ShapeBvh>(key);
    if (!moving.bvh) {
      moving.bvh = build.assets.keep(key, std::make_shared<const ShapeBvh>(std::make_shared<const Shape>(
                                              Sphere{sphere->center, sphere->radius, Transform{}})));
      ++build.counters.shape_bvhs;
    }
  }
  // Anything a transform in between reaches lies within the bounds at both ends,
  // grown by the turn; each end must stay within the limit, with room to turn.
  Point3 object_lo, object_hi;
  shape_bounds(moving.bvh->shape(), &object_lo, &object_hi);
  for (const Transform* end : {&moving.open, &moving.close}) {
    Point3 lo = object_lo, hi = object_hi;
    moved_bounds(*end, &lo, &hi);
    const Vec3 turn(glm::length(hi - lo));
    moving.problem = extent_problem(lo - turn, hi + turn);
    if (!moving.problem.empty()) break;
  }
  return moving;
}

std::shared_ptr<const std::vector<uint32_t>> crease_patches(const PlacedShape& placed,
                                                            float threshold_degrees, AssetCache& assets) {
  if (placed.features_key.empty()) return nullptr;
  const auto* mesh =
      std::get_if<TriangleMesh>(placed.features_in_world ? placed.world.get() : &placed.bvh->shape());
  if (!mesh) return nullptr;
  std::string key = "crease patches|" + placed.features_key + "|";
  append_key(key, threshold_degrees);
  if (auto found = assets.find<std::vector<uint32_t>>(key)) return found;
  auto features = assets.find<MeshFeatures>(placed.features_key);
  if (!features) {
    features = assets.keep(placed.features_key,
                           std::make_shared<const MeshFeatures>(find_feature_edges(
                               std::span(mesh->positions.data(), mesh->vertex_count()), mesh->indices)));
  }
  return assets.keep(
      key, std::make_shared<const std::vector<uint32_t>>(smooth_patches(*features, threshold_degrees)),
      {placed.features_key});
}

}  // namespace inkray
