// The surface a camera ray "sees" for line detection: the first hit that is not
// a perfect mirror, smooth glass or a transparent sheet, found by following
// those deterministically (mirror: reflect; glass: refract, reflect on total
// internal reflection; transparent: straight on). Rays through neighbouring
// pixels follow the same rules, so lines appear in reflections and refractions.
#pragma once

#include <optional>

#include "core/geometry/ray.h"
#include "core/integrator/path_tracer.h"
#include "core/world/render_scene.h"

namespace inkray {

inline constexpr uint32_t kDirect = UINT32_MAX;

struct PerceivedSurface {
  bool hit = false;
  uint32_t object = 0;     // index into RenderScene::objects
  uint32_t identity = 0;   // RenderObject::source: strokes share their base object's
  uint32_t via = kDirect;  // identity of the first mirror or glass followed
  uint32_t material = 0;   // RenderObject::line_material: a mix keeps its id, strokes their base's
  Point3 p{0.f};
  Normal3 ng{0.f}, ns{0.f};  // facing the arriving ray
  float distance = 0.f;      // along the whole chain from the camera
  std::optional<Color> line_color;  // a material graph's line colour output here
  float line_width = 1.f;           // and its line width output
};

// Follows at most kMaxPerceivedChain specular vertices; u_mix resolves mix
// materials. `first`, when given, is the ray's own intersection, already
// traced. Adds the rays it traced to *rays.
inline constexpr int kMaxPerceivedChain = 8;
PerceivedSurface find_perceived_surface(const RenderScene& scene, Ray ray, float u_mix, uint32_t* rays,
                                        const PrimaryHit* first = nullptr);

}  // namespace inkray
