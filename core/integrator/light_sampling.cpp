#include "core/integrator/light_sampling.h"

#include "core/math/float_error.h"
#include "core/sampling/spherical_rectangle.h"
#include "core/sampling/warp.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

LightSample delta_sample(const LightReference& ref, const Point3& light_p, const Color& radiance) {
  LightSample s;
  const Vec3 d = light_p - ref.p;
  s.wi = glm::normalize(d);
  s.radiance = radiance;
  s.pdf = 1.f;
  s.is_delta = true;
  s.shadow_ray = spawn_ray_to(ref.p, ref.p_error, ref.n, light_p, Vec3(0.f), Vec3(0.f));
  s.shadow_t_max = kShadowTMax;
  return s;
}

// Completes a sample that reached a point on an emitting surface.
std::optional<LightSample> surface_sample(const World& world, const LightReference& ref, uint32_t object,
                                          const SurfaceInteraction& on_light, float pdf_solid_angle) {
  const Vec3 d = on_light.p - ref.p;
  const float dist2 = glm::dot(d, d);
  if (!(dist2 > 0.f) || !(pdf_solid_angle > 0.f) || !std::isfinite(pdf_solid_angle)) return std::nullopt;
  LightSample s;
  s.wi = d / std::sqrt(dist2);
  s.radiance = material_emission(world.material_of(object), on_light, glm::dot(-s.wi, on_light.ng));
  if (is_black(s.radiance)) return std::nullopt;
  s.pdf = pdf_solid_angle;
  s.shadow_ray = spawn_ray_to(ref.p, ref.p_error, ref.n, on_light.p, on_light.p_error, on_light.ng);
  s.shadow_t_max = kShadowTMax;
  return s;
}

float area_to_solid_angle(float pdf_area, const Point3& ref, const SurfaceInteraction& on_light) {
  const Vec3 d = on_light.p - ref;
  const float dist2 = glm::dot(d, d);
  const float cos_light = std::abs(glm::dot(on_light.ng, d)) / std::sqrt(dist2);
  return cos_light > 0.f ? pdf_area * dist2 / cos_light : 0.f;
}

// Cosine of the half-angle the sphere subtends from ref; 0 when ref is inside.
float sphere_cos_max(const SphereAreaLight& s, const Point3& ref) {
  const float dist2 = glm::dot(ref - s.center, ref - s.center);
  const float r2 = s.radius * s.radius;
  return dist2 > r2 * 1.0001f ? std::sqrt(std::max(0.f, 1.f - r2 / dist2)) : 0.f;
}

SurfaceInteraction mesh_point(const TriangleMesh& mesh, size_t tri, Vec2 b) {
  const uint32_t i0 = mesh.indices[3 * tri], i1 = mesh.indices[3 * tri + 1], i2 = mesh.indices[3 * tri + 2];
  const float b0 = b.x, b1 = b.y, b2 = 1.f - b.x - b.y;
  const Point3 &p0 = mesh.positions[i0], &p1 = mesh.positions[i1], &p2 = mesh.positions[i2];
  SurfaceInteraction si;
  si.p = b0 * p0 + b1 * p1 + b2 * p2;
  si.p_error =
      Vec3(gamma_bound(7) * max_component(glm::abs(b0 * p0) + glm::abs(b1 * p1) + glm::abs(b2 * p2)));
  si.ng = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  if (!mesh.normals.empty()) {
    const Vec3 ns = b0 * mesh.normals[i0] + b1 * mesh.normals[i1] + b2 * mesh.normals[i2];
    if (glm::dot(ns, si.ng) < 0.f) si.ng = -si.ng;
  }
  si.ns = si.ng;
  si.uv = mesh.uvs.empty() ? Vec2(b1, b2) : b0 * mesh.uvs[i0] + b1 * mesh.uvs[i1] + b2 * mesh.uvs[i2];
  if (!mesh.colors.empty()) si.color = b0 * mesh.colors[i0] + b1 * mesh.colors[i1] + b2 * mesh.colors[i2];
  si.prim = uint32_t(tri);
  return si;
}

std::optional<LightSample> sample_mesh(const World& world, const MeshAreaLight& l, const LightReference& ref,
                                       Vec2 u) {
  const auto& mesh = std::get<TriangleMesh>(world.geometry.shape(l.object));
  float pmf = 0.f;
  const size_t tri = l.triangles.sample(u.x, &pmf, &u.x);
  SurfaceInteraction on_light = mesh_point(mesh, tri, sample_uniform_triangle(u));
  on_light.object = l.object;
  return surface_sample(world, ref, l.object, on_light, area_to_solid_angle(1.f / l.area, ref.p, on_light));
}

// Solid-angle sampling where it pays: near the rectangle, where distance and cosine
// vary across it and area sampling's weights with them. From further than
// kSolidAngleReach diagonals from its centre they vary by under a quarter, and area
// sampling is as good for a fraction of the cost. Not either for a rectangle filling
// nearly the hemisphere, nor one so small that its spherical excess is lost to
// rounding (the bounds pbrt-v4 uses for its spherical rectangles and triangles).
constexpr float kSolidAngleReach = 2.f;

