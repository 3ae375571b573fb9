#include "core/compiler/compile.h"

#include "core/lights/light_sampling.h"
#include "core/compiler/compile_materials.h"
#include "core/compiler/compile_strokes.h"
#include "core/document/memory_budget.h"
#include "core/geometry/obj_loader.h"
#include "core/document/scene_checks.h"

#include <cmath>
#include <cstdio>
#include <map>

namespace inkray {
namespace {

std::optional<Shape> compile_shape(const ObjectDesc& obj, const std::filesystem::path& base, std::string* error) {
  const Transform to_world = transform_from_desc(obj.transform);
  return std::visit(
      [&](const auto& s) -> std::optional<Shape> {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, SphereDesc>) {
          return Sphere{s.center, s.radius, to_world};
        } else if constexpr (std::is_same_v<T, QuadDesc>) {
          return make_quad(s.corner, s.edge_u, s.edge_v, to_world);
        } else if constexpr (std::is_same_v<T, BoxDesc>) {
          return make_box(glm::min(s.min, s.max), glm::max(s.min, s.max), to_world);
        } else {
          auto data = load_obj(base / s.path, error);
          if (!data) return std::nullopt;
          return make_mesh(std::move(data->positions), std::move(data->normals), std::move(data->uvs),
                           std::move(data->indices), to_world);
        }
      },
      obj.shape);
}

Light compile_light(const LightDesc& desc, float scene_radius) {
  return std::visit(
      [&](const auto& l) -> Light {
        using T = std::decay_t<decltype(l)>;
        if constexpr (std::is_same_v<T, PointLightDesc>) {
          return PointLight{l.position, l.color * l.intensity};
        } else if constexpr (std::is_same_v<T, SpotLightDesc>) {
          const float cos_total = std::cos(glm::radians(l.cone_angle));
          const float cos_falloff = std::cos(glm::radians(std::min(l.falloff_angle, l.cone_angle)));
          return SpotLight{l.position, Frame::from_z(glm::normalize(l.target - l.position)), l.color * l.intensity,
                           cos_total, std::max(cos_falloff, cos_total + 1e-6f)};
        } else {
          return DirectionalLight{-glm::normalize(l.direction), l.color * l.intensity, scene_radius};
        }
      },
      desc.data);
}

// Emissive shapes become area lights when they can be sampled exactly.
std::optional<Light> area_light_for(const RenderScene& scene, uint32_t object) {
  const Shape& shape = scene.geometry.shape(object);
  if (const auto* mesh = std::get_if<TriangleMesh>(&shape)) {
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

void shape_bounds(const Shape& shape, Point3* lo, Point3* hi) {
  if (const auto* sphere = std::get_if<Sphere>(&shape)) return sphere->bounds(lo, hi);
  const TriangleMesh& mesh = std::get<TriangleMesh>(shape);
  *lo = Point3(std::numeric_limits<float>::infinity());
  *hi = -*lo;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    *lo = glm::min(*lo, mesh.positions[v]);
    *hi = glm::max(*hi, mesh.positions[v]);
  }
}

// Empty when the shape lies within kMaxWorldCoordinate, else why not.
std::string world_extent_problem(const Shape& shape) {
  Point3 lo, hi;
  shape_bounds(shape, &lo, &hi);
  const float reach = std::max(max_component(glm::abs(lo)), max_component(glm::abs(hi)));
  if (std::isfinite(reach) && reach <= kMaxWorldCoordinate) return {};
  char text[160];
  std::snprintf(text, sizeof text,
                "after its transform the shape reaches %g units from the origin; the limit is %g "
                "(scale it down or move it closer)",
                double(reach), double(kMaxWorldCoordinate));
  return text;
}

size_t material_source(const SceneDesc& desc, const ObjectDesc& obj) {
  for (size_t m = 0; m < desc.materials.size(); ++m)
    if (desc.materials[m].name == obj.material) return m;
  return 0;
}

// The object's overrides win over its material's where they differ from the defaults.
LineOverride combine_lines(const LineOverrideDesc& material, const LineOverrideDesc& object) {
  LineOverride l;
  l.exclude = material.exclude || object.exclude;
  l.stop_lines = material.stop_lines || object.stop_lines;
  l.width_scale = material.width_scale * object.width_scale;
  l.override_color = material.override_color || object.override_color;
  l.color = object.override_color ? object.color : material.color;
  return l;
}

}  // namespace

Transform transform_from_desc(const TransformDesc& desc) {
  Transform t = Transform::scale(desc.scale);
  for (const RotationDesc& r : desc.rotate) t = Transform::rotate(r.degrees, r.axis) * t;
  return Transform::translate(desc.translate) * t;
}

CompileResult compile_scene(const SceneDesc& desc, const CompileOptions& options) {
  CompileResult result;
  const auto cancelled = [&] {
    if (!options.cancel.requested()) return false;
    result.cancelled = true;
    result.scene.reset();
    result.errors = {"cancelled while building the scene"};
    return true;
  };
  // The editor holds documents that cannot render yet (an unset file, a dangling name):
  // they stop here with the reader's messages rather than deeper with vaguer ones.
  ErrorLog log("");
  check_scene(desc, desc.base_dir, log);
  result.errors = log.take();
  if (result.errors.empty()) check_memory_budget(desc, options.memory_limit, result.errors);
  if (!result.errors.empty()) return result;
  auto scene = std::make_shared<RenderScene>();
  scene->settings = desc.render;
  scene->outlines = desc.outlines;
  scene->camera = Camera(desc.camera, desc.render.width, desc.render.height);

  compile_materials(desc, *scene, result.errors);
  std::map<std::string, uint32_t> material_index;
  for (size_t i = 0; i < scene->material_names.size(); ++i) material_index[scene->material_names[i]] = uint32_t(i);

  for (size_t i = 0; i < desc.objects.size(); ++i) {
    if ((i & 255) == 0 && cancelled()) return result;
    const ObjectDesc& obj = desc.objects[i];
    if (!obj.visible) continue;
    const std::string where = "objects[" + std::to_string(i) + "] \"" + obj.name + "\": ";
    const auto mat = material_index.find(obj.material);
    if (mat == material_index.end()) {
      result.errors.push_back(where + "no material named \"" + obj.material + "\"");
      continue;
    }
    std::string error;
    auto shape = compile_shape(obj, desc.base_dir, &error);
    if (!shape) {
      result.errors.push_back(where + error);
      continue;
    }
    if (const std::string problem = world_extent_problem(*shape); !problem.empty()) {
      result.errors.push_back(where + problem);
      continue;
    }
    scene->geometry.add(std::move(*shape));
    scene->objects.push_back(
        {obj.name, mat->second, -1, uint32_t(i), mat->second, combine_lines(desc.materials[material_source(desc, obj)].lines, obj.lines)});
  }
  if (!result.errors.empty()) return result;
  // Strokes grow on the compiled objects and join the same BVH.
  if (cancelled()) return result;
  compile_strokes(desc, *scene, result.errors, options.cancel);
  if (cancelled() || !result.errors.empty()) return result;
  scene->geometry.commit();

  Point3 lo(0.f), hi(0.f);
  if (scene->geometry.shape_count()) scene->geometry.bounds(&lo, &hi);
  scene->scene_center = 0.5f * (lo + hi);
  scene->scene_radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);

