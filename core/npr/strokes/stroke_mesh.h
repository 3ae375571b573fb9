// Ribbon meshes for an emitter's strokes: rails of points across each stroke,
// on the surface, lifted off it so no ribbon touches or crosses the surface it
// lies on, with as few points as keep the ribbon within a tolerance of it.
#pragma once

#include "core/base/cancel.h"

#include "core/geometry/alpha_mask.h"
#include "core/geometry/triangle_mesh.h"
#include "core/npr/strokes/stroke_surface.h"
#include "core/document/npr_desc.h"

#include <span>
#include <vector>

namespace inkray {

struct StrokeGeometry {
  // Stroke i owns vertices [first_vertex[i], first_vertex[i + 1]) (none when it
  // could not grow) and its triangles, consecutively. Its vertices form rails
  // across the stroke at each kept station; uv: u across (0 left, 1 right), v
  // along (0 at the tail, 1 at the tip). Normals are the surface's, colours the
  // stroke's.
  TriangleMesh mesh;
  std::vector<AlphaTriangle> alpha;    // per triangle: brush uv, corner alphas, variant
  std::vector<uint32_t> first_vertex;  // stroke count + 1 entries
  float offset = 0.f;                  // base lift above the surface
  float max_lift = 0.f;                // largest lift of any vertex (curvature included)
};

// How closely a ribbon follows the surface: every part of it stands off the
// surface by the offset plus at most this fraction of its width (or the
// offset, if larger), as long as the stroke's `segments` along and
// kMaxColumns across allow. Stations and columns beyond what that needs are
// left out.
inline constexpr float kFollowTolerance = 0.01f;
inline constexpr int kMaxColumns = 4;
// Where a ribbon cannot follow that closely (a fold sharper than its stations
// and columns), the part standing off the surface by more than the offset
// fades: fully opaque up to kFadeStart of the width off, transparent from
// kFadeEnd on.
inline constexpr float kFadeStart = 0.15f;
inline constexpr float kFadeEnd = 0.3f;

// The emitter's offset, or when it is 0, one derived from the object: 1e-4 of
// its size (capped at 5% of the mean stroke width, so strokes on a huge ground
// do not float), and never below 256 float roundings of its coordinates, so
// rays leaving the surface and the strokes (offset by their own rounding
// error) never start on the wrong side of the paint.
float stroke_offset(const StrokeSurface& surface, const StrokeEmitterDesc& emitter);

// Grows one stroke per root (in parallel; the result does not depend on the
// thread count) and builds the ribbons (docs/strokes.md, "Ribbons follow the
// surface"). colors[i] is stroke i's vertex colour. Each vertex is a surface point
// lifted along the normal there by the offset plus the deepest a chord between neighbouring
// vertices can dip below the surface; which stroke lies on top is the
// renderer's (painting order, AlphaMask::paint), not a matter of height. Parts
// of a ribbon whose growth left the surface are cut; parts standing off the
// surface, or wrapping around it by more than 60 degrees from the centreline's
// normal, fade (AlphaTriangle::fade). Once `cancel` is requested the ribbons
// are left unfinished (the caller discards them).
StrokeGeometry build_stroke_mesh(const StrokeSurface& surface, std::span<const SurfacePoint> roots,
                                 std::span<const Color> colors, const StrokeEmitterDesc& emitter,
                                 const Cancel& cancel = {});

}  // namespace inkray
