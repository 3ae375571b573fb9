// Toon shading: the light level at a hit and the toon colour it selects.
//
// Light level. Each light l gives, at the hit, the irradiance it delivers
// (E_l = N.L-weighted, shadowed) and its reference irradiance E_ref_l: what a
// surface facing it, unshadowed, would receive (for a spot, on its axis, so the
// cone's falloff darkens the bands). The level is
//     L = clamp(sum_l lum(E_l) / max_l lum(E_ref_l), 0, 1),
// i.e. light relative to the brightest light here. With one light of any type
// and strength L is exactly N.L times visibility (times a spot's falloff), so
// `threshold` is the cosine where the terminator sits (0.5: 60 degrees from the
// light) whatever the light's intensity or distance. A weaker fill light adds in proportion to its
// strength (a fill at 30% of the key lifts its side to at most 0.3), and two
// equal lights widen the lit area, as an artist expects. Normalising by the sum
// of all lights instead would dim one side whenever a second light is added;
// dividing by (1 + E) would make the bands depend on absolute exposure.
//
// Sampled lights. Delta lights are exact. An area light contributes one sample
// with its own shadow ray, from its own stratified dimension, and the level is
// quantised per sample. The render then converges to the average of clean band
// images: inside a penumbra or across a large light's terminator the bands mix
// in proportion to the light's visible part, which is an anti-aliased band edge,
// not the grey smear that quantising a noisy average would give. One ray per
// light keeps the cost proportional to the light count (toon scenes have few).
//
// The environment. Its irradiance for the normal is exact (closed form for the
// constant and gradient skies), and it counts as a light of `environment` times
// its strength, received and reference alike. At full weight a sky as bright as
// the key light lifts every side to nearly the full level and washes the bands
// out, so the default is 0.25: the sky lifts and tints the shadow side a little,
// as a fill light would, and the key light places the bands. At 0 the sky adds
// nothing (the level is that of a scene without it); in a scene lit by the sky
// alone any weight above 0 gives the same bands, the level being relative to the
// brightest light. Unshadowed by default, so it adds no noise to the band edges
// it moves. With `environment_shadows` one cosine-weighted shadow ray per sample
// (from the toon block, like an area light's) decides whether the sky counts for
// that sample, and the level is quantised per sample as above: the bands converge
// to their average over the visible part of the hemisphere, like ambient
// occlusion (exact for a constant sky; a gradient sky's occluded part is weighted
// by the cosine, not by its radiance).
#include "core/integrator/toon_shading.h"

#include "core/base/overloaded.h"
#include "core/geometry/ray.h"
#include "core/integrator/light_sampling.h"
#include "core/math/frame.h"
#include "core/sampling/warp.h"

#include <cmath>
#include <optional>
#include <vector>