  // Lights: emissive objects, the lights list, then the environment when it is not black.
  for (uint32_t o = 0; o < scene->objects.size(); ++o) {
    if (!material_is_emissive(scene->material_of(o))) continue;
    if (auto light = area_light_for(*scene, o)) {
      scene->objects[o].light = int(scene->lights.size());
      scene->lights.push_back(*light);
    }
  }
  for (const LightDesc& l : desc.lights) scene->lights.push_back(compile_light(l, scene->scene_radius));
  scene->environment = compile_environment(desc.environment, scene->scene_radius);
  if (max_component(scene->environment.zenith + scene->environment.horizon + scene->environment.nadir) > 0.f) {
    scene->environment_light = int(scene->lights.size());
    scene->lights.push_back(scene->environment);
  }
  // Half by power, half uniformly: power alone all but ignores a small spot
  // next to a sun whose power counts the whole scene's area, though the spot
  // may light what the camera sees. The uniform half bounds any light's
  // variance by at most twice what power selection gives.
  std::vector<float> power;
  double total = 0.0;
  for (const Light& l : scene->lights) {
    power.push_back(std::max(light_power(*scene, l), 0.f));
    total += power.back();
  }
  if (total > 0.0)
    for (float& p : power) p = float(0.5 * p / total + 0.5 / double(power.size()));
  scene->light_selection = DiscreteDistribution(power);

  result.scene = std::move(scene);
  return result;
}

}  // namespace inkray
