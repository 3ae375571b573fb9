// The camera's settings as one block (docs/architecture.md, "Parameter tables"): the
// document's CameraDesc derives from it and a Camera is built from it, so a setting
// is declared once, with one default, and the compiled camera reads no document.
#pragma once

#include "core/math/types.h"

namespace inkray {

struct CameraParams {
  Point3 look_from{0.f, 0.f, 5.f};
  Point3 look_at{0.f};
  Vec3 up{0.f, 1.f, 0.f};
  float vfov = 40.f;           // vertical field of view, degrees
  float aperture = 0.f;        // lens diameter; 0 is a pinhole
  float focus_distance = 0.f;  // 0 focuses on look_at
  bool operator==(const CameraParams&) const = default;
};

}  // namespace inkray
