// Light sampling against closed-form answers, per light type: what a sample
// delivers, its pdf, that light_pdf agrees with sample_light for the same
// direction, and that the area lights' pdfs integrate to 1. Then the light
// selection distribution compile_scene builds.
#include "core/integrator/light_sampling.h"

#include "core/compiler/compile.h"
#include "core/math/hash.h"
#include "core/sampling/warp.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace inkray {
namespace {

// Monte Carlo estimates below use an n x n stratified grid of jittered samples.
constexpr int kGrid = 256;

std::shared_ptr<const RenderScene> compile(const SceneDesc& desc) {
  const CompileResult c = compile_scene(desc);
  EXPECT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
  return c.scene;
}

ObjectDesc object(std::string name, ShapeVariant shape, std::string material) {
  return inkray::testing::make_object(std::move(name), std::move(shape), std::move(material));
}

SceneDesc with_lights(std::vector<LightDesc> lights) {
  SceneDesc d;
  d.materials.push_back({"grey", DiffuseDesc{}, {}});
  // Something to bound the scene; far from every light and reference point used.
  d.objects.push_back(object("far", SphereDesc{{0.f, -100.f, 0.f}, 1.f}, "grey"));
  d.lights = std::move(lights);
  return d;
}

// A point on the origin whose surface faces +y.
LightReference origin_facing_up() { return {Point3(0.f), Vec3(0.f), Normal3(0.f, 1.f, 0.f)}; }

// Jittered sample (i, j) of the grid, reproducible.
Vec2 grid_sample(int i, int j, Pcg32& rng) {
  return {(float(i) + rng.next_float()) / kGrid, (float(j) + rng.next_float()) / kGrid};
}

// Where a ray from ref towards wi meets the scene, for light_pdf.
std::optional<SurfaceInteraction> trace(const RenderScene& scene, const Point3& from, const Vec3& wi) {
  const Ray ray{from, wi};
  Hit hit;
  if (!scene.world->geometry.intersect(ray, kInfinity, &hit)) return std::nullopt;
  return scene.world->geometry.interaction(ray, hit);
}

void expect_color_near(const Color& got, const Color& want, float relative) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], relative * std::abs(want[c])) << "channel " << c;
}

// ---------------------------------------------------------------- delta lights

// A point light's irradiance at distance d facing it is I / d^2.
TEST(LightSampling, PointLightFollowsInverseSquare) {
  const Color color(1.f, 0.5f, 0.25f);
  const float intensity = 8.f;
  const Point3 position(1.f, 2.f, -2.f);  // distance 3 from the origin
  const auto scene = compile(with_lights({{"bulb", PointLightDesc{position, color, intensity}}}));
  ASSERT_TRUE(scene);
  ASSERT_EQ(scene->world->lights.size(), 1u);
  const Light& light = scene->world->lights[0];
  ASSERT_TRUE(std::holds_alternative<PointLight>(light));
  const LightReference ref = origin_facing_up();

  const auto s = sample_light(*scene->world, light, ref, Vec2(0.3f, 0.6f));
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->is_delta);
  EXPECT_EQ(s->pdf, 1.f);
  expect_color_near(s->radiance, color * intensity / 9.f, 1e-5f);
  EXPECT_NEAR(glm::length(s->wi - position / 3.f), 0.f, 1e-6f);
  // The shadow ray ends at the light.
  EXPECT_NEAR(glm::length(s->shadow_ray.o + s->shadow_ray.d - position), 0.f, 1e-5f);
  EXPECT_LE(s->shadow_t_max, 1.f);
  // No other technique reaches a delta light.
  EXPECT_EQ(light_pdf(*scene->world, light, ref, s->wi, SurfaceInteraction{}), 0.f);

  // Twice as far, a quarter of the light.
  const LightReference far{-position, Vec3(0.f), Normal3(0.f, 1.f, 0.f)};
  const auto s2 = sample_light(*scene->world, light, far, Vec2(0.5f));
  ASSERT_TRUE(s2);
  expect_color_near(s2->radiance, 0.25f * s->radiance, 1e-5f);
}

