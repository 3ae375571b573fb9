#include "core/integrator/path_tracer.h"

#include "core/lights/light_sampling.h"
#include "core/math/frame.h"
#include "core/sampling/warp.h"

namespace inkray {
namespace {

// Sample dimensions: pairs 0-1 belong to the camera (see render_session.cpp);
// each bounce owns three pairs, so a decision always draws the same dimension
// whatever came before: (light choice, lobe choice), light position, direction.
constexpr uint32_t kCameraPairs = 2;
constexpr uint32_t kPairsPerBounce = 3;

void record_first_hit(const RenderScene& scene, const SurfaceInteraction& si, FirstHit* out) {
  const RenderObject& obj = scene.objects[si.object];
  out->object = int(obj.source);
  out->material = int(obj.material);
  out->albedo = material_albedo(scene.materials[obj.material], si);
  out->normal = si.ns;
  out->depth = glm::dot(si.p - scene.camera.origin(), scene.camera.forward());
}

// MIS weight for emission found by a BSDF-sampled ray.
float emitter_weight(const RenderScene& scene, int light, bool after_delta, float bsdf_pdf,
                     const LightReference& from, const Vec3& dir, const SurfaceInteraction& on_light) {
  if (after_delta || light < 0) return 1.f;
  const float pdf = scene.light_selection.pmf(size_t(light)) *
                    light_pdf(scene, scene.lights[size_t(light)], from, dir, on_light);
  return power_heuristic(bsdf_pdf, pdf);
}

}  // namespace

PathResult trace_path(const RenderScene& scene, const Ray& camera_ray, const Sampler& sampler, FirstHit* first_hit) {
  PathResult result;
  Color beta(1.f);
  float eta_scale = 1.f;
  bool after_delta = true;  // the camera "samples" its ray with a delta: no MIS on the first hit
  float prev_pdf = 0.f;
  LightReference prev_ref;
  Ray ray = camera_ray;
  const bool sample_lights = !scene.light_selection.empty();

  for (int depth = 0;; ++depth) {
    Hit hit;
    ++result.rays;
    if (!scene.geometry.intersect(ray, kInfinity, &hit)) {
      const Color le = scene.environment.radiance(ray.d);
      if (!is_black(le)) {
        const SurfaceInteraction nowhere;
        result.radiance += beta * le *
                           emitter_weight(scene, scene.environment_light, after_delta, prev_pdf, prev_ref, ray.d,
                                          nowhere);
      }
      break;
    }
    const SurfaceInteraction si = scene.geometry.interaction(ray, hit);
    const Material& material = scene.material_of(si.object);
    const Vec3 wo = -glm::normalize(ray.d);
    if (depth == 0 && first_hit) record_first_hit(scene, si, first_hit);

    if (std::holds_alternative<EmissiveMaterial>(material)) {
      const Color le = material_emission(material, si, glm::dot(wo, si.ng));
      if (!is_black(le))
        result.radiance += beta * le *
                           emitter_weight(scene, scene.objects[si.object].light, after_delta, prev_pdf, prev_ref,
                                          ray.d, si);
      break;
    }
    if (const auto* unlit = std::get_if<UnlitMaterial>(&material)) {
      result.radiance += beta * texture_eval(unlit->color, si.uv);
      break;
    }
    if (depth >= scene.settings.max_depth) break;
    const std::optional<Bsdf> bsdf = material_bsdf(material, si);
    if (!bsdf) break;

    // Opaque surfaces are two-sided: face them towards the viewer. Surfaces
    // that transmit keep their orientation, which tells inside from outside.
    Normal3 ns = si.ns, ng = si.ng;
    if (!material_has_transmission(material) && glm::dot(wo, ng) < 0.f) {
      ns = -ns;
      ng = -ng;
    }
    const Frame frame = Frame::from_z(ns);
    const Vec3 wo_local = frame.to_local(wo);
    const LightReference ref{si.p, si.p_error, ng};

    const uint32_t pairs = kCameraPairs + kPairsPerBounce * uint32_t(depth);
    const Vec2 u_choice = sampler.get_pair(pairs);  // x: which light, y: which lobe

    if (sample_lights && !bsdf_is_delta(*bsdf)) {
      float pmf = 0.f;
      const size_t li = scene.light_selection.sample(u_choice.x, &pmf);
      if (const auto ls = sample_light(scene, scene.lights[li], ref, sampler.get_pair(pairs + 1))) {
        const Vec3 wi_local = frame.to_local(ls->wi);
        const Color f = bsdf_eval(*bsdf, wo_local, wi_local) * std::abs(wi_local.z);
        if (!is_black(f)) {
          ++result.rays;
          if (!scene.geometry.occluded(ls->shadow_ray, ls->shadow_t_max)) {
            const float light_pdf_total = pmf * ls->pdf;
            const float w = ls->is_delta ? 1.f : power_heuristic(light_pdf_total, bsdf_pdf(*bsdf, wo_local, wi_local));
            result.radiance += beta * f * ls->radiance * (w / light_pdf_total);
          }
        }
      }
    }

    const auto bs = bsdf_sample(*bsdf, wo_local, u_choice.y, sampler.get_pair(pairs + 2));
    if (!bs) break;
    beta *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
    after_delta = bs->is_delta;
    prev_pdf = bs->pdf;
    prev_ref = ref;
    if (bs->is_transmission) eta_scale *= sqr(bs->eta);
    ray = spawn_ray(si.p, si.p_error, ng, frame.to_world(bs->wi));

    // Russian roulette on throughput, undoing the radiance scaling of refraction
    // so paths inside glass are not killed for it (pbrt-v4).
    const float rr = max_component(beta * eta_scale);
    if (rr < 1.f && depth > 1) {
      const float q = std::max(0.f, 1.f - rr);
      if (sampler.get_hashed(uint32_t(depth)) < q) break;
      beta /= 1.f - q;
    }
    if (is_black(beta)) break;
  }
  return result;
}

}  // namespace inkray
