#include "core/integrator/light_inputs.h"

#include "core/integrator/light_sampling.h"

#include <algorithm>

namespace inkray {

void gather_light_inputs(const RenderScene& scene, const LightReference& ref, float time, ShadingPoint& sp,
                         uint32_t* rays) {
  sp.n_dot_l = 0.f;
  sp.shadow = 0.f;
  sp.light_color = Color(0.f);
  std::optional<LightSample> best;
  float best_luminance = 0.f;
  for (const Light& light : scene.world->lights) {
    const auto s = sample_light(*scene.world, light, ref, Vec2(0.5f));
    if (!s) continue;
    const float l = luminance(s->radiance);
    if (l > best_luminance) best_luminance = l, best = s;
  }
  if (!best) return;
  sp.n_dot_l = std::max(0.f, glm::dot(sp.ns, best->wi));
  sp.light_color = best->radiance / std::max(max_component(best->radiance), 1e-20f);
  ++*rays;
  best->shadow_ray.time = time;
  sp.shadow = scene.world->geometry.occluded(best->shadow_ray, best->shadow_t_max) ? 0.f : 1.f;
}

}  // namespace inkray