// A spot gives I / d^2 inside its falloff angle, nothing outside its cone, and
// smoothstep(cos_total, cos_falloff, cos) of it in between.
TEST(LightSampling, SpotLightFallsOffBetweenItsAngles) {
  const float cone = 30.f, falloff = 20.f, intensity = 5.f, height = 4.f;
  const auto scene = compile(with_lights(
      {{"spot", SpotLightDesc{{0.f, height, 0.f}, {0.f, 0.f, 0.f}, Color(1.f), intensity, cone, falloff}}}));
  ASSERT_TRUE(scene);
  const Light& light = scene->world->lights[0];
  ASSERT_TRUE(std::holds_alternative<SpotLight>(light));
  const float cos_total = std::cos(glm::radians(cone)), cos_falloff = std::cos(glm::radians(falloff));

  // A receiver on the floor at `degrees` off the spot's axis.
  const auto at_angle = [&](float degrees) {
    const float x = height * std::tan(glm::radians(degrees));
    return sample_light(*scene->world, light, {Point3(x, 0.f, 0.f), Vec3(0.f), Normal3(0.f, 1.f, 0.f)},
                        Vec2(0.5f));
  };
  const auto expected = [&](float degrees) {
    const float d2 = sqr(height / std::cos(glm::radians(degrees)));
    const float t =
        glm::clamp((std::cos(glm::radians(degrees)) - cos_total) / (cos_falloff - cos_total), 0.f, 1.f);
    return intensity * t * t * (3.f - 2.f * t) / d2;
  };
  for (float degrees : {0.f, 10.f, 19.f}) {
    const auto s = at_angle(degrees);
    ASSERT_TRUE(s) << degrees;
    EXPECT_TRUE(s->is_delta);
    EXPECT_NEAR(s->radiance.g, intensity / sqr(height / std::cos(glm::radians(degrees))), 1e-5f) << degrees;
  }
  float previous = expected(20.f);
  for (float degrees : {21.f, 23.f, 25.f, 27.f, 29.f}) {
    const auto s = at_angle(degrees);
    ASSERT_TRUE(s) << degrees;
    EXPECT_NEAR(s->radiance.g, expected(degrees), 1e-4f * expected(0.f)) << degrees;
    EXPECT_LT(s->radiance.g, previous) << degrees;
    EXPECT_GT(s->radiance.g, 0.f) << degrees;
    previous = s->radiance.g;
  }
  for (float degrees : {31.f, 45.f, 80.f}) EXPECT_FALSE(at_angle(degrees)) << degrees;
  // Behind the spot.
  EXPECT_FALSE(sample_light(*scene->world, light,
                            {Point3(0.f, 2.f * height, 0.f), Vec3(0.f), Normal3(0.f, -1.f, 0.f)},
                            Vec2(0.5f)));
  EXPECT_EQ(light_pdf(*scene->world, light, origin_facing_up(), Vec3(0.f, 1.f, 0.f), SurfaceInteraction{}),
            0.f);
}

// A directional light's radiance field is its irradiance on a surface facing it;
// a tilted surface receives it times the cosine.
TEST(LightSampling, DirectionalLightGivesItsIrradiance) {
  const Vec3 travel(1.f, -2.f, 0.5f);
  const Color color(0.5f, 1.f, 0.75f);
  const float intensity = 3.f;
  const auto scene = compile(with_lights({{"sun", DirectionalLightDesc{travel, color, intensity}}}));
  ASSERT_TRUE(scene);
  const Light& light = scene->world->lights[0];
  ASSERT_TRUE(std::holds_alternative<DirectionalLight>(light));
  for (const Point3 p : {Point3(0.f), Point3(10.f, -3.f, 7.f)}) {
    const auto s =
        sample_light(*scene->world, light, {p, Vec3(0.f), Normal3(0.f, 1.f, 0.f)}, Vec2(0.2f, 0.9f));
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->is_delta);
    EXPECT_EQ(s->pdf, 1.f);
    EXPECT_NEAR(glm::length(s->wi + glm::normalize(travel)), 0.f, 1e-6f);
    expect_color_near(s->radiance, color * intensity, 1e-6f);
    EXPECT_EQ(s->shadow_t_max, kInfinity);
    const float irradiance_up = s->radiance.g * glm::dot(Vec3(0.f, 1.f, 0.f), s->wi) / s->pdf;
    EXPECT_NEAR(irradiance_up, intensity * 2.f / glm::length(travel), 1e-5f);
  }
  EXPECT_EQ(light_pdf(*scene->world, light, origin_facing_up(), -travel, SurfaceInteraction{}), 0.f);
}

