// A point on the surface strokes grow on, with what growth and colouring read.
#pragma once

#include "core/math/types.h"

#include <cstdint>

namespace inkray {

struct SurfacePoint {
  Point3 p{0.f};
  Normal3 n{0.f, 0.f, 1.f};   // unit, outward (the shading normal where a mesh has one)
  Normal3 ng{0.f, 0.f, 1.f};  // unit normal of the facet under p (= n on analytic surfaces)
  Vec2 uv{0.f};
  Color color{1.f};  // the base mesh's interpolated vertex colour
  uint32_t prim = 0;
  // A projection that landed on an open boundary of a mesh from beyond it: the
  // point asked about lies off the surface, past its edge.
  bool boundary = false;
};

}  // namespace inkray
