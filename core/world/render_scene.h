// RenderScene: the immutable, compiled form of a SceneDesc (docs/architecture.md,
// "From JSON to pixels", "World and view"): a shared World and the view of it
// (camera, compiled settings and line setup). Render threads only read it, through a shared_ptr to const.
#pragma once

#include "core/camera/camera.h"
#include "core/world/line_setup.h"
#include "core/world/view_settings.h"
#include "core/world/world.h"

#include <memory>
#include <string>
#include <vector>

namespace inkray {

struct RenderScene {
  std::shared_ptr<const World> world = std::make_shared<const World>();
  Camera camera;
  SampleSettings sampling;  // what every sample reads of the render settings
  ResolveSettings resolve;  // the painterly filter and the line colours, read by the resolve
  LineSetup lines;          // what the outlines mean for every sample at the image's resolution
};

// Whether anything moves while the shutter is open: a shape or the camera
// (docs/architecture.md, "Motion blur").
inline bool moves_during_shutter(const RenderScene& scene) {
  return scene.sampling.motion_blur && (scene.world->geometry.any_moving() || scene.camera.moves());
}

// The smooth patch of triangle `prim` of an object at the scene's crease threshold,
// or kNoPatch where the object has none (docs/architecture.md, "Mesh normals and
// feature edges").
inline uint32_t crease_patch(const RenderScene& scene, uint32_t object, uint32_t prim) {
  const auto& patches = scene.world->objects[object].crease_patches;
  return patches && prim < patches->size() ? (*patches)[prim] : kNoPatch;
}

// What a material graph reads at a hit on one of the scene's objects, seen from `wo`
// at `depth` along the path (the light inputs are the integrator's to gather).
inline ShadingPoint scene_shading_point(const RenderScene& scene, const SurfaceInteraction& si,
                                        const Vec3& wo, float depth) {
  const RenderObject& object = scene.world->objects[si.object];
  ShadingPoint sp = shading_point(si, wo);
  sp.depth = depth;
  sp.object_id = object.source;
  sp.material_id = object.material;
  // Textures stay fixed on a moving object: the hit is taken back through where the
  // object stands at its instant (docs/architecture.md, "Motion blur").
  if (!scene.world->geometry.moving(si.object)) {
    sp.p_object = object.to_object.point(si.p);
  } else {
    const Transform at = scene.world->geometry.placement(si.object, si.time);
    sp.p_object = object.local_to_object.point(Point3(at.inv * glm::vec4(si.p, 1.f)));
  }
  return sp;
}

}  // namespace inkray