// ---------------------------------------------------------------- mesh area light

// A square emitter of half-width a, facing down at height h above the origin.
// A square lamp of half-width a at height h above the origin, or (sheared) the
// parallelogram with the same corner, first edge and area.
SceneDesc square_lamp_scene(float a, float h, float le, bool sheared = false) {
  SceneDesc d = with_lights({});
  d.materials.push_back({"lamp", EmissiveDesc{Color(le), 1.f, false}, {}});
  // cross(edge_u, edge_v) points down: the lamp's front faces the origin.
  const Vec3 edge_v = sheared ? Vec3(a, 0.f, 2.f * a) : Vec3(0.f, 0.f, 2.f * a);
  d.objects.push_back(object("lamp", QuadDesc{{-a, h, -a}, {2.f * a, 0.f, 0.f}, edge_v}, "lamp"));
  return d;
}

struct GridEstimate {
  double irradiance = 0.0;  // sum over the grid of radiance.g * cos / pdf
  int checked_pdf = 0;      // samples whose direction was traced and light_pdf checked
};

// Samples `light` from ref at every point of the jittered grid (seeded `seed`): `check`
// judges each sample; every 97th direction is traced and must meet `object`, where
// `check_hit` judges the point and light_pdf must agree with the sample's pdf. With
// `rim_may_miss` a direction that meets nothing is passed over (rays at a sphere's rim
// may graze past it). Stops at the first fatal failure, as one loop in the test would.
void sample_over_grid(
    const RenderScene& scene, const Light& light, const LightReference& ref, uint64_t seed, uint32_t object,
    bool rim_may_miss, GridEstimate& out, const std::function<void(const LightSample&)>& check,
    const std::function<void(const LightSample&, const SurfaceInteraction&)>& check_hit =
        [](const LightSample&, const SurfaceInteraction&) {}) {
  Pcg32 rng(seed);
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const auto s = sample_light(*scene.world, light, ref, grid_sample(i, j, rng));
      ASSERT_TRUE(s);
      check(*s);
      if (::testing::Test::HasFatalFailure()) return;
      out.irradiance += double(s->radiance.g * s->wi.y / s->pdf);
      if ((i * kGrid + j) % 97 != 0) continue;
      const auto on_light = trace(scene, ref.p, s->wi);
      if (!on_light && rim_may_miss) continue;
      ASSERT_TRUE(on_light);
      ASSERT_EQ(on_light->object, object);
      check_hit(*s, *on_light);
      EXPECT_NEAR(light_pdf(*scene.world, light, ref, s->wi, *on_light), s->pdf, 1e-4f * s->pdf);
      ++out.checked_pdf;
    }
}

// light_pdf integrated over the directions from the origin that meet the light (where
// `on_light` says a hit is on it): a grid of directions from `direction`, whose density
// is `pdf`, seeded `seed`. 1 for a pdf that is one.
template <class Direction>
double light_pdf_integral(const RenderScene& scene, const Light& light, uint64_t seed, Direction direction,
                          float pdf, const std::function<bool(const SurfaceInteraction&)>& on_light) {
  const LightReference ref = origin_facing_up();
  Pcg32 rng(seed);
  double sum = 0.0;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const Vec3 wi = direction(grid_sample(i, j, rng));
      const auto hit = trace(scene, ref.p, wi);
      if (hit && on_light(*hit)) sum += light_pdf(*scene.world, light, ref, wi, *hit) / pdf;
    }
  return sum / double(kGrid * kGrid);
}

// Irradiance below the centre of a square of half-width a at height h, radiance
// le: four corner-aligned rectangles (differential-area-to-rectangle form factor).
float square_irradiance(float a, float h, float le) {
  const double x = a / h, sx = std::sqrt(1.0 + x * x);
  return float(4.0 * le * (x / sx) * std::atan(x / sx));
}

