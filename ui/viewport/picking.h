// Picking: which document object the camera sees through a pixel, and how far
// away along the view axis (for click-to-focus). One ray through the core's
// compiled geometry; safe on the UI thread since compiled scenes are immutable.
#pragma once

#include "core/world/render_scene.h"

namespace inkray {

struct PickResult {
  int object = -1;    // index into SceneDesc::objects; -1 for the background
  float depth = 0.f;  // distance along the camera's forward axis
  Point3 point{0.f};
};

// `image_pos`: continuous pixel coordinates of the scene's render resolution, (0,0) top-left.
// `camera` is the document's current one: the compiled scene's may lag behind a drag.
PickResult pick(const RenderScene& scene, const Camera& camera, Vec2 image_pos);
inline PickResult pick(const RenderScene& scene, Vec2 image_pos) {
  return pick(scene, scene.camera, image_pos);
}

}  // namespace inkray
