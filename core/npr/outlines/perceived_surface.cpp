#include "core/npr/outlines/perceived_surface.h"

#include "core/base/overloaded.h"
#include "core/materials/fresnel.h"

#include <cmath>
#include <optional>

namespace inkray {
namespace {

// Where a line-finding ray goes on past a specular surface.
struct Continuation {
  Vec3 direction{0.f};
  float blur = 0.f;  // angular spread of the surface's lobe around `direction`, radians
};

// The direction a line-finding ray continues in past a specular surface, or
// nullopt where the surface is what is seen. A GGX lobe of roughness alpha
// tilts microfacet normals by about alpha radians: a reflection spreads by
// twice that, a refraction by |1 - 1/eta| times it (the deflection of a ray
// through a tilted interface near normal incidence).
std::optional<Continuation> continue_through(const Material& material, const SurfaceInteraction& si,
                                             const Vec3& wo) {
  using Next = std::optional<Continuation>;
  return std::visit(Overloaded{
                        // Diffuse surfaces, emitters and flat colours are what is seen.
                        [](const DiffuseMaterial&) -> Next { return std::nullopt; },
                        [&](const ConductorMaterial& c) -> Next {
                          return Continuation{reflect(wo, si.ns), 2.f * ggx_alpha(c.roughness)};
                        },
                        [&](const DielectricMaterial& d) -> Next {
                          // Glass shows mostly what is behind it: follow the refraction,
                          // and the reflection only where there is none.
                          const float alpha = ggx_alpha(d.roughness);
                          if (const auto r = refract(wo, si.ns, d.ior))
                            return Continuation{r->wt, std::abs(1.f - 1.f / d.ior) * alpha};
                          return Continuation{reflect(wo, si.ns), 2.f * alpha};
                        },
                        [](const EmissiveMaterial&) -> Next { return std::nullopt; },
                        [](const UnlitMaterial&) -> Next { return std::nullopt; },
                        [&](const TransparentMaterial&) -> Next {
                          return Continuation{-wo, 0.f};
                        },
                        [](const ToonMaterial&) -> Next { return std::nullopt; },
                        // The caller resolves mixes and graphs first.
                        [](const MixMaterial&) -> Next { return std::nullopt; },
                        [](const GraphMaterial&) -> Next { return std::nullopt; },
                    },
                    material);
}

}  // namespace

PerceivedSurface find_perceived_surface(const RenderScene& scene, Ray ray, float u_mix,
                                        const FollowLimits& limits, uint32_t* rays, const PrimaryHit* first) {
  PerceivedSurface out;
  const bool follow = limits.specular;
  const float max_blur = limits.max_blur;
  for (int chain = 0; chain <= kMaxPerceivedChain; ++chain) {
    // The centre ray's hit is the camera sample's own; other rays trace theirs.
    SurfaceInteraction traced;
    const SurfaceInteraction* hit_si = &traced;
    float length = 0.f;
    if (chain == 0 && first) {
      if (!first->hit) return out;
      hit_si = &first->si;
      length = first->distance;
    } else {
      Hit hit;
      ++*rays;
      if (!scene.world->geometry.intersect(ray, kInfinity, &hit)) return out;
      traced = scene.world->geometry.interaction(ray, hit);
      length = hit.t * glm::length(ray.d);
    }
    const SurfaceInteraction& si = *hit_si;
    const RenderObject& object = scene.world->objects[si.object];
    const Vec3 wo = -glm::normalize(ray.d);
    const uint32_t index = object.material;
    const Material* material = &scene.world->materials[index];
    const auto* graph = std::get_if<GraphMaterial>(material);
    // Most hits are on plain materials, which need no shading point: it is
    // built only for mixes and graphs, which read it.
    const float depth = out.distance + length;
    std::optional<Material> scratch;
    // A graph whose surfaces are all opaque to lines is what is seen, whatever it computes.
    if (material_flags(*material).resolves && !(graph && !graph->program->lines_pass_through)) {
      // Lines do not gather light: a graph reading it sees a fully lit surface.
      material = resolve_material(scene.world->materials, index, scene_shading_point(scene, si, wo, depth),
                                  u_mix, scratch.emplace())
                     .material;
      if (!material) return out;
    }
    out.distance = depth;

    std::optional<Continuation> next;
    if (follow && !object.lines.stop_lines) {
      next = continue_through(*material, si, wo);
      if (next && out.blur + next->blur > max_blur) next.reset();  // too rough: the surface is what is seen
    }
    if (next && chain == kMaxPerceivedChain) {
      out.lost = true;  // still bouncing: no surface within reach
      return out;
    }
    if (!next) {
      out.hit = true;
      out.object = si.object;
      out.identity = object.source;
      out.material = object.line_material;
      out.patch = crease_patch(scene, si.object, si.prim);
      out.p = si.p;
      const bool flip = glm::dot(wo, si.ng) < 0.f;
      out.ng = flip ? -si.ng : si.ng;
      out.ns = flip ? -si.ns : si.ns;
      if (std::holds_alternative<GraphMaterial>(scene.world->materials[index])) {
        const SurfaceOverrides o = material_overrides(scene.world->materials, index,
                                                      scene_shading_point(scene, si, wo, depth), u_mix);
        out.line_color = o.line_color;
        out.line_width = o.line_width.value_or(1.f);
      }
      return out;
    }
    if (out.via == kDirect) out.via = object.source;
    out.chain_object[size_t(chain)] = object.source;
    out.chain_dir[size_t(chain)] = glm::normalize(next->direction);
    out.chain_length = chain + 1;
    out.blur += next->blur;
    const Normal3 side = glm::dot(next->direction, si.ng) > 0.f ? si.ng : -si.ng;
    ray = spawn_ray(si, side, next->direction);  // at the hit's instant: the sample's
  }
  return out;
}

}  // namespace inkray
