// Lights: emissive objects, the document's lights, then the environment.
#include "core/compiler/compile_lights.h"

#include "core/integrator/light_sampling.h"

#include <cmath>

namespace inkray {
namespace {

Light compile_light(const LightDesc& desc, float scene_radius) {
  return std::visit(
      [&](const auto& l) -> Light {
        using T = std::decay_t<decltype(l)>;
        if constexpr (std::is_same_v<T, PointLightDesc>) {
          return PointLight{l.position, l.color * l.intensity};
        } else if constexpr (std::is_same_v<T, SpotLightDesc>) {
          const float cos_total = std::cos(glm::radians(l.cone_angle));
          const float cos_falloff = std::cos(glm::radians(std::min(l.falloff_angle, l.cone_angle)));
          return SpotLight{l.position, Frame::from_z(glm::normalize(l.target - l.position)),
                           l.color * l.intensity, cos_total, std::max(cos_falloff, cos_total + 1e-6f)};
        } else {
          return DirectionalLight{-glm::normalize(l.direction), l.color * l.intensity, scene_radius};
        }
      },
      desc.data);
}

// A quad as make_quad lays it out (corner, +u, +u+v, +v; two triangles) whose edges
// meet at right angles: sampled by solid angle.
std::optional<RectAreaLight> rect_light_for(const TriangleMesh& mesh, uint32_t object) {
  // (positions holds one more point: Embree's padding, triangle_mesh.h)
  const std::vector<uint32_t> quad = {0, 1, 2, 0, 2, 3};
  if (mesh.positions.size() < 4 || mesh.indices != quad) return std::nullopt;
  const Point3* p = mesh.positions.data();
  const Vec3 u = p[1] - p[0], v = p[3] - p[0];
  const float lu = glm::length(u), lv = glm::length(v);
  if (!(lu > 0.f) || !(lv > 0.f) || !std::isfinite(lu * lv)) return std::nullopt;
  const float tolerance = 1e-5f * (lu + lv);
  if (glm::length(p[2] - (p[0] + u + v)) > tolerance || std::abs(glm::dot(u, v)) > 1e-5f * lu * lv)
    return std::nullopt;
  return RectAreaLight{object, p[0], u / lu, v / lv, lu, lv};
}

// Emissive shapes become area lights when they can be sampled exactly.
std::optional<Light> area_light_for(const World& world, uint32_t object) {
  const Shape& shape = world.geometry.shape(object);
  if (const auto* mesh = std::get_if<TriangleMesh>(&shape)) {
    if (auto rect = rect_light_for(*mesh, object)) return *rect;
    std::vector<float> areas(mesh->triangle_count());
    double total = 0.0;
    for (size_t t = 0; t < areas.size(); ++t) total += areas[t] = mesh->triangle_area(t);
    if (total <= 0.0) return std::nullopt;
    return MeshAreaLight{object, DiscreteDistribution(areas), float(total)};
  }
  Point3 center;
  float radius = 0.f;
  // A sheared or unevenly scaled sphere has no simple solid-angle sampler; its
  // emission is still found by BSDF sampling, with full weight.
  if (!std::get<Sphere>(shape).is_round(&center, &radius)) return std::nullopt;
  return SphereAreaLight{object, center, radius};
}

EnvironmentLight compile_environment(const EnvironmentDesc& env, float scene_radius) {
  EnvironmentLight e;
  e.scene_radius = scene_radius;
  if (const auto* c = std::get_if<ConstantEnvironmentDesc>(&env)) {
    e.zenith = e.horizon = e.nadir = c->color;
  } else {
    const auto& g = std::get<GradientEnvironmentDesc>(env);
    e.zenith = g.zenith;
    e.horizon = g.horizon;
    e.nadir = g.nadir;
  }
  return e;
}

}  // namespace

void compile_lights(const SceneDesc& desc, World& world) {
  world.lights.clear();
  world.environment_light = -1;
  for (RenderObject& o : world.objects) o.light = -1;
  // Emissive objects, the lights list, then the environment when it is not black.
  for (uint32_t o = 0; o < world.objects.size(); ++o) {
    if (!material_is_emissive(world.material_of(o))) continue;
    if (auto light = area_light_for(world, o)) {
      world.objects[o].light = int(world.lights.size());
      world.lights.push_back(*light);
    }
  }
  for (const LightDesc& l : desc.lights) world.lights.push_back(compile_light(l, world.scene_radius));
  world.environment = compile_environment(desc.environment, world.scene_radius);
  if (max_component(world.environment.zenith + world.environment.horizon + world.environment.nadir) > 0.f) {
    world.environment_light = int(world.lights.size());
    world.lights.push_back(world.environment);
  }
  // Half by power, half uniformly: power alone all but ignores a small spot
  // next to a sun whose power counts the whole scene's area, though the spot
  // may light what the camera sees. The uniform half bounds any light's
  // variance by at most twice what power selection gives.
  std::vector<float> power;
  double total = 0.0;
  for (const Light& l : world.lights) {
    power.push_back(std::max(light_power(world, l), 0.f));
    total += power.back();
  }
  if (total > 0.0)
    for (float& p : power) p = float(0.5 * p / total + 0.5 / double(power.size()));
  world.light_selection = DiscreteDistribution(power);
}

}  // namespace inkray