std::optional<SphericalRectangle> rect_solid_angle(const RectAreaLight& l, const Point3& from) {
  const Vec3 to_center = l.corner + 0.5f * (l.width * l.x + l.height * l.y) - from;
  const float reach = kSolidAngleReach * kSolidAngleReach * (l.width * l.width + l.height * l.height);
  if (glm::dot(to_center, to_center) > reach) return std::nullopt;
  auto r = spherical_rectangle(from, l.corner, l.x, l.y, l.width, l.height);
  if (!r || r->solid_angle < 3e-4 || r->solid_angle > 6.22) return std::nullopt;
  return r;
}

// The mesh's interaction at the point corner + s * width * x + t * height * y of its
// rectangle, laid out by make_quad (triangles 0 1 2 and 0 2 3 over the corners
// corner, +u, +u+v, +v): normals, uv and position error as a traced ray finds them.
SurfaceInteraction rect_point(const TriangleMesh& mesh, float s, float t) {
  s = std::clamp(s, 0.f, 1.f);
  t = std::clamp(t, 0.f, 1.f);
  return s >= t ? mesh_point(mesh, 0, Vec2(1.f - s, s - t)) : mesh_point(mesh, 1, Vec2(1.f - t, s));
}

std::optional<LightSample> sample_rect(const World& world, const RectAreaLight& l, const LightReference& ref,
                                       Vec2 u) {
  const auto& mesh = std::get<TriangleMesh>(world.geometry.shape(l.object));
  const auto solid = rect_solid_angle(l, ref.p);
  Vec2 st = u;  // the point's fractions of the edges
  if (solid) {
    const Vec3 d = sample_spherical_rectangle(*solid, u) - l.corner;
    st = Vec2(glm::dot(d, l.x) / l.width, glm::dot(d, l.y) / l.height);
  }
  SurfaceInteraction on_light = rect_point(mesh, st.x, st.y);
  on_light.object = l.object;
  const float pdf = solid ? float(1.0 / solid->solid_angle)
                          : area_to_solid_angle(1.f / (l.width * l.height), ref.p, on_light);
  return surface_sample(world, ref, l.object, on_light, pdf);
}

std::optional<LightSample> sample_sphere(const World& world, const SphereAreaLight& l,
                                         const LightReference& ref, Vec2 u) {
  const auto& sphere = std::get<Sphere>(world.geometry.shape(l.object));
  const float cos_max = sphere_cos_max(l, ref.p);
  Vec3 dir_to_point;  // from the centre, in world space
  float pdf = 0.f;
  if (cos_max > 0.f) {
    // Uniform in the cone of directions the sphere subtends; then find the
    // point that direction reaches (pbrt-v4 Sphere::Sample by solid angle).
    const Vec3 to_center = l.center - ref.p;
    const float dc = glm::length(to_center);
    const Frame frame = Frame::from_z(to_center / dc);
    const Vec3 w = frame.to_world(sample_uniform_cone(u, cos_max));
    const float cos_t = glm::dot(w, to_center / dc);
    const float sin2_t = std::max(0.f, 1.f - cos_t * cos_t);
    // Distance along w to the near intersection, clamped at the tangent point.
    const float t = dc * cos_t - safe_sqrt(l.radius * l.radius - dc * dc * sin2_t);
    dir_to_point = glm::normalize(ref.p + t * w - l.center);
    pdf = uniform_cone_pdf(cos_max);
  } else {
    dir_to_point = sample_uniform_sphere(u);
  }
  // Evaluate the sphere at the chosen point through its own reprojection, so
  // position error and uv match what a traced ray would find.
  const Point3 target = l.center + l.radius * dir_to_point;
  const Ray probe{ref.p, target - ref.p};
  SurfaceInteraction on_light = sphere.interaction(probe, 1.f);
  on_light.object = l.object;
  if (cos_max <= 0.f) pdf = area_to_solid_angle(1.f / (4.f * kPi * l.radius * l.radius), ref.p, on_light);
  return surface_sample(world, ref, l.object, on_light, pdf);
}

std::optional<LightSample> sample_environment(const EnvironmentLight& env, const LightReference& ref,
                                              Vec2 u) {
  LightSample s;
  s.wi = sample_uniform_sphere(u);
  s.radiance = env.radiance(s.wi);
  if (is_black(s.radiance)) return std::nullopt;
  s.pdf = uniform_sphere_pdf();
  s.shadow_ray = spawn_ray(ref.p, ref.p_error, ref.n, s.wi);
  s.shadow_t_max = kInfinity;
  return s;
}

