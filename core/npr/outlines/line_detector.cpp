#include "core/npr/outlines/line_detector.h"

#include "core/npr/outlines/line_gain.h"
#include "core/npr/outlines/outline_styles.h"
#include "core/npr/outlines/perceived_surface.h"
#include "core/sampling/warp.h"

#include <cmath>

namespace inkray {
namespace {

constexpr uint32_t bit(LineType t) { return 1u << uint32_t(t); }
constexpr int kMaxStencilRays = 64;
// Surfaces of two objects that meet without an occlusion draw an intersection
// line only where they are not one continuous plane (a light flush with the
// ceiling is an object boundary, not an intersection).
constexpr float kIntersectionAngle = 15.f;
constexpr float kMinOcclusionJump = 0.02f;
// Lines seen through a specular chain are drawn in full while the chain has
// widened the stencil's footprint at most kCoherentSpread times, and not at all
// beyond kIncoherentSpread (a smooth glass ball magnifies by a few times, a
// mirror ball by up to ~20 near its rim; a bumpy or faceted refractor by
// hundreds: docs/outlines.md, "Lines through mirrors and glass").
constexpr float kCoherentSpread = 8.f;
constexpr float kIncoherentSpread = 32.f;

// Which line types see a break between the centre and a stencil ray.
// `occlusion_jump`: the relative plane distance that counts as an occlusion.
uint32_t breaks(const PerceivedSurface& c, const PerceivedSurface& s, const LineSetup& setup,
                float occlusion_jump) {
  // Two misses differ only where one of them saw the sky in a mirror.
  if (!c.hit && !s.hit) return c.via == s.via ? 0 : bit(LineType::silhouette) | bit(LineType::object);
  if (c.hit != s.hit) return bit(LineType::silhouette);
  const float nearest = std::max(std::min(c.distance, s.distance), 1e-20f);
  // Distance of each point from the other's tangent plane: zero along a
  // continuous surface (however grazing), large across an occlusion.
  const Vec3 d = s.p - c.p;
  const float plane_jump = std::max(std::abs(glm::dot(d, c.ng)), std::abs(glm::dot(d, s.ng))) / nearest;
  const bool occlusion = plane_jump > occlusion_jump;
  const bool same_object = c.identity == s.identity && c.via == s.via;
  const float cos_normals = glm::dot(c.ns, s.ns);

  uint32_t found = 0;
  if (occlusion) found |= bit(LineType::silhouette);
  if (!same_object) {
    found |= bit(LineType::object);
    if (!occlusion && cos_normals < setup.intersection_cos) found |= bit(LineType::intersection);
  } else if (!occlusion) {
    // On a mesh, creases are its feature edges, found once at load: a line
    // along the edge, not wherever noisy facets happen to bend between two
    // samples. Analytic shapes compare normals.
    const bool meshed = c.patch != kNoPatch && s.patch != kNoPatch;
    if (meshed ? c.patch != s.patch : cos_normals < setup.crease_cos) found |= bit(LineType::crease);
  }
  if (c.material != s.material) found |= bit(LineType::material);
  // Depth lines are occlusions with a large gap behind them: a receding plane
  // changes distance quickly but continuously and draws none.
  if (occlusion && std::abs(c.distance - s.distance) / nearest > setup.depth_jump)
    found |= bit(LineType::depth);
  return found;
}

// How many times the chains of the centre and a stencil ray have widened the
// angle between them, over the vertices where they touched the same objects,
// plus the roughness blur of the vertices followed relative to the stencil.
// theta0: the angle between the two camera rays; stencil_angle: the stencil's radius as an angle.
float pair_spread(const PerceivedSurface& c, const PerceivedSurface& s, float theta0, float stencil_angle) {
  float spread = 1.f;
  const int common = std::min(c.chain_length, s.chain_length);
  if (common > 0 && theta0 > 1e-6f * stencil_angle) {
    for (int i = 0; i < common && c.chain_object[size_t(i)] == s.chain_object[size_t(i)]; ++i)
      spread = std::max(spread, glm::length(c.chain_dir[size_t(i)] - s.chain_dir[size_t(i)]) / theta0);
  }
  return spread + 0.5f * (c.blur + s.blur) / std::max(stencil_angle, 1e-12f);
}

// The line width at this sample in pixels, before the per-type multipliers. It reads
// the compiled setup only, never the document's outline settings.
float sample_width_px(const RenderScene& scene, const LineSetup& setup, const Camera& camera,
                      const PerceivedSurface& centre, const Vec3& ray_dir) {
  const float distance = centre.hit ? centre.distance : setup.miss_distance;
  float width = setup.width_px;
  if (setup.world_width) {
    const float along_view = distance * std::max(glm::dot(ray_dir, camera.forward()), 1e-3f);
    width = camera.world_to_pixels(setup.world_width_units, along_view);
  }
  if (setup.distance_falloff > 0.f && distance > setup.falloff_start && setup.falloff_start > 0.f)
    width *= std::pow(setup.falloff_start / distance, setup.distance_falloff);
  if (centre.hit) width *= scene.world->objects[centre.object].lines.width_scale * centre.line_width;
  return width;
}

// The stencil at a sample's width (Stencil, line_detector.h). Types narrower
// than kMinLineWidthPx use a disc that wide and weigh their rays by how much
// narrower they are; the ink-preserving gain (line_gain.h) scales each type for
// the film's pixel size.
Stencil make_stencil(const LineSetup& setup, float width_px) {
  Stencil st;
  for (int t = 0; t < kLineTypeCount; ++t) {
    const float w = width_px * setup.width[size_t(t)];
    if (!(setup.enabled & bit(LineType(t))) || !(w > 0.f)) continue;
    const float drawn = std::max(w, kMinLineWidthPx);
    st.reach[size_t(t)] = drawn * kStencilRadiusPerWidth;
    st.radius = std::max(st.radius, st.reach[size_t(t)]);
  }
  for (int t = 0; t < kLineTypeCount; ++t) {
    const float r = st.reach[size_t(t)];
    if (r <= 0.f) continue;
    const float w = width_px * setup.width[size_t(t)];
    const float fade = std::min(w / kMinLineWidthPx, 1.f);
    st.weight[size_t(t)] = sqr(st.radius / r) * fade * ink_preserving_gain(setup.film_pixel / r) / kLineGain;
  }
  return st;
}

}  // namespace

float chain_coherence(float spread) {
  if (spread <= kCoherentSpread) return 1.f;
  if (spread >= kIncoherentSpread) return 0.f;
  return std::log(kIncoherentSpread / spread) / std::log(kIncoherentSpread / kCoherentSpread);
}

LineSetup make_line_setup(const OutlineDesc& o, const RenderScene& scene) {
  LineSetup s;
  if (!o.any_line() || !(o.width > 0.f)) return s;
  for (int t = 0; t < kLineTypeCount; ++t) {
    const LineStyleDesc& style = line_style(o, LineType(t));
    if (!style.enabled || !(style.width > 0.f)) continue;  // width 0 draws nothing
    s.enabled |= bit(LineType(t));
    s.width[size_t(t)] = style.width;
    s.max_width = std::max(s.max_width, style.width);
  }
  if (!s.enabled) return s;
  s.active = true;
  s.quality = std::clamp(o.quality, 1, kMaxStencilRays);
  // Adaptive sampling reads a pixel's first samples as if its lines stood still. Where
  // something moves during the shutter a line crosses a pixel at some instants only,
  // which a few probes miss: such a scene samples its lines in full, or a blurred
  // line would show as scattered dots (docs/architecture.md, "Motion blur").
  s.adaptive = o.adaptive && !moves_during_shutter(scene);
  const float height = scene.camera.image_height();
  s.width_px = o.unit == LineWidthUnit::pixels    ? o.width * height / o.reference_height
               : o.unit == LineWidthUnit::percent ? o.width * height / 100.f
                                                  : 0.f;
  s.world_width = o.unit == LineWidthUnit::world;
  s.world_width_units = o.width;
  s.distance_falloff = o.distance_falloff;
  s.falloff_start = o.falloff_start;
  // World widths vary per sample; a couple of pixels stands for them.
  s.nominal_radius_px =
      std::max(s.world_width ? 2.f : s.width_px * s.max_width, kMinLineWidthPx) * kStencilRadiusPerWidth;
  s.miss_distance = std::max(glm::length(scene.world->scene_center - scene.camera.origin()), 1e-6f);
  s.crease_cos = std::cos(glm::radians(o.crease.threshold));
  s.intersection_cos = std::cos(glm::radians(kIntersectionAngle));
  s.depth_jump = o.depth.threshold;
  s.pixel_angle = 1.f / scene.camera.world_to_pixels(1.f, 1.f);
  // The film pixel's samples spread over a box 2 * filter_radius wide, or a
  // Gaussian of sigma filter_radius / 3 (a box sqrt(12) sigma wide has its variance).
  const SampleSettings& rs = scene.sampling;
  const float footprint =
      rs.filter == PixelFilter::box ? 2.f * rs.filter_radius : rs.filter_radius / 3.f * std::sqrt(12.f);
  s.film_pixel = std::max(footprint, 1e-3f);
  s.follow = {o.in_reflections, kIncoherentSpread * s.nominal_radius_px * s.pixel_angle};
  s.at_width = make_stencil(s, s.width_px);
  return s;
}

LineSetup line_setup_for_film(const LineSetup& setup, int divisor) {
  LineSetup s = setup;
  if (!s.active || divisor <= 1) return s;
  s.film_pixel = setup.film_pixel * float(divisor);
  s.at_width = make_stencil(s, s.width_px);
  return s;
}

LineSample detect_lines(const RenderScene& scene, const LineSetup& setup, const Camera& camera, Vec2 film_pos,
                        Vec2 lens, const Ray& centre_ray, const PrimaryHit& primary, float u_mix,
                        const StencilDraw& draw, uint32_t* rays) {
  LineSample out;
  out.rays = float(draw.count);
  if (draw.count <= 0) return out;
  const PerceivedSurface centre =
      find_perceived_surface(scene, centre_ray, u_mix, setup.follow, rays, &primary);
  if (centre.lost || (centre.hit && scene.world->objects[centre.object].lines.exclude)) return out;
  const float width_px = sample_width_px(scene, setup, camera, centre, centre_ray.d);
  const Stencil stencil = width_px == setup.width_px ? setup.at_width : make_stencil(setup, width_px);
  if (stencil.radius <= 0.f) return out;
  const float stencil_angle = stencil.radius * setup.pixel_angle;
  const Vec3 centre_dir = glm::normalize(centre_ray.d);
  // An occlusion moves the surface much further off its tangent plane than a
  // smooth surface bends within the stencil: 2% of the distance, or twice
  // the stencil's angular radius for wide lines, where a crease would
  // otherwise pass for an occlusion.
  const float occlusion_jump = std::max(kMinOcclusionJump, 2.f * stencil_angle);

  const Sampler pixel(draw.x, draw.y, draw.first, draw.seed);
  for (int k = 0; k < draw.count; ++k) {
    const Vec2 u = pixel.get_pair_at(draw.first + uint32_t(k), kOutlinePairBlock);
    const Vec2 offset = stencil.radius * sample_uniform_disk_concentric(u);
    const float reach = glm::length(offset);
    uint32_t wanted = 0;
    for (int t = 0; t < kLineTypeCount; ++t)
      if (stencil.reach[size_t(t)] > 0.f && reach <= stencil.reach[size_t(t)]) wanted |= bit(LineType(t));
    if (!wanted) continue;
    // At the sample's instant: the stencil sees what its centre sees, so the lines
    // of a moving object blur with it instead of breaking.
    const Ray ray = camera.generate_ray(film_pos + offset, lens, centre_ray.time);
    const PerceivedSurface s = find_perceived_surface(scene, ray, u_mix, setup.follow, rays);
    if (s.lost || (s.hit && scene.world->objects[s.object].lines.exclude)) continue;
    const uint32_t found = breaks(centre, s, setup, occlusion_jump) & wanted;
    if (!found) continue;
    const float theta0 = glm::length(glm::normalize(ray.d) - centre_dir);
    const float coherence = chain_coherence(pair_spread(centre, s, theta0, stencil_angle));
    if (coherence <= 0.f) continue;
    float strongest = 0.f;
    for (int t = 0; t < kLineTypeCount; ++t)
      if (found & bit(LineType(t))) {
        const float w = coherence * stencil.weight[size_t(t)];
        out.coverage[size_t(t)] += w;
        strongest = std::max(strongest, w);
      }
    out.weight += strongest;
    out.hit_rays += 1.f;
    // The line belongs to the nearer surface of the two.
    const PerceivedSurface& owner = !s.hit || (centre.hit && centre.distance <= s.distance) ? centre : s;
    if (!owner.hit) continue;
    const LineOverride& lo = scene.world->objects[owner.object].lines;
    if (lo.override_color || owner.line_color) {
      out.override_weight += strongest;
      out.override_color += strongest * (lo.override_color ? lo.color : *owner.line_color);
    }
  }
  return out;
}

}  // namespace inkray
