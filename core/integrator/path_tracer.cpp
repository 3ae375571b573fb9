// The path loop. Toon surfaces show their cel look to the camera and through
// mirrors and glass, and scatter as Lambertians of their colour for everything
// else (see toon_shading.h); mixes are resolved to one side per sample.
#include "core/integrator/path_tracer.h"

#include "core/base/overloaded.h"
#include "core/integrator/toon_shading.h"
#include "core/integrator/light_inputs.h"
#include "core/integrator/light_sampling.h"
#include "core/math/frame.h"
#include "core/sampling/warp.h"

#include <utility>

namespace inkray {
namespace {

// Sample dimensions: pairs 0-1 belong to the camera (see render_session.cpp);
// each bounce owns four pairs, so a decision always draws the same dimension
// whatever came before: (light choice, lobe choice), light position, direction,
// (mix choice, unused). Toon lighting has its own block (toon_shading.h).
constexpr uint32_t kCameraPairs = 2;
constexpr uint32_t kPairsPerBounce = 4;
static_assert(kFirstHitMixPair == kCameraPairs + 3, "the mix choice is the fourth pair of bounce 0");

struct PathState {
  Color beta{1.f};
  float eta_scale = 1.f;
  bool after_delta = true;     // the camera "samples" its ray with a delta: no MIS on the first hit
  bool specular_chain = true;  // only delta bounces since the camera: toon surfaces show their look
  bool skip_lights =
      false;  // the ray gathers a toon's indirect light: emission of sampled lights is its bands'
  float prev_pdf = 0.f;
  LightReference prev_ref;
  Ray ray;
  float path_length = 0.f;
};

void record_first_hit(const RenderScene& scene, const Camera& camera, const SurfaceInteraction& si,
                      const Material& resolved, FirstHit* out) {
  const RenderObject& obj = scene.world->objects[si.object];
  out->object = int(obj.source);
  out->material = int(obj.material);            // a mix keeps its own id, so material lines do not flicker
  out->albedo = material_albedo(resolved, si);  // a mix's side per sample: averages to the blend
  out->normal = si.ns;
  out->depth = glm::dot(si.p - camera.origin(), camera.forward());
}

// MIS weight for emission found by a BSDF-sampled ray.
float emitter_weight(const RenderScene& scene, int light, const PathState& st, const Vec3& dir,
                     const SurfaceInteraction& on_light) {
  if (st.after_delta || light < 0) return 1.f;
  const float pdf = scene.world->light_selection.pmf(size_t(light)) *
                    light_pdf(*scene.world, scene.world->lights[size_t(light)], st.prev_ref, dir, on_light);
  return power_heuristic(st.prev_pdf, pdf);
}

void add_escaped(const RenderScene& scene, const PathState& st, PathResult& result) {
  if (st.skip_lights && scene.world->environment_light >= 0) return;
  const Color le = scene.world->environment.radiance(st.ray.d);
  if (is_black(le)) return;
  const SurfaceInteraction nowhere;
  result.radiance +=
      st.beta * le * emitter_weight(scene, scene.world->environment_light, st, st.ray.d, nowhere);
}

// Next-event estimation: one light chosen by power, MIS-weighted against the BSDF.
// Lights stand where the frame has them; the shadow ray sees the rest at the
// path's instant (docs/architecture.md, "Motion blur").
void add_direct_light(const RenderScene& scene, const Bsdf& bsdf, const Frame& frame, const Vec3& wo_local,
                      const LightReference& ref, float u_light, Vec2 u_position, const PathState& st,
                      PathResult& result) {
  float pmf = 0.f;
  const size_t li = scene.world->light_selection.sample(u_light, &pmf);
  auto ls = sample_light(*scene.world, scene.world->lights[li], ref, u_position);
  if (!ls) return;
  const Vec3 wi_local = frame.to_local(ls->wi);
  const Color f = bsdf_eval(bsdf, wo_local, wi_local) * std::abs(wi_local.z);
  if (is_black(f)) return;
  ++result.rays;
  ls->shadow_ray.time = st.ray.time;
  if (scene.world->geometry.occluded(ls->shadow_ray, ls->shadow_t_max)) return;
  const float light_pdf_total = pmf * ls->pdf;
  const float w = ls->is_delta ? 1.f : power_heuristic(light_pdf_total, bsdf_pdf(bsdf, wo_local, wi_local));
  result.radiance += st.beta * f * ls->radiance * (w / light_pdf_total);
}

// Samples the BSDF for the next ray and applies Russian roulette; false ends the path.
bool scatter(const Sampler& sampler, const Bsdf& bsdf, const Frame& frame, const Vec3& wo_local,
             const SurfaceInteraction& si, const LightReference& ref, float u_lobe, Vec2 u, int depth,
             PathState& st) {
  const auto bs = bsdf_sample(bsdf, wo_local, u_lobe, u);
  if (!bs) return false;
  st.beta *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
  st.after_delta = bs->is_delta;
  st.specular_chain = st.specular_chain && bs->is_delta;
  st.prev_pdf = bs->pdf;
  st.prev_ref = ref;
  if (bs->is_transmission) st.eta_scale *= sqr(bs->eta);
  st.ray = spawn_ray(si, ref.n, frame.to_world(bs->wi));

  // Russian roulette on throughput, undoing the radiance scaling of refraction
  // so paths inside glass are not killed for it (pbrt-v4).
  const float rr = max_component(st.beta * st.eta_scale);
  if (rr < 1.f && depth > 1) {
    const float q = std::max(0.f, 1.f - rr);
    if (sampler.get_hashed(uint32_t(depth)) < q) return false;
    st.beta /= 1.f - q;
  }
  return !is_black(st.beta);
}

// One hit of the path, seen from the side the ray arrived on.
struct Bounce {
  const SurfaceInteraction& si;
  Vec3 wo;     // towards the viewer, normalised
  Normal3 ns;  // faces the viewer unless the surface transmits
  LightReference ref;
  uint32_t pairs;  // the first sample pair of this bounce
  int depth;
};

// Emission of the emitter the path ended on, weighted against light sampling.
void add_emission(const RenderScene& scene, const Bounce& b, const Material& material, bool skip_lights,
                  const PathState& st, PathResult& result) {
  const int light = scene.world->objects[b.si.object].light;
  const Color le = material_emission(material, b.si, glm::dot(b.wo, b.si.ng));
  if (!is_black(le) && !(skip_lights && light >= 0))
    result.radiance += st.beta * le * emitter_weight(scene, light, st, st.ray.d, b.si);
}

// Next-event estimation and a sampled bounce through the material's BSDF; false ends the path.
bool continue_by_bsdf(const RenderScene& scene, const Sampler& sampler, const Bounce& b,
                      const Material& material, PathState& st, PathResult& result) {
  if (b.depth >= scene.sampling.max_depth) return false;
  const std::optional<Bsdf> bsdf = material_bsdf(material, b.si);
  if (!bsdf) return false;
  const Vec2 u_choice = sampler.get_pair(b.pairs);  // x: which light, y: which lobe
  const Frame frame = Frame::from_z(b.ns);
  const Vec3 wo_local = frame.to_local(b.wo);
  if (!scene.world->light_selection.empty() && !bsdf_is_delta(*bsdf))
    add_direct_light(scene, *bsdf, frame, wo_local, b.ref, u_choice.x, sampler.get_pair(b.pairs + 1), st,
                     result);
  return scatter(sampler, *bsdf, frame, wo_local, b.si, b.ref, u_choice.y, sampler.get_pair(b.pairs + 2),
                 b.depth, st);
}

// A toon surface showing its cel look; false ends the path. When it receives
// indirect light the path goes on to gather it.
bool shade_toon(const RenderScene& scene, const Sampler& sampler, const Bounce& b, const ToonMaterial& toon,
                const Material& material, PathState& st, PathResult& result) {
  const ToonHit th{&b.si, b.wo, b.ns, b.ref, st.path_length, b.depth};
  const ToonShade shade = toon_shade(scene, toon, th, sampler, &result.rays);
  result.radiance += st.beta * shade.radiance;
  if (st.specular_chain && result.band < 0.f) result.band = shade.band;
  // Indirect light adds to the bands; the light the bands show is not gathered again.
  if (!st.specular_chain || !toon.receive_indirect || b.depth >= scene.sampling.max_depth) return false;
  const Frame frame = Frame::from_z(b.ns);
  const Bsdf lambert = *material_bsdf(material, b.si);
  if (!scatter(sampler, lambert, frame, frame.to_local(b.wo), b.si, b.ref, sampler.get_pair(b.pairs).y,
               sampler.get_pair(b.pairs + 2), b.depth, st))
    return false;
  // The bands show colour * E / E_ref whatever the lights' strength; indirect
  // irradiance is measured in the same unit, so brighter lights do not wash
  // the bands out with bounce light.
  if (shade.reference > 0.f) st.beta /= shade.reference;
  st.skip_lights = true;
  return true;
}

}  // namespace

PathResult trace_path(const RenderScene& scene, const Camera& camera, const Ray& camera_ray,
                      const Sampler& sampler, FirstHit* first_hit, PrimaryHit* primary) {
  PathResult result;
  PathState st;
  st.ray = camera_ray;

  for (int depth = 0;; ++depth) {
    Hit hit;
    ++result.rays;
    // After a diffuse or glossy bounce the ray gathers indirect light, which may skip paint.
    if (!scene.world->geometry.intersect(st.ray, kInfinity, &hit,
                                         st.specular_chain ? RayKind::camera : RayKind::indirect)) {
      add_escaped(scene, st, result);
      break;
    }
    const SurfaceInteraction si = scene.world->geometry.interaction(st.ray, hit);
    const Vec3 wo = -glm::normalize(st.ray.d);
    st.path_length += hit.t * glm::length(st.ray.d);
    if (depth == 0 && primary) *primary = {true, si, st.path_length};
    const uint32_t pairs = kCameraPairs + kPairsPerBounce * uint32_t(depth);
    const bool skip_lights = std::exchange(st.skip_lights, false);

    // Mixes and graphs decide per sample which surface this is (material.h).
    const uint32_t material_index = scene.world->objects[si.object].material;
    const Material* chosen = &scene.world->materials[material_index];
    Material scratch;
    if (material_flags(*chosen).resolves) {
      ShadingPoint sp = scene_shading_point(scene, si, wo, st.path_length);
      if (material_uses_light(scene.world->materials, material_index))
        gather_light_inputs(scene, LightReference{si.p, si.p_error, sp.ng}, si.time, sp, &result.rays);
      const ResolvedMaterial r = resolve_material(scene.world->materials, material_index, sp,
                                                  sampler.get_pair(pairs + 3).x, scratch);
      if (!r.material) break;
      chosen = r.material;
      st.beta *= r.weight;
    }
    const Material& material = *chosen;
    if (depth == 0 && first_hit) {
      record_first_hit(scene, camera, si, material, first_hit);
    } else if (first_hit && st.specular_chain) {
      // Seen in a mirror or through glass: the surface seen is what the denoiser's guide
      // should describe (its texture, its shape), so its albedo and normal replace
      // those of the mirror; the ids and depth stay the first hit's.
      first_hit->albedo = material_albedo(material, si);
      first_hit->normal = si.ns;
    }

    // Opaque surfaces are two-sided: face them towards the viewer. Surfaces
    // that transmit keep their orientation, which tells inside from outside.
    Normal3 ns = si.ns, ng = si.ng;
    if (!material_has_transmission(material) && glm::dot(wo, ng) < 0.f) {
      ns = -ns;
      ng = -ng;
    }
    const Bounce b{si, wo, ns, LightReference{si.p, si.p_error, ng}, pairs, depth};

    // One case per kind of material: a new kind does not compile until the path
    // loop says what it does there. False ends the path.
    const auto by_bsdf = [&] { return continue_by_bsdf(scene, sampler, b, material, st, result); };
    const bool go_on = std::visit(
        Overloaded{
            [&](const DiffuseMaterial&) { return by_bsdf(); },
            [&](const ConductorMaterial&) { return by_bsdf(); },
            [&](const DielectricMaterial&) { return by_bsdf(); },
            [&](const EmissiveMaterial&) {
              add_emission(scene, b, material, skip_lights, st, result);
              return false;  // nothing scatters off an emitter
            },
            [&](const UnlitMaterial& m) {
              result.radiance += st.beta * texture_eval(m.color, si.uv);  // its colour whatever the light
              return false;
            },
            [&](const TransparentMaterial&) { return by_bsdf(); },
            [&](const ToonMaterial& m) {
              // Its cel look shows directly and through mirrors and glass; light
              // bouncing off it sees a Lambertian of its colour.
              if (st.specular_chain || !m.bounce_indirect)
                return shade_toon(scene, sampler, b, m, material, st, result);
              return by_bsdf();
            },
            // resolve_material above never returns a mix or a graph.
            [](const MixMaterial&) { return false; },
            [](const GraphMaterial&) { return false; },
        },
        material);
    if (!go_on) break;
  }
  if (first_hit) first_hit->band = result.band;
  return result;
}

}  // namespace inkray
