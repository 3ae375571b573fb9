// The lines of a scene's surfaces as straight pieces in world space, found from the
// geometry itself rather than from what the camera sees: the edges of meshes where
// they turn from the camera (silhouettes) or fold sharply (creases), and the contour
// circles of spheres. Hidden lines (hidden_lines.h) sample them and ask what lies
// in front.
#pragma once

#include "core/world/render_scene.h"

#include <array>
#include <cstdint>
#include <vector>

namespace inkray {

// A triangle the edge lies on, or none.
inline constexpr uint32_t kNoFace = UINT32_MAX;

// One straight piece of a line on a surface. Pieces that share an end share its
// joint id (unique over the scene), so they can be followed from one to the next.
struct SurfaceEdge {
  Point3 a{0.f}, b{0.f};
  uint32_t joint_a = 0, joint_b = 0;
  uint32_t object = 0;  // index into World::objects
  LineType type = LineType::crease;
  // The triangles of the object the edge borders: grazed by every ray to the edge,
  // they never hide it.
  std::array<uint32_t, 2> faces{kNoFace, kNoFace};
  // False for a sphere's contour: a sphere never hides its own contour, and the
  // pieces, chords of the circle, dip into it.
  bool own_object_hides = true;
};

struct SurfaceEdges {
  std::vector<SurfaceEdge> edges;
  uint32_t joints = 0;  // joint ids are below this
};

// The edges of the line types `types` (bits by LineType; silhouette and crease are
// found) of every object that draws lines, seen from `eye` (paint layers and objects
// whose lines are excluded have none): mesh edges whose two triangles face the eye
// differently (silhouette), or whose normals meet at a cosine below
// scene.lines.crease_cos, and open boundaries (crease); a sphere's contour as seen
// from `eye`, in chords about `spacing_px` long on the image. An edge of both types
// is a silhouette. In object order, then by the objects' own order.
SurfaceEdges surface_edges(const RenderScene& scene, const Point3& eye, uint32_t types, float spacing_px);

}  // namespace inkray
