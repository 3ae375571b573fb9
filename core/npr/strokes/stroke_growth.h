// Growing one stroke's centreline over the surface: steps along the flow
// direction in the local tangent plane, each projected back onto the surface
// where the tangent frame is taken again, so a stroke bends with the surface it
// lies on and stops where the surface does.
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
};

StrokeShape draw_stroke_shape(const StrokeEmitterDesc& emitter, uint32_t seed, uint32_t stroke);

// A stroke's centreline, from its tail to its tip.
struct StrokeSpine {
  std::vector<SurfacePoint> stations;
  std::vector<float> v;   // per station: where it lies along the brush, 0 at the tail, 1 at the tip
  bool cut_tail = false;  // growth stopped early at that end: the next step left the surface
  bool cut_tip = false;
};

// Grows the stroke with `segments` steps of length / segments, each re-projected
// onto the surface: half against the flow and half along it, so the root is the
// stroke's centre and roots spread evenly means strokes spread evenly. `flow`
// need not be unit or tangent; where it is (nearly) parallel to the normal the
// stroke keeps its previous direction, or starts along a fixed tangent. A step
// that does not land on the surface (step_lands) ends that half of the stroke:
// the spine then holds fewer than segments + 1 stations and marks the cut end.
void grow_stroke(const StrokeSurface& surface, const SurfacePoint& root, const Vec3& flow,
                 const StrokeShape& shape, int segments, StrokeSpine* spine);

// Whether a step of length `step` from `from` projected to `to` stayed on the
// surface: not past an open boundary of a mesh, no farther than 1.5 steps (a
// projection that jumped to another part of the surface) and with the normal
// turned by less than 100 degrees (a jump to a facing surface, as across a thin
// sheet). Folds up to 90 degrees, such as a box's edges, are walked around.
inline constexpr float kLandingCos = -0.17364818f;  // cos(100 degrees)
bool step_lands(const SurfacePoint& from, const SurfacePoint& to, float step);

}  // namespace inkray
