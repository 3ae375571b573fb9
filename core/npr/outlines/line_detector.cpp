#include "core/npr/outlines/line_detector.h"

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
  } else if (!occlusion && cos_normals < setup.crease_cos) {
    found |= bit(LineType::crease);
  }
  if (c.material != s.material) found |= bit(LineType::material);
  if (std::abs(c.distance - s.distance) / nearest > setup.depth_jump) found |= bit(LineType::depth);
  return found;
}

// The line width at this sample in pixels, before the per-type multipliers.
float sample_width_px(const RenderScene& scene, const LineSetup& setup, const Camera& camera,
                      const PerceivedSurface& centre, const Vec3& ray_dir) {
  const OutlineDesc& o = scene.outlines;
  const float distance = centre.hit ? centre.distance : setup.miss_distance;
  float width = setup.width_px;
  if (setup.world_width) {
    const float along_view = distance * std::max(glm::dot(ray_dir, camera.forward()), 1e-3f);
    width = camera.world_to_pixels(o.width, along_view);
  }
  if (o.distance_falloff > 0.f && distance > o.falloff_start && o.falloff_start > 0.f)
    width *= std::pow(o.falloff_start / distance, o.distance_falloff);
  if (centre.hit) width *= scene.objects[centre.object].lines.width_scale * centre.line_width;
  return width;
}

}  // namespace

LineSetup make_line_setup(const RenderScene& scene) {
  LineSetup s;
  const OutlineDesc& o = scene.outlines;
  if (!o.any_line()) return s;
  s.active = true;
  for (int t = 0; t < kLineTypeCount; ++t) {
    const LineStyleDesc& style = line_style(o, LineType(t));
    if (!style.enabled) continue;
    s.enabled |= bit(LineType(t));
    s.width[size_t(t)] = style.width;
    s.max_width = std::max(s.max_width, style.width);
  }
  s.rays = std::clamp(o.quality, 1, kMaxStencilRays);
  // Narrower line types share the stencil: a point of the wide disc that falls
  // inside a narrower one is a uniform point of that disc, so counting it with
  // weight (R / r)^2 keeps every type's coverage unbiased.
  for (int t = 0; t < kLineTypeCount; ++t)
    if (s.width[size_t(t)] > 0.f) s.ray_weight[size_t(t)] = sqr(s.max_width / s.width[size_t(t)]) / float(s.rays);
  const float height = scene.camera.image_height();
  s.width_px = o.unit == LineWidthUnit::pixels    ? o.width * height / o.reference_height
               : o.unit == LineWidthUnit::percent ? o.width * height / 100.f
                                                  : 0.f;
  s.world_width = o.unit == LineWidthUnit::world;
  s.miss_distance = std::max(glm::length(scene.scene_center - scene.camera.origin()), 1e-6f);
  s.crease_cos = std::cos(glm::radians(o.crease.threshold));
  s.intersection_cos = std::cos(glm::radians(kIntersectionAngle));
  s.depth_jump = o.depth.threshold;
  return s;
}

LineSample detect_lines(const RenderScene& scene, const LineSetup& setup, const Camera& camera, Vec2 film_pos,
                        Vec2 lens, const Ray& centre_ray, const PrimaryHit& primary, float u_mix,
                        const Sampler& sampler, uint32_t* rays) {
  LineSample out;
  const PerceivedSurface centre = find_perceived_surface(scene, centre_ray, u_mix, rays, &primary);
  if (centre.hit && scene.objects[centre.object].lines.exclude) return out;
  const float width = sample_width_px(scene, setup, camera, centre, centre_ray.d);
  const float pixel_angle = 1.f / camera.world_to_pixels(1.f, 1.f);
  const float radius = std::max(width * setup.max_width * kStencilRadiusPerWidth, 1e-3f);
  const std::array<float, kLineTypeCount>& weight = setup.ray_weight;

  for (int k = 0; k < setup.rays; ++k) {
    const Vec2 u = sampler.get_pair(kOutlinePairBlock + uint32_t(k));
    const Vec2 offset = radius * sample_uniform_disk_concentric(u);
    const float reach = glm::length(offset) / radius * setup.max_width;  // in width multipliers
    uint32_t wanted = 0;
    for (int t = 0; t < kLineTypeCount; ++t)
      if ((setup.enabled & bit(LineType(t))) && reach <= setup.width[size_t(t)]) wanted |= bit(LineType(t));
    if (!wanted) continue;
    const PerceivedSurface s =
        find_perceived_surface(scene, camera.generate_ray(film_pos + offset, lens), u_mix, rays);
    if (s.hit && scene.objects[s.object].lines.exclude) continue;
    // An occlusion moves the surface much further off its tangent plane than a
    // smooth surface bends within the stencil: 2% of the distance, or twice
    // the stencil's angular radius for wide lines, where a crease would
    // otherwise pass for an occlusion.
    const float occlusion_jump = std::max(kMinOcclusionJump, 2.f * radius * pixel_angle);
    const uint32_t found = breaks(centre, s, setup, occlusion_jump) & wanted;
    if (!found) continue;
    float strongest = 0.f;
    for (int t = 0; t < kLineTypeCount; ++t)
      if (found & bit(LineType(t))) {
        out.coverage[size_t(t)] += weight[size_t(t)];
        strongest = std::max(strongest, weight[size_t(t)]);
      }
    out.weight += strongest;
    // The line belongs to the nearer surface of the two.
    const PerceivedSurface& owner = !s.hit || (centre.hit && centre.distance <= s.distance) ? centre : s;
    const LineOverride& lo = scene.objects[owner.object].lines;
    if (lo.override_color || owner.line_color) {
      out.override_weight += strongest;
      out.override_color += strongest * (lo.override_color ? lo.color : *owner.line_color);
    }
  }
  return out;
}

}  // namespace inkray