// A quad with square corners is sampled uniformly in the solid angle it subtends:
// every sample's pdf is 1 / (the square's solid angle), light_pdf agrees for the
// point a ray finds, and the irradiance estimate is the analytic one.
TEST(LightSampling, RectAreaLightIsSampledUniformlyInSolidAngle) {
  const float a = 0.75f, h = 1.5f, le = 2.f;
  const auto scene = compile(square_lamp_scene(a, h, le));
  ASSERT_TRUE(scene);
  ASSERT_EQ(scene->world->lights.size(), 1u);
  const Light& light = scene->world->lights[0];
  const auto* rect = std::get_if<RectAreaLight>(&light);
  ASSERT_TRUE(rect);
  EXPECT_NEAR(rect->width * rect->height, 4.f * a * a, 1e-5f);
  EXPECT_EQ(scene->world->objects[rect->object].light, 0);
  // The solid angle of a square seen from a point on its axis.
  const float solid_angle = 4.f * std::asin(a * a / (a * a + h * h));

  const LightReference ref = origin_facing_up();
  GridEstimate grid;
  ASSERT_NO_FATAL_FAILURE(sample_over_grid(
      *scene, light, ref, 7, rect->object, false, grid,
      [&](const LightSample& s) {
        ASSERT_FALSE(s.is_delta);
        ASSERT_GT(s.wi.y, 0.f);
        expect_color_near(s.radiance, Color(le), 1e-6f);
        ASSERT_NEAR(s.pdf, 1.f / solid_angle, 1e-4f / solid_angle);
      },
      [&](const LightSample& s, const SurfaceInteraction& on_light) {
        EXPECT_NEAR(glm::length(on_light.p - (ref.p + s.wi * (h / s.wi.y))), 0.f, 1e-4f);
      }));
  EXPECT_GT(grid.checked_pdf, 600);
  const float expected = square_irradiance(a, h, le);
  EXPECT_NEAR(grid.irradiance / double(kGrid * kGrid), expected, 0.001 * expected);

  // The emitter is one-sided: from above it sends nothing.
  const LightReference above{Point3(0.f, 2.f * h, 0.f), Vec3(0.f), Normal3(0.f, -1.f, 0.f)};
  EXPECT_FALSE(sample_light(*scene->world, light, above, Vec2(0.4f, 0.4f)));
  // Seen from almost in its plane it subtends too little to sample by solid angle:
  // area sampling then, with light_pdf still agreeing.
  const LightReference edge_on{Point3(40.f, h - 0.001f, 0.f), Vec3(0.f), Normal3(-1.f, 0.f, 0.f)};
  const auto grazing = sample_light(*scene->world, light, edge_on, Vec2(0.3f, 0.6f));
  ASSERT_TRUE(grazing);
  const auto hit = trace(*scene, edge_on.p, grazing->wi);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(light_pdf(*scene->world, light, edge_on, grazing->wi, *hit), grazing->pdf,
              1e-3f * grazing->pdf);
}

// A parallelogram is sampled by area: pdf = (1 / area) * dist^2 / cos.
TEST(LightSampling, MeshAreaLightPdfIsInverseAreaInSolidAngle) {
  const float a = 0.75f, h = 1.5f, le = 2.f;
  const auto scene = compile(square_lamp_scene(a, h, le, true));
  ASSERT_TRUE(scene);
  ASSERT_EQ(scene->world->lights.size(), 1u);
  const Light& light = scene->world->lights[0];
  const auto* mesh = std::get_if<MeshAreaLight>(&light);
  ASSERT_TRUE(mesh);
  const float area = 4.f * a * a;
  EXPECT_NEAR(mesh->area, area, 1e-5f);
  EXPECT_EQ(scene->world->objects[mesh->object].light, 0);

  GridEstimate grid;
  ASSERT_NO_FATAL_FAILURE(sample_over_grid(
      *scene, light, origin_facing_up(), 7, mesh->object, false, grid, [&](const LightSample& s) {
        ASSERT_GT(s.wi.y, 0.f);
        // The point lies on the plane y = h at distance h / wi.y, seen at cosine wi.y.
        const float expected_pdf = sqr(h) / (area * s.wi.y * s.wi.y * s.wi.y);
        ASSERT_NEAR(s.pdf, expected_pdf, 1e-4f * expected_pdf);
      }));
  EXPECT_GT(grid.checked_pdf, 600);
}

