// World: what a compile builds of the scene's content (docs/architecture.md, "World
// and view"): the geometry, objects, materials and lights. Immutable once built and
// shared by every RenderScene that views it, so a new camera, line colour or sample
// count is a new view of the same world, not a copy of its 20,000 objects.
#pragma once

#include "core/geometry/embree_scene.h"
#include "core/geometry/mesh_features.h"
#include "core/lights/light.h"
#include "core/materials/material.h"
#include "core/math/transform.h"

#include <memory>
#include <string>
#include <vector>

namespace inkray {

// Outline overrides of one object, its material's and its own combined.
struct LineOverride {
  bool exclude = false;     // produces no lines
  bool stop_lines = false;  // lines are not followed through this mirror or glass
  float width_scale = 1.f;
  bool override_color = false;
  Color color{0.f};
};

struct RenderObject {
  std::string name;
  uint32_t material = 0;
  int light = -1;              // index into World::lights when the object emits and is sampled
  uint32_t source = 0;         // index into SceneDesc::objects
  uint32_t line_material = 0;  // material boundaries are drawn where this changes
  LineOverride lines;
  Transform to_object;  // world to the object's own space: where graph textures are fixed
  // For a shape that moves while the shutter is open (EmbreeScene::moving): its BVH's
  // space to the object's own space (the identity but for strokes, whose BVH lies
  // where they grew). to_object is the frame's; hits at other instants use this.
  Transform local_to_object{};
  // Smooth patch per triangle (prim) at the crease threshold, for crease lines: two
  // hits in different patches lie across a feature edge (geometry/mesh_features.h).
  // Null for spheres and strokes, and while crease lines are off.
  std::shared_ptr<const std::vector<uint32_t>> crease_patches = nullptr;
};

struct World {
  EmbreeScene geometry;  // shape i belongs to objects[i]
  std::vector<RenderObject> objects;
  std::vector<Material> materials;
  std::vector<std::string> material_names;
  std::vector<Light> lights;
  DiscreteDistribution light_selection;  // by estimated power; empty when there are no lights
  EnvironmentLight environment;          // what escaping rays see (black by default)
  int environment_light = -1;            // index into lights when the environment is not black
  Point3 scene_center{0.f};
  float scene_radius = 1.f;

  const Material& material_of(uint32_t object) const { return materials[objects[object].material]; }
};

}  // namespace inkray
