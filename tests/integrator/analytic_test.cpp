// The path tracer against closed-form answers.
#include "support/render_helpers.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

using namespace inkray::testing;

SceneDesc sphere_in_environment(MaterialVariant material, Color environment) {
  SceneDesc d = small_scene(32, 32);
  d.camera.look_from = {0.f, 0.f, 4.f};
  d.camera.vfov = 20.f;  // the sphere fills the frame
  d.materials.push_back({"m", std::move(material), {}});
  d.objects.push_back({"sphere", SphereDesc{{0.f, 0.f, 0.f}, 1.f}, {}, "m", true, {}});
  d.environment = ConstantEnvironmentDesc{environment};
  return d;
}

// A convex object in a uniform environment: every bounce leaves to the sky,
// so a Lambertian surface returns exactly albedo * environment.
TEST(IntegratorAnalytic, DiffuseFurnace) {
  const RgbImage img = render_scene(sphere_in_environment(DiffuseDesc{Color(0.8f)}, Color(1.f)), 256);
  const Color centre = mean_color(img, 10, 10, 22, 22);
  EXPECT_NEAR(centre.r, 0.8f, 0.008f);
  EXPECT_NEAR(centre.g, 0.8f, 0.008f);
  EXPECT_NEAR(centre.b, 0.8f, 0.008f);
}

TEST(IntegratorAnalytic, WhiteFurnaceOfLosslessMaterials) {
  for (MaterialVariant m :
       {MaterialVariant(DiffuseDesc{Color(1.f)}), MaterialVariant(ConductorDesc{Color(1.f), 0.f}),
        MaterialVariant(DielectricDesc{1.5f, 0.f, Color(1.f)}),
        MaterialVariant(TransparentDesc{Color(1.f)})}) {
    const RgbImage img = render_scene(sphere_in_environment(m, Color(0.5f)), 256);
    const Color centre = mean_color(img, 8, 8, 24, 24);
    EXPECT_NEAR(centre.g, 0.5f, 0.5f * 0.005f) << "material " << m.index();
  }
}

// Integrating sphere: a point light of intensity I at the centre of a closed
// Lambertian sphere of radius R and albedo rho. The direct irradiance is
// uniform, so the wall radiance is rho * I / (pi R^2 (1 - rho)) everywhere.
TEST(IntegratorAnalytic, IntegratingSphereWithPointLight) {
  const float radius = 2.f, rho = 0.5f, intensity = 3.f;
  SceneDesc d = small_scene(24, 24);
  d.render.max_depth = 200;
  d.camera.look_from = {0.f, 0.f, 1.f};
  d.camera.look_at = {0.f, 0.f, -1.f};
  d.camera.vfov = 60.f;
  d.materials.push_back({"wall", DiffuseDesc{Color(rho)}, {}});
  d.objects.push_back({"shell", SphereDesc{{0.f, 0.f, 0.f}, radius}, {}, "wall", true, {}});
  d.lights.push_back({"bulb", PointLightDesc{{0.f, 0.f, 0.f}, Color(1.f), intensity}});
  const RgbImage img = render_scene(d, 512);
  const float expected = rho * intensity / (kPi * radius * radius * (1.f - rho));
  EXPECT_NEAR(mean_color(img).g, expected, expected * 0.01f);
}

// A Lambertian floor under a spherical area light: at the point straight below,
// E = pi Le (r/d)^2 and the reflected radiance is rho Le (r/d)^2.
TEST(IntegratorAnalytic, FloorUnderSphereLight) {
  const float r = 0.5f, height = 3.f, le = 4.f, rho = 0.6f;
  SceneDesc d = small_scene(33, 33);
  d.camera.look_from = {0.f, 0.2f, 0.f};
  d.camera.look_at = {0.f, -1.f, 0.f};
  d.camera.up = {0.f, 0.f, 1.f};
  d.camera.vfov = 1.f;     // a tiny patch of floor around the point below the light
  d.render.max_depth = 1;  // direct light only: the floor's light does not come back
  d.materials.push_back({"floor", DiffuseDesc{Color(rho)}, {}});
  d.materials.push_back({"lamp", EmissiveDesc{Color(1.f), le, false}, {}});
  d.objects.push_back(
      {"floor", QuadDesc{{-50.f, 0.f, -50.f}, {0.f, 0.f, 100.f}, {100.f, 0.f, 0.f}}, {}, "floor", true, {}});
  d.objects.push_back({"lamp", SphereDesc{{0.f, height, 0.f}, r}, {}, "lamp", true, {}});
  // The camera sits between floor and lamp; hide it from the light with nothing: it is not geometry.
  const RgbImage img = render_scene(d, 256);
  const float expected = rho * le * (r / height) * (r / height);
  EXPECT_NEAR(mean_color(img).g, expected, expected * 0.01f);
}

}  // namespace
}  // namespace inkray
