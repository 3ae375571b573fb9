// Auto smooth: vertex normals for a mesh read without them, smooth across edges whose
// dihedral angle is at most a threshold and split at sharper ones, as Blender's auto
// smooth (docs/architecture.md, "Mesh normals and feature edges").
#pragma once

#include "core/geometry/obj_loader.h"

namespace inkray {

// Whether auto_smooth would change the mesh: it has no normals and smooth_angle > 0.
bool needs_auto_smooth(const TriangleMeshData& mesh, float smooth_angle_degrees);

// The mesh with a normal per vertex. Around each position, the triangles joined
// through edges of at most smooth_angle_degrees (found by position) form fans, and
// each fan gets one normal: its facet normals weighted by their corner angles there.
// A vertex is split where fans differ, as the loader splits it where uvs do; the
// triangles keep their order. Normals in the mesh, or smooth_angle_degrees <= 0,
// return it unchanged (flat shading). Every normal is a finite unit vector, also at
// degenerate triangles and non-manifold edges.
TriangleMeshData auto_smooth(const TriangleMeshData& mesh, float smooth_angle_degrees);

}  // namespace inkray
