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
};

struct ObjectBuild {
  AssetCache& assets;
  CompileCounters& counters;
  std::filesystem::path base_dir;
  bool stand_ins = false;  // CompileOptions::stand_in_for_missing_assets
};

// The object's shape placed by its transform, from the cache when nothing that
// shapes it changed. *key names what shaped it (the shape, the mesh file's stamp,
// the transform). Null with *error set when its mesh cannot be read; with
// build.stand_ins, a unit box centred on the object's origin instead (*error set
// all the same), so the user sees where the mesh belongs.
std::shared_ptr<const PlacedShape> place_object(const ObjectDesc& object, ObjectBuild& build, std::string* key,
                                                std::string* error);

// Scale, then the rotations in order, then translation.
Transform transform_from_desc(const TransformDesc& desc);

}  // namespace inkray