// Over the directions that reach the lamp, light_pdf integrates to 1, for the
// rectangle and the parallelogram (uniform hemisphere directions, 256^2
// stratified, tolerance 1%).
TEST(LightSampling, AreaLightPdfIntegratesToOne) {
  for (const bool sheared : {false, true}) {
    const auto scene = compile(square_lamp_scene(1.f, 1.f, 1.f, sheared));
    ASSERT_TRUE(scene);
    const double integral = light_pdf_integral(
        *scene, scene->world->lights[0], 11,
        [](Vec2 u) {
          const Vec3 h = sample_uniform_hemisphere(u);
          return Vec3(h.x, h.z, h.y);  // the hemisphere around +y
        },
        uniform_hemisphere_pdf(),
        [&](const SurfaceInteraction& hit) { return scene->world->objects[hit.object].light == 0; });
    EXPECT_NEAR(integral, 1.0, 0.01) << (sheared ? "parallelogram" : "rectangle");
  }
}

// ---------------------------------------------------------------- sphere area light

SceneDesc sphere_lamp_scene(Point3 center, float radius, float le, bool two_sided) {
  SceneDesc d = with_lights({});
  d.materials.push_back({"lamp", EmissiveDesc{Color(le), 1.f, two_sided}, {}});
  d.objects.push_back(object("lamp", SphereDesc{center, radius}, "lamp"));
  return d;
}

// Seen from outside, a sphere is sampled uniformly in the cone it subtends.
TEST(LightSampling, SphereLightSamplesTheConeItSubtends) {
  const float r = 1.f, d = 2.5f, le = 3.f;
  const auto scene = compile(sphere_lamp_scene({0.f, d, 0.f}, r, le, false));
  ASSERT_TRUE(scene);
  ASSERT_EQ(scene->world->lights.size(), 1u);
  const Light& light = scene->world->lights[0];
  const auto* sphere = std::get_if<SphereAreaLight>(&light);
  ASSERT_TRUE(sphere);
  const float cos_max = std::sqrt(1.f - sqr(r / d));
  const float cone_pdf = 1.f / (2.f * kPi * (1.f - cos_max));

  GridEstimate grid;
  // Directions at the very rim may graze past the sphere.
  ASSERT_NO_FATAL_FAILURE(sample_over_grid(*scene, light, origin_facing_up(), 3, sphere->object, true, grid,
                                           [&](const LightSample& s) {
                                             ASSERT_GE(s.wi.y, cos_max - 1e-4f);  // inside the cone
                                             ASSERT_NEAR(s.pdf, cone_pdf, 1e-4f * cone_pdf);
                                             expect_color_near(s.radiance, Color(le), 1e-6f);
                                           }));
  EXPECT_GT(grid.checked_pdf, 600);
  // A sphere straight above a surface: E = pi le (r / d)^2.
  const float expected = kPi * le * sqr(r / d);
  EXPECT_NEAR(grid.irradiance / double(kGrid * kGrid), expected, 0.002 * expected);
}

// Over the directions that reach the sphere, light_pdf integrates to 1
// (uniform sphere directions, 256^2 stratified, tolerance 1%).
TEST(LightSampling, SphereLightPdfIntegratesToOneOverItsCone) {
  const auto scene = compile(sphere_lamp_scene({0.5f, 2.f, -0.5f}, 1.f, 1.f, false));
  ASSERT_TRUE(scene);
  const Light& light = scene->world->lights[0];
  const double integral = light_pdf_integral(
      *scene, light, 5, [](Vec2 u) { return sample_uniform_sphere(u); }, uniform_sphere_pdf(),
      [&](const SurfaceInteraction& hit) { return hit.object == std::get<SphereAreaLight>(light).object; });
  EXPECT_NEAR(integral, 1.0, 0.01);
}

