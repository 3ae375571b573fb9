// Where the editor puts a new object: in front of the camera at the distance of its
// target, sized to a fraction of the visible height, and beside the objects already
// there rather than inside them. An imported mesh is fitted to the view from its bounds.
#pragma once

#include "core/document/desc.h"

namespace inkray {

// Fractions of the visible height at the target's distance.
inline constexpr float kNewShapeFraction = 0.25f;
inline constexpr float kNewMeshFraction = 0.5f;

struct Placement {
  Point3 center{0.f};
  float size = 1.f;  // the new object's diameter, world units
};

// World height the camera sees at `distance` along its view axis.
float visible_height(const CameraDesc& camera, float distance);
// A sphere of `fraction` of the visible height at the target's distance: at the target
// itself unless that overlaps an object, else the nearest free spot of a grid across the
// view plane that still lies inside the view; with no free spot, the least crowded.
Placement place_in_view(const SceneDesc& scene, float fraction = kNewShapeFraction);
// Scale and translate that fit the local bounds [lo, hi] (largest side) into the
// placement's sphere, centred on it.
TransformDesc fit_bounds(const Point3& lo, const Point3& hi, const Placement& placement);

}  // namespace inkray