namespace inkray {
namespace {

struct LightTerm {
  Color received{0.f};   // N.L-weighted irradiance with visibility
  Color reference{0.f};  // unshadowed irradiance at normal incidence
  Vec3 wi{0.f};
  bool highlight = false;  // lit and may place a specular band (not the sky)
};

// Integral over the sphere of max(0, a.w) max(0, b.w) for unit a, b at angle theta.
float clamped_cosine_product(float cos_theta) {
  const float c = glm::clamp(cos_theta, -1.f, 1.f);
  return (2.f / 3.f) * ((kPi - std::acos(c)) * c + safe_sqrt(1.f - c * c));
}

// Unshadowed irradiance from the sky on a surface with normal n, in closed form:
// the sky is horizon + (zenith - horizon) max(0, y) + (nadir - horizon) max(0, -y).
Color sky_irradiance(const EnvironmentLight& env, float n_y) {
  return kPi * env.horizon + (env.zenith - env.horizon) * clamped_cosine_product(n_y) +
         (env.nadir - env.horizon) * clamped_cosine_product(-n_y);
}

// The sky's exact irradiance for the normal, weighted by the material's
// `environment`; with its shadows on, `u` picks the one direction that decides
// whether this sample sees the sky. Its reference is a surface facing its
// brightest part.
LightTerm environment_term(const RenderScene& scene, const EnvironmentLight& env, const ToonMaterial& m,
                           const ToonHit& hit, Vec2 u, uint32_t* rays) {
  LightTerm t;
  if (!(m.environment > 0.f)) return t;
  t.reference = sky_irradiance(env, 1.f);
  for (float n_y : {-1.f, 0.f}) {
    const Color e = sky_irradiance(env, n_y);
    if (luminance(e) > luminance(t.reference)) t.reference = e;
  }
  t.reference *= m.environment;
  if (m.environment_shadows) {
    const Vec3 wi = Frame::from_z(hit.ns).to_world(sample_cosine_hemisphere(u));
    if (!(glm::dot(hit.ref.n, wi) > 0.f)) return t;  // into the surface itself
    ++*rays;
    Ray shadow = spawn_ray(hit.ref.p, hit.ref.p_error, hit.ref.n, wi);
    shadow.time = hit.si->time;
    if (scene.world->geometry.occluded(shadow, kInfinity)) return t;
  }
  t.received = m.environment * glm::max(sky_irradiance(env, hit.ns.y), Color(0.f));
  return t;
}

// A light sampled for its direction: `reference`, when given, is what a surface facing
// it would receive, else the sample's own unshadowed irradiance is.
LightTerm sampled_term(const RenderScene& scene, const Light& light, const ToonHit& hit, Vec2 u,
                       uint32_t* rays, std::optional<Color> reference) {
  LightTerm t;
  auto ls = sample_light(*scene.world, light, hit.ref, u);
  if (reference) {
    t.reference = *reference;
  } else if (ls) {
    t.reference = ls->radiance / ls->pdf;
  }
  if (!ls) return t;
  const float cos_n = glm::dot(hit.ns, ls->wi);
  // Light below the geometric surface would need a shadow ray through it.
  if (!(cos_n > 0.f) || !(glm::dot(hit.ref.n, ls->wi) > 0.f)) return t;
  ++*rays;
  ls->shadow_ray.time = hit.si->time;  // lights stand at the frame; the rest at the hit's instant
  if (scene.world->geometry.occluded(ls->shadow_ray, ls->shadow_t_max)) return t;
  t.wi = ls->wi;
  t.received = (ls->radiance / ls->pdf) * cos_n;
  t.highlight = true;
  return t;
}

// Every kind of light, with no catch-all (core/lights/light.h, LightTraits): the sky in
// closed form, a spot against the light on its axis (so its cone's falloff reads as a
// falling light level), the others against what their sample delivers.
LightTerm light_term(const RenderScene& scene, const Light& light, const ToonMaterial& m, const ToonHit& hit,
                     Vec2 u, uint32_t* rays) {
  const auto sampled = [&](std::optional<Color> reference = std::nullopt) {
    return sampled_term(scene, light, hit, u, rays, reference);
  };
  return std::visit(
      Overloaded{
          [&](const EnvironmentLight& env) { return environment_term(scene, env, m, hit, u, rays); },
          [&](const SpotLight& spot) {
            const Vec3 d = spot.position - hit.ref.p;
            return sampled(spot.intensity / std::max(glm::dot(d, d), 1e-20f));
          },
          [&](const PointLight&) { return sampled(); },
          [&](const DirectionalLight&) { return sampled(); },
          [&](const MeshAreaLight&) { return sampled(); },
          [&](const RectAreaLight&) { return sampled(); },
          [&](const SphereAreaLight&) { return sampled(); },
      },
      light);
}

float ramp_v(const ToonMaterial& m, const ToonHit& hit) {
  switch (m.ramp_axis) {
    case ToonRampAxis::depth: {
      const float span = m.ramp_far - m.ramp_near;
      return span != 0.f ? glm::clamp((hit.view_depth - m.ramp_near) / span, 0.f, 1.f) : 0.f;
    }
    case ToonRampAxis::facing:
      return glm::clamp(glm::dot(hit.ns, hit.wo), 0.f, 1.f);
    default:
      return 0.5f;
  }
}

}  // namespace

ToonShade toon_shade(const RenderScene& scene, const ToonMaterial& m, const ToonHit& hit,
                     const Sampler& sampler, uint32_t* rays) {
  const SurfaceInteraction& si = *hit.si;
  thread_local std::vector<LightTerm> terms;  // no allocation per hit
  terms.clear();
  float reference_max = 0.f;
  float received = 0.f;
  Color tint_sum(0.f);
  for (size_t l = 0; l < scene.world->lights.size(); ++l) {
    const Light& light = scene.world->lights[l];
    const bool sampled = std::holds_alternative<MeshAreaLight>(light) ||
                         std::holds_alternative<RectAreaLight>(light) ||
                         std::holds_alternative<SphereAreaLight>(light) ||
                         (std::holds_alternative<EnvironmentLight>(light) && m.environment_shadows);
    const LightTerm t = light_term(
        scene, light, m, hit, sampled ? sampler.get_pair(toon_light_pair(hit.depth, l)) : Vec2(0.5f), rays);
    if (!is_finite(t.reference) || !is_finite(t.received)) continue;
    reference_max = std::max(reference_max, luminance(t.reference));
    received += luminance(t.received);
    // Each light's own colour, brightest channel 1, weighted by the light it gives:
    // a mean of fixed colours varies smoothly where lights of different hue
    // overlap (normalising the summed colour would crease where channels swap).
    if (max_component(t.received) > 0.f)
      tint_sum += luminance(t.received) * t.received / max_component(t.received);
    terms.push_back(t);
  }

  ToonLightInput in;
  if (reference_max > 0.f) in.level = glm::clamp(received / reference_max, 0.f, 1.f);
  if (received > 0.f) in.tint = tint_sum / received;
  in.ramp_v = ramp_v(m, hit);
  const Color base = si.color * texture_eval(m.color, si.uv);
  Color out = toon_base_color(m, base, in);
  // A ramp has no hard steps in its level; bands do.
  const bool banded = !m.ramp_image && !(m.ramp && !m.ramp->empty());
  float band = banded ? toon_band_level(m, glm::clamp(in.level, 0.f, 1.f)) : 0.f;

  if (m.specular && reference_max > 0.f) {
    float coverage = 0.f;
    for (const LightTerm& t : terms) {
      if (!t.highlight) continue;
      const Vec3 h = glm::normalize(t.wi + hit.wo);
      // A weak light makes a smaller highlight, and none if it is weak enough.
      coverage = std::max(
          coverage, toon_specular_coverage(m, glm::dot(hit.ns, h), luminance(t.reference) / reference_max));
    }
    out += coverage * m.specular_color;
    band += 2.f * coverage;
  }
  // The rim is not modulated by the light level: it is a stylised back light that
  // separates a shape from what is behind it, which matters most on the dark side.
  const float rim = toon_rim_coverage(m, glm::dot(hit.ns, hit.wo));
  out += rim * m.rim_color;
  band += 4.f * rim;
  return {is_finite(out) ? out : Color(0.f), reference_max, band};
}

}  // namespace inkray
