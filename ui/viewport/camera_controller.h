// Viewport camera navigation as pure functions over CameraDesc: orbit about
// look_at (turntable, world up), pan in the image plane, dolly towards
// look_at, and framing a bounding sphere. Plain maths, tested without a window.
#pragma once

#include "core/document/desc.h"

namespace inkray {

// Radians: yaw about the world up axis, pitch about the camera's right axis.
// Pitch stops short of the poles so the view never flips.
CameraDesc orbit(const CameraDesc& camera, float yaw, float pitch);
// Moves eye and target by a drag of (dx, dy) pixels in an image `image_height`
// pixels tall, so the point under the cursor at look_at's depth follows it.
CameraDesc pan(const CameraDesc& camera, float dx, float dy, float image_height);
// Scales the eye-to-target distance by `factor` (< 1 moves closer).
CameraDesc dolly(const CameraDesc& camera, float factor);
// Keeps the viewing direction and places a sphere so it fills the view.
CameraDesc frame_sphere(const CameraDesc& camera, const Point3& center, float radius);
// Sets the focus distance (along the view axis) for click-to-focus.
CameraDesc focus_at(const CameraDesc& camera, float distance);

// Mouse input mapped to the functions above, with one sensitivity setting.
struct CameraController {
  float orbit_radians_per_pixel = 0.008f;
  float dolly_per_wheel_step = 0.85f;  // distance factor per wheel notch
  float dolly_per_pixel = 0.005f;      // right drag: exp(dy * this)

  CameraDesc drag_orbit(const CameraDesc& c, float dx, float dy) const {
    return orbit(c, -dx * orbit_radians_per_pixel, -dy * orbit_radians_per_pixel);
  }
  CameraDesc wheel(const CameraDesc& c, float steps) const;
  CameraDesc drag_dolly(const CameraDesc& c, float dy) const;
};

}  // namespace inkray
