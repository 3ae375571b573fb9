// Placing an object's shape: the bottom-level BVH it is traced in (built once
// per shape, shared by every placement), the instance transform, and the shape
// in world space that hits, lights and strokes read.
#pragma once

#include "core/compiler/asset_cache.h"
#include "core/compiler/compile_counters.h"
#include "core/document/desc.h"
#include "core/geometry/embree_scene.h"

#include <memory>
#include <string>

namespace inkray {

struct PlacedShape {
  std::shared_ptr<const ShapeBvh> bvh;
  Transform to_world;  // the instance's: identity for a sphere, whose BVH holds its transform
  std::shared_ptr<const Shape> world;
  std::string problem;  // why it cannot be placed (reaching too far), else empty
  // The cache key of the shape's feature edges (mesh_features.h): the shape's, and
  // the transform's too when it bends angles (features_in_world). Empty for a sphere.
  std::string features_key;
  bool features_in_world = false;  // found on `world`, else on the BVH's object-space mesh
};

struct ObjectBuild {
  AssetCache& assets;
  CompileCounters& counters;
  std::filesystem::path base_dir;
  bool stand_ins = false;  // CompileOptions::stand_in_for_missing_assets
};

// The object's shape placed by its transform, from the cache when nothing that
// shapes it changed. *key names what shaped it (the shape, the mesh file's stamp and
// smooth angle, the transform). A mesh file without normals is auto-smoothed
// (mesh_normals.h); the file as read stays cached while its BVH does, so a new
// smooth angle reads no file. Null with *error set when its mesh cannot be read; with
// build.stand_ins, a unit box centred on the object's origin instead (*error set
// all the same), so the user sees where the mesh belongs.
std::shared_ptr<const PlacedShape> place_object(const ObjectDesc& object, ObjectBuild& build,
                                                std::string* key, std::string* error);

// An object that moves while the shutter is open (docs/architecture.md, "Motion
// blur"): its shape in its own space, traced by a BVH that an instance places at the
// shutter's opening and closing.
struct MovingShape {
  std::shared_ptr<const ShapeBvh> bvh;  // the shape in the object's own space
  Transform open, close;
  std::string problem;  // why it cannot be placed (reaching too far at either end), else empty
};

// The object `placed` (place_object, at the frame) moving from transform `open` to
// `close`. A mesh's BVH is the placed one; a sphere, whose placed BVH holds its
// transform, gets one in its own space, kept in the cache.
MovingShape place_moving(const ObjectDesc& object, const PlacedShape& placed, const TransformDesc& open,
                         const TransformDesc& close, ObjectBuild& build);

// The smooth patch of each triangle of a placed mesh, quad or box at a crease
// threshold in degrees (smooth_patches, mesh_features.h); null for a sphere. The
// feature edges are found once per shape and the patches once per threshold, both
// kept in the cache.
std::shared_ptr<const std::vector<uint32_t>> crease_patches(const PlacedShape& placed,
                                                            float threshold_degrees, AssetCache& assets);

// Scale, then the rotations in order, then translation.
Transform transform_from_desc(const TransformDesc& desc);

}  // namespace inkray