// The solid-angle density with which sample_light picks the direction to `on_light`,
// one overload per light that is not a delta (LightTraits): a new kind of area light
// does not compile until it has one.
float solid_angle_pdf(const MeshAreaLight& m, const LightReference& ref, const SurfaceInteraction& on_light) {
  return area_to_solid_angle(1.f / m.area, ref.p, on_light);
}
float solid_angle_pdf(const RectAreaLight& r, const LightReference& ref, const SurfaceInteraction& on_light) {
  if (const auto solid = rect_solid_angle(r, ref.p)) return float(1.0 / solid->solid_angle);
  return area_to_solid_angle(1.f / (r.width * r.height), ref.p, on_light);
}
float solid_angle_pdf(const SphereAreaLight& s, const LightReference& ref,
                      const SurfaceInteraction& on_light) {
  const float cos_max = sphere_cos_max(s, ref.p);
  if (cos_max > 0.f) return uniform_cone_pdf(cos_max);
  return area_to_solid_angle(1.f / (4.f * kPi * s.radius * s.radius), ref.p, on_light);
}
float solid_angle_pdf(const EnvironmentLight&, const LightReference&, const SurfaceInteraction&) {
  return uniform_sphere_pdf();
}

}  // namespace

std::optional<LightSample> sample_light(const World& world, const Light& light, const LightReference& ref,
                                        Vec2 u) {
  return std::visit(
      [&](const auto& l) -> std::optional<LightSample> {
        using T = std::decay_t<decltype(l)>;
        if constexpr (std::is_same_v<T, PointLight>) {
          const float dist2 = glm::dot(l.position - ref.p, l.position - ref.p);
          return delta_sample(ref, l.position, l.intensity / dist2);
        } else if constexpr (std::is_same_v<T, SpotLight>) {
          const Vec3 d = ref.p - l.position;
          const float dist2 = glm::dot(d, d);
          const float cos_t = glm::dot(d, l.frame.z) / std::sqrt(dist2);
          const float falloff = glm::smoothstep(l.cos_total, l.cos_falloff, cos_t);
          if (falloff <= 0.f) return std::nullopt;
          return delta_sample(ref, l.position, l.intensity * falloff / dist2);
        } else if constexpr (std::is_same_v<T, DirectionalLight>) {
          LightSample s;
          s.wi = l.to_light;
          s.radiance = l.irradiance;
          s.pdf = 1.f;
          s.is_delta = true;
          s.shadow_ray = spawn_ray(ref.p, ref.p_error, ref.n, s.wi);
          s.shadow_t_max = kInfinity;
          return s;
        } else if constexpr (std::is_same_v<T, MeshAreaLight>) {
          return sample_mesh(world, l, ref, u);
        } else if constexpr (std::is_same_v<T, RectAreaLight>) {
          return sample_rect(world, l, ref, u);
        } else if constexpr (std::is_same_v<T, SphereAreaLight>) {
          return sample_sphere(world, l, ref, u);
        } else {
          static_assert(std::is_same_v<T, EnvironmentLight>, "a kind of light sample_light does not handle");
          return sample_environment(l, ref, u);
        }
      },
      light);
}

float light_pdf(const World& /*world*/, const Light& light, const LightReference& ref, const Vec3& /*wi*/,
                const SurfaceInteraction& on_light) {
  return std::visit(
      [&](const auto& l) -> float {
        if constexpr (LightTraits<std::decay_t<decltype(l)>>::delta) {
          return 0.f;
        } else {
          return solid_angle_pdf(l, ref, on_light);
        }
      },
      light);
}

float light_power(const World& world, const Light& light) {
  return std::visit(
      [&](const auto& l) -> float {
        using T = std::decay_t<decltype(l)>;
        if constexpr (std::is_same_v<T, PointLight>) {
          return 4.f * kPi * luminance(l.intensity);
        } else if constexpr (std::is_same_v<T, SpotLight>) {
          return 2.f * kPi * luminance(l.intensity) * (1.f - 0.5f * (l.cos_falloff + l.cos_total));
        } else if constexpr (std::is_same_v<T, DirectionalLight>) {
          return kPi * sqr(l.scene_radius) * luminance(l.irradiance);
        } else if constexpr (std::is_same_v<T, MeshAreaLight> || std::is_same_v<T, RectAreaLight> ||
                             std::is_same_v<T, SphereAreaLight>) {
          const Material& m = world.material_of(l.object);
          const bool two_sided = std::get<EmissiveMaterial>(m).two_sided;
          float area = 0.f;
          if constexpr (std::is_same_v<T, MeshAreaLight>)
            area = l.area;
          else if constexpr (std::is_same_v<T, RectAreaLight>)
            area = l.width * l.height;
          else
            area = 4.f * kPi * l.radius * l.radius;
          return kPi * (two_sided ? 2.f : 1.f) * area * luminance(material_average_emission(m));
        } else {
          static_assert(std::is_same_v<T, EnvironmentLight>, "a kind of light light_power does not handle");
          const Color avg = (l.zenith + 2.f * l.horizon + l.nadir) * 0.25f;
          return 4.f * kPi * kPi * sqr(l.scene_radius) * luminance(avg);
        }
      },
      light);
}

}  // namespace inkray