// Inside a sphere (here two-sided, so it shines inwards) the whole sphere is
// sampled by area: the pdf still matches light_pdf and integrates to 1, and a
// surface inside a uniformly glowing sphere receives pi le.
TEST(LightSampling, SphereLightFromInside) {
  const float r = 2.f, le = 0.5f;
  const auto scene = compile(sphere_lamp_scene({0.f, 0.5f, 0.f}, r, le, true));
  ASSERT_TRUE(scene);
  const Light& light = scene->world->lights[0];
  const uint32_t object = std::get<SphereAreaLight>(light).object;
  const LightReference ref = origin_facing_up();
  Pcg32 rng(9);
  double irradiance = 0.0, pdf_sum = 0.0;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const auto s = sample_light(*scene->world, light, ref, grid_sample(i, j, rng));
      ASSERT_TRUE(s);
      expect_color_near(s->radiance, Color(le), 1e-6f);
      irradiance += double(s->radiance.g * std::max(0.f, s->wi.y) / s->pdf);
      if ((i * kGrid + j) % 97 == 0) {
        const auto on_light = trace(*scene, ref.p, s->wi);
        ASSERT_TRUE(on_light);
        ASSERT_EQ(on_light->object, object);
        EXPECT_NEAR(light_pdf(*scene->world, light, ref, s->wi, *on_light), s->pdf, 1e-3f * s->pdf);
      }
      const Vec3 wi = sample_uniform_sphere(grid_sample(i, j, rng));
      const auto on_light = trace(*scene, ref.p, wi);
      ASSERT_TRUE(on_light);
      pdf_sum += light_pdf(*scene->world, light, ref, wi, *on_light) / uniform_sphere_pdf();
    }
  EXPECT_NEAR(pdf_sum / double(kGrid * kGrid), 1.0, 0.01);
  EXPECT_NEAR(irradiance / double(kGrid * kGrid), kPi * le, 0.01 * kPi * le);
}

// ---------------------------------------------------------------- environment

TEST(LightSampling, EnvironmentIsSampledUniformly) {
  SceneDesc d = with_lights({});
  d.environment = GradientEnvironmentDesc{Color(0.2f, 0.4f, 1.f), Color(1.f), Color(0.1f)};
  const auto scene = compile(d);
  ASSERT_TRUE(scene);
  ASSERT_EQ(scene->world->environment_light, 0);
  const Light& light = scene->world->lights[0];
  const auto* env = std::get_if<EnvironmentLight>(&light);
  ASSERT_TRUE(env);
  const LightReference ref = origin_facing_up();
  Pcg32 rng(13);
  for (int k = 0; k < 1000; ++k) {
    const auto s = sample_light(*scene->world, light, ref, Vec2(rng.next_float(), rng.next_float()));
    ASSERT_TRUE(s);
    EXPECT_FALSE(s->is_delta);
    EXPECT_NEAR(glm::length(s->wi), 1.f, 1e-5f);
    EXPECT_EQ(s->pdf, uniform_sphere_pdf());
    EXPECT_EQ(light_pdf(*scene->world, light, ref, s->wi, SurfaceInteraction{}), s->pdf);
    expect_color_near(s->radiance, env->radiance(s->wi), 1e-6f);
    EXPECT_EQ(s->shadow_t_max, kInfinity);
  }
}

// A constant sky of radiance L gives a surface pi L.
TEST(LightSampling, ConstantEnvironmentIrradiance) {
  SceneDesc d = with_lights({});
  d.environment = ConstantEnvironmentDesc{Color(0.8f)};
  const auto scene = compile(d);
  ASSERT_TRUE(scene);
  const Light& light = scene->world->lights[size_t(scene->world->environment_light)];
  Pcg32 rng(17);
  double irradiance = 0.0;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const auto s = sample_light(*scene->world, light, origin_facing_up(), grid_sample(i, j, rng));
      ASSERT_TRUE(s);
      irradiance += double(s->radiance.g * std::max(0.f, s->wi.y) / s->pdf);
    }
  EXPECT_NEAR(irradiance / double(kGrid * kGrid), kPi * 0.8f, 0.005 * kPi * 0.8f);
}

