// The surface a camera ray "sees" for line detection: the first hit that is not
// a mirror, glass or a transparent sheet, found by following those
// deterministically (mirror: reflect; glass: refract, reflect on total internal
// reflection; transparent: straight on). Rays through neighbouring pixels
// follow the same rules, so lines appear in reflections and refractions.
//
// Nearly smooth mirrors and glass are followed too, along their mean
// direction, as long as their roughness blurs less than `max_blur` radians in
// total; the blur is recorded, and the line detector fades lines by it
// (docs/outlines.md, "Lines through mirrors and glass").
#pragma once

#include <array>
#include <optional>

#include "core/geometry/ray.h"
#include "core/integrator/path_tracer.h"
#include "core/world/line_setup.h"
#include "core/world/render_scene.h"

namespace inkray {

inline constexpr uint32_t kDirect = UINT32_MAX;
inline constexpr int kMaxPerceivedChain = 8;

struct PerceivedSurface {
  bool hit = false;
  // The chain ran out of vertices before reaching a surface (a ray trapped in a
  // bumpy refractor): nothing coherent is seen, and no line is drawn against it.
  bool lost = false;
  uint32_t object = 0;     // index into RenderScene::objects
  uint32_t identity = 0;   // RenderObject::source: strokes share their base object's
  uint32_t via = kDirect;  // identity of the first mirror or glass followed
  uint32_t material = 0;   // RenderObject::line_material: a mix keeps its id, strokes their base's
  // The mesh's smooth patch at the crease threshold, or kNoPatch (render_scene.h, crease_patch()).
  uint32_t patch = UINT32_MAX;
  Point3 p{0.f};
  Normal3 ng{0.f}, ns{0.f};         // facing the arriving ray
  float distance = 0.f;             // along the whole chain from the camera
  std::optional<Color> line_color;  // a material graph's line colour output here
  float line_width = 1.f;           // and its line width output

  // The specular chain followed: which object each vertex was on and the unit
  // direction the ray left it in. Two rays whose chains agree vertex by vertex
  // are the finite differences of one ray through the chain (see line_detector.cpp).
  int chain_length = 0;
  std::array<uint32_t, kMaxPerceivedChain> chain_object{};
  std::array<Vec3, kMaxPerceivedChain> chain_dir{};
  float blur = 0.f;  // angular blur of the rough vertices followed, radians
};

// Follows at most kMaxPerceivedChain specular vertices; u_mix resolves mix
// materials. `first`, when given, is the ray's own intersection, already
// traced. Rough mirrors and glass are followed while the chain's blur stays
// within follow.max_blur radians. Adds the rays it traced to *rays.
PerceivedSurface find_perceived_surface(const RenderScene& scene, Ray ray, float u_mix,
                                        const FollowLimits& follow, uint32_t* rays,
                                        const PrimaryHit* first = nullptr);

}  // namespace inkray
