// RenderScene: the immutable, compiled form of a SceneDesc (docs/architecture.md,
// "From JSON to pixels"). Render threads only read it, through a shared_ptr to
// const; copies share the geometry.
#pragma once

#include "core/camera/camera.h"
#include "core/geometry/embree_scene.h"
#include "core/geometry/mesh_features.h"
#include "core/lights/light.h"
#include "core/materials/material.h"
#include "core/math/transform.h"
#include "core/document/desc.h"

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
  int light = -1;              // index into RenderScene::lights when the object emits and is sampled
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

struct RenderScene {
  Camera camera;
  RenderSettings settings;
  EmbreeScene geometry;  // shape i belongs to objects[i]
  std::vector<RenderObject> objects;
  std::vector<Material> materials;
  std::vector<std::string> material_names;
  std::vector<Light> lights;
  DiscreteDistribution light_selection;  // by estimated power; empty when there are no lights
  EnvironmentLight environment;          // what escaping rays see (black by default)
  int environment_light = -1;            // index into lights when the environment is not black
  OutlineDesc outlines;  // line types, widths and colours; any_line() false means no outline work
  Point3 scene_center{0.f};
  float scene_radius = 1.f;

  const Material& material_of(uint32_t object) const { return materials[objects[object].material]; }
};

// Whether anything moves while the shutter is open: a shape or the camera
// (docs/architecture.md, "Motion blur").
inline bool moves_during_shutter(const RenderScene& scene) {
  return scene.settings.motion_blur() && (scene.geometry.any_moving() || scene.camera.moves());
}

// The smooth patch of triangle `prim` of an object at the scene's crease threshold,
// or kNoPatch where the object has none (docs/architecture.md, "Mesh normals and
// feature edges").
inline uint32_t crease_patch(const RenderScene& scene, uint32_t object, uint32_t prim) {
  const auto& patches = scene.objects[object].crease_patches;
  return patches && prim < patches->size() ? (*patches)[prim] : kNoPatch;
}

// What a material graph reads at a hit on one of the scene's objects, seen from `wo`
// at `depth` along the path (the light inputs are the integrator's to gather).
inline ShadingPoint scene_shading_point(const RenderScene& scene, const SurfaceInteraction& si,
                                        const Vec3& wo, float depth) {
  const RenderObject& object = scene.objects[si.object];
  ShadingPoint sp = shading_point(si, wo);
  sp.depth = depth;
  sp.object_id = object.source;
  sp.material_id = object.material;
  // Textures stay fixed on a moving object: the hit is taken back through where the
  // object stands at its instant (docs/architecture.md, "Motion blur").
  if (!scene.geometry.moving(si.object)) {
    sp.p_object = object.to_object.point(si.p);
  } else {
    const Transform at = scene.geometry.placement(si.object, si.time);
    sp.p_object = object.local_to_object.point(Point3(at.inv * glm::vec4(si.p, 1.f)));
  }
  return sp;
}

}  // namespace inkray