// ---------------------------------------------------------------- light selection

// Half by power, half uniform: every light can be chosen, a black one too, and
// the probabilities sum to 1. Sampling picks each light at its pmf.
TEST(LightSampling, SelectionGivesEveryLightAShare) {
  SceneDesc d = square_lamp_scene(0.5f, 3.f, 10.f);
  d.materials.push_back({"ball", EmissiveDesc{Color(1.f, 0.5f, 0.5f), 20.f, false}, {}});
  d.objects.push_back(object("ball", SphereDesc{{3.f, 2.f, 0.f}, 0.25f}, "ball"));
  d.lights.push_back({"bulb", PointLightDesc{{0.f, 2.f, 0.f}, Color(1.f), 50.f}});
  d.lights.push_back({"spot", SpotLightDesc{{1.f, 3.f, 0.f}, {1.f, 0.f, 0.f}, Color(1.f), 2.f, 20.f, 10.f}});
  d.lights.push_back({"sun", DirectionalLightDesc{{0.f, -1.f, 0.2f}, Color(1.f), 4.f}});
  d.lights.push_back({"off", PointLightDesc{{0.f, 1.f, 0.f}, Color(1.f), 0.f}});
  d.environment = ConstantEnvironmentDesc{Color(0.05f)};
  const auto scene = compile(d);
  ASSERT_TRUE(scene);
  const size_t n = scene->world->lights.size();
  ASSERT_EQ(n, 7u);  // two emitters, four lights, the sky
  ASSERT_EQ(scene->world->light_selection.size(), n);
  ASSERT_FALSE(scene->world->light_selection.empty());

  // Every emitting object points at its own light.
  for (uint32_t o = 0; o < scene->world->objects.size(); ++o) {
    const int l = scene->world->objects[o].light;
    if (l < 0) continue;
    std::visit(
        [&](const auto& light) {
          if constexpr (requires { light.object; })
            EXPECT_EQ(light.object, o);
          else
            ADD_FAILURE() << "object " << o << " points at a light that is not an area light";
        },
        scene->world->lights[size_t(l)]);
  }

  double total_power = 0.0;
  for (const Light& l : scene->world->lights) total_power += light_power(*scene->world, l);
  ASSERT_GT(total_power, 0.0);
  double sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const float pmf = scene->world->light_selection.pmf(i);
    EXPECT_GT(pmf, 0.f) << "light " << i;
    const double expected =
        0.5 * light_power(*scene->world, scene->world->lights[i]) / total_power + 0.5 / double(n);
    EXPECT_NEAR(pmf, expected, 1e-6) << "light " << i;
    sum += pmf;
  }
  EXPECT_NEAR(sum, 1.0, 1e-6);
  EXPECT_EQ(light_power(*scene->world, scene->world->lights[5]), 0.f);  // "off"
  EXPECT_NEAR(scene->world->light_selection.pmf(5), 0.5 / double(n), 1e-7);

  // Stratified choices land on each light in proportion to its pmf.
  std::vector<int> count(n, 0);
  const int choices = 1 << 16;
  for (int k = 0; k < choices; ++k) {
    float pmf = 0.f;
    const size_t i = scene->world->light_selection.sample((float(k) + 0.5f) / float(choices), &pmf);
    ASSERT_LT(i, n);
    EXPECT_EQ(pmf, scene->world->light_selection.pmf(i));
    ++count[i];
  }
  for (size_t i = 0; i < n; ++i)
    EXPECT_NEAR(double(count[i]) / choices, scene->world->light_selection.pmf(i), 2.0 / choices)
        << "light " << i;
}

// With no lights there is nothing to choose: the integrator skips light sampling.
TEST(LightSampling, SelectionIsEmptyWithoutLights) {
  const auto scene = compile(with_lights({}));
  ASSERT_TRUE(scene);
  EXPECT_TRUE(scene->world->lights.empty());
  EXPECT_TRUE(scene->world->light_selection.empty());
}

}  // namespace
}  // namespace inkray
