// Growing one stroke's centreline over the surface: steps along the flow
// direction projected on the tangent plane, each re-projected onto the surface,
// so a stroke bends with the surface it lies on.
#pragma once

#include "core/npr/strokes/stroke_surface.h"
#include "core/document/npr_desc.h"

#include <vector>

namespace inkray {

// The random choices of one stroke, all drawn from (emitter seed, stroke index).
struct StrokeShape {
  float length = 0.f;
  float width = 0.f;
  float angle = 0.f;  // rotation of the flow about the normal, radians
  float bend = 0.f;   // change of that rotation from one end to the other, radians
  int layer = 0;      // in [0, kStrokeLayers): strokes on higher layers lie on top
};
inline constexpr int kStrokeLayers = 16;

StrokeShape draw_stroke_shape(const StrokeEmitterDesc& emitter, uint32_t seed, uint32_t stroke);

// Writes segments + 1 stations into *stations, from the stroke's tail to its
// tip, with the root in the middle: half the stroke grows against the flow and
// half along it, so the root is the stroke's centre and roots spread evenly
// means strokes spread evenly. `flow` need not be unit or tangent; where it is
// (nearly) parallel to the normal the stroke keeps its previous direction, or
// starts along a fixed tangent.
void grow_stroke(const StrokeSurface& surface, const SurfacePoint& root, const Vec3& flow, const StrokeShape& shape,
                 int segments, std::vector<SurfacePoint>* stations);

}  // namespace inkray
