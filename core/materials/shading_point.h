// What a material graph may read at a hit: the surface, the view, ids, and the
// light inputs a cel shader quantises (gathered by the integrator only when the
// graph uses them).
#pragma once

#include "core/geometry/ray.h"

#include <cstdint>

namespace inkray {

struct ShadingPoint {
  const SurfaceInteraction* si = nullptr;
  Vec3 wo{0.f, 0.f, 1.f};     // towards the viewer, normalised
  Normal3 ns{0.f, 0.f, 1.f};  // shading normal on the viewer's side
  Normal3 ng{0.f, 0.f, 1.f};  // geometric normal on the viewer's side
  Point3 p_object{0.f};       // the hit in the object's own space (textures stay on a moving object)
  float depth = 0.f;          // distance along the path from the camera
  uint32_t object_id = 0;     // index in the document's objects
  uint32_t material_id = 0;   // index in the compiled material table
  // Light inputs: the strongest light at the hit.
  float n_dot_l = 1.f;
  float shadow = 1.f;
  Color light_color{1.f};
};

// A shading point seen from `wo` with normals turned towards it.
inline ShadingPoint shading_point(const SurfaceInteraction& si, const Vec3& wo) {
  ShadingPoint sp;
  sp.si = &si;
  sp.wo = wo;
  sp.p_object = si.p;  // callers that know the object's transform replace it
  const bool back = glm::dot(wo, si.ng) < 0.f;
  sp.ns = back ? -si.ns : si.ns;
  sp.ng = back ? -si.ng : si.ng;
  return sp;
}

}  // namespace inkray
