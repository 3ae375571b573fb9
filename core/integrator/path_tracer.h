// The path tracer: an iterative loop with next-event estimation, multiple
// importance sampling (power heuristic) and Russian roulette. Toon surfaces show
// their cel look along specular chains from the camera and scatter as diffuse
// surfaces otherwise; mix materials pick one side per sample.
#pragma once

#include "core/integrator/first_hit.h"
#include "core/sampling/sampler.h"
#include "core/world/render_scene.h"

namespace inkray {

struct PathResult {
  Color radiance{0.f};
  uint32_t rays = 0;  // traced rays (camera, bounce and shadow), for statistics
  float band = -1.f;  // FirstHit::band of the first toon surface along the camera's specular chain
};

// The sample pair whose x picks a mix's side at the camera ray's hit. Line
// detection reuses it, so its rays see the same side as the path.
inline constexpr uint32_t kFirstHitMixPair = 5;

// The camera ray's own intersection, for work that starts from the same hit
// (line detection) and would otherwise trace the ray again.
struct PrimaryHit {
  bool hit = false;
  SurfaceInteraction si;
  float distance = 0.f;
};

// Radiance along a ray from `camera` (the scene's, or one an editor moved
// without recompiling; the depth AOV is measured along its axis).
// `first_hit` and `primary` are filled when not null.
PathResult trace_path(const RenderScene& scene, const Camera& camera, const Ray& camera_ray,
                      const Sampler& sampler, FirstHit* first_hit, PrimaryHit* primary = nullptr);

}  // namespace inkray
