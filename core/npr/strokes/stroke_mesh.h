// Ribbon meshes for an emitter's strokes: two vertices per station, lifted off
// the surface so no ribbon touches or crosses the surface it lies on.
#pragma once

#include "core/base/cancel.h"

#include "core/geometry/triangle_mesh.h"
#include "core/npr/strokes/stroke_surface.h"
#include "core/document/npr_desc.h"

#include <span>

namespace inkray {

struct StrokeGeometry {
  // Stroke i owns vertices [i * V, (i + 1) * V) with V = 2 (segments + 1), and
  // triangles [i * 2 segments, (i + 1) * 2 segments). uv: u across (0 left, 1
  // right), v along (0 at the tail, 1 at the tip). Normals are the surface's.
  TriangleMesh mesh;
  float offset = 0.f;    // base lift above the surface
  float max_lift = 0.f;  // largest lift of any vertex (layers and curvature included)
};

// The emitter's offset, or when it is 0, one derived from the object: 1e-4 of
// its size (capped at 5% of the mean stroke width, so strokes on a huge ground
// do not float), and never below 256 float roundings of its coordinates, so the
// 16 stroke layers stay apart and rays leaving the surface and the strokes
// (offset by their own rounding error) never start on the wrong side.
float stroke_offset(const StrokeSurface& surface, const StrokeEmitterDesc& emitter);

// Grows one stroke per root (in parallel; the result does not depend on the
// thread count) and builds the ribbons. colors[i] is stroke i's vertex colour.
// Each vertex lies at its projection onto the surface plus a lift along the
// normal: the offset scaled by the stroke's layer (1 to 2 times), plus the
// deepest a chord between neighbouring vertices can dip below the surface. Once
// `cancel` is requested the ribbons are left unfinished (the caller discards them).
StrokeGeometry build_stroke_mesh(const StrokeSurface& surface, std::span<const SurfacePoint> roots,
                                 std::span<const Color> colors, const StrokeEmitterDesc& emitter,
                                 const Cancel& cancel = {});

}  // namespace inkray
