// The toon and mix materials in the path tracer: band values, terminator
// placement, shadows, highlights and rims against closed-form answers; mixes in
// a white furnace.
#include "core/camera/camera.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inkray {
namespace {

using namespace inkray::testing;

constexpr int kSize = 96;

// A unit sphere seen from far away through a narrow lens: nearly orthographic,
// so the visible disk is the hemisphere facing +z and areas have closed forms.
SceneDesc far_sphere(MaterialVariant material, std::vector<LightDesc> lights) {
  SceneDesc d = small_scene(kSize, kSize);
  d.camera.look_from = {0.f, 0.f, 200.f};
  d.camera.vfov = 2.f * glm::degrees(std::atan(1.15f / 200.f));
  d.materials.push_back({"m", std::move(material), {}});
  d.objects.push_back({"sphere", SphereDesc{{0.f, 0.f, 0.f}, 1.f}, {}, "m", true, {}});
  d.lights = std::move(lights);
  return d;
}

ToonDesc plain_toon(ColorInput color, int bands, float threshold) {
  ToonDesc t;
  t.color = color;
  t.shadow_color = Color(0.25f);
  t.bands = bands;
  t.threshold = threshold;
  t.softness = 0.f;
  t.specular = false;
  t.rim = false;
  t.receive_indirect = false;
  return t;
}

LightDesc directional(Vec3 travel, float intensity = 1.f) {
  return {"sun", DirectionalLightDesc{travel, Color(1.f), intensity}};
}

// Pixels wholly covered by the sphere: an unlit white render is exactly 1 there.
std::vector<bool> interior_mask(const SceneDesc& scene) {
  SceneDesc d = scene;
  d.materials[0].data = UnlitDesc{Color(1.f)};
  d.lights.clear();
  const RgbImage img = render_scene(d, 4);
  std::vector<bool> mask(img.pixels.size());
  for (size_t i = 0; i < mask.size(); ++i) mask[i] = img.pixels[i].g == 1.f;
  return mask;
}

// The scene rendered, and beside it the same scene in unlit white: how much of each
// pixel the sphere covers.
struct ImageAndCoverage {
  RgbImage image, coverage;
};
ImageAndCoverage render_with_coverage(const SceneDesc& scene, int spp) {
  SceneDesc white = scene;
  white.materials[0].data = UnlitDesc{Color(1.f)};
  return {render_scene(scene, spp), render_scene(white, spp)};
}

std::vector<Color> band_values(Color color, int bands) {
  std::vector<Color> values;
  for (int k = 0; k < bands; ++k)
    values.push_back(color * glm::mix(Color(0.25f), Color(1.f), float(k) / float(bands - 1)));
  return values;
}

struct BandCount {
  int interior = 0;
  int off_band = 0;  // mixed pixels on a band boundary
  std::vector<int> per_band;
};

BandCount count_bands(const RgbImage& img, const std::vector<bool>& mask, const std::vector<Color>& values) {
  BandCount c;
  c.per_band.assign(values.size(), 0);
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    if (!mask[i]) continue;
    ++c.interior;
    bool matched = false;
    for (size_t k = 0; k < values.size() && !matched; ++k) {
      if (max_component(glm::abs(img.pixels[i] - values[k])) < 1e-4f) {
        ++c.per_band[k];
        matched = true;
      }
    }
    if (!matched) ++c.off_band;
  }
  return c;
}

// Bands are exact: a pixel off every band value is one a band edge crosses.
// Tolerance: 1e-4 per channel for a band value; under 8% of interior pixels mixed.
void expect_clean_bands(const SceneDesc& d, const Color& color, int bands) {
  const std::vector<bool> mask = interior_mask(d);
  const RgbImage img = render_scene(d, 8);
  const BandCount c = count_bands(img, mask, band_values(color, bands));
  ASSERT_GT(c.interior, 2000);
  EXPECT_LT(c.off_band, c.interior * 8 / 100);
  for (int k = 0; k < bands; ++k) EXPECT_GT(c.per_band[size_t(k)], 0) << "band " << k << " is missing";
}

TEST(ToonIntegrator, DirectionalLightGivesExactBands) {
  const Color color(0.9f, 0.5f, 0.3f);
  for (int bands : {2, 3}) {
    SCOPED_TRACE(bands);
    expect_clean_bands(far_sphere(plain_toon(color, bands, 0.4f), {directional({-1.f, -0.6f, -0.5f}, 3.f)}),
                       color, bands);
  }
}

TEST(ToonIntegrator, PointLightGivesExactBands) {
  const Color color(0.3f, 0.6f, 0.9f);
  for (int bands : {2, 3}) {
    SCOPED_TRACE(bands);
    const LightDesc bulb{"bulb", PointLightDesc{{4.f, 3.f, 3.f}, Color(1.f), 40.f}};
    expect_clean_bands(far_sphere(plain_toon(color, bands, 0.4f), {bulb}), color, bands);
  }
}

// A small, distant area light: every sample of it puts a pixel in the same band
// except across the narrow penumbra of the terminator, so bands stay clean.
TEST(ToonIntegrator, SmallAreaLightConvergesToCleanBands) {
  const Color color(0.8f, 0.8f, 0.4f);
  SceneDesc d = far_sphere(plain_toon(color, 3, 0.3f), {});
  d.materials.push_back({"lamp", EmissiveDesc{Color(1.f), 2000.f, false}, {}});
  d.objects.push_back({"lamp", SphereDesc{{-12.f, 8.f, 6.f}, 0.1f}, {}, "lamp", true, {}});
  expect_clean_bands(d, color, 3);
}

// Under one directional light the level is n.l, so with light from +x the lit
// part of the visible disk is x > threshold: area (acos t - t sqrt(1 - t^2)) / pi.
TEST(ToonIntegrator, ThresholdPlacesTheTerminatorAnalytically) {
  for (float t : {0.2f, 0.5f, 0.8f}) {
    SCOPED_TRACE(t);
    ToonDesc toon = plain_toon(Color(1.f), 2, t);
    toon.shadow_color = Color(0.f);
    const auto [img, mask] =
        render_with_coverage(far_sphere(toon, {directional({-1.f, 0.f, 0.f}, 0.7f)}), 16);
    double lit = 0.0, disk = 0.0;
    for (size_t i = 0; i < img.pixels.size(); ++i) {
      lit += img.pixels[i].g;
      disk += mask.pixels[i].g;
    }
    const double expected = (std::acos(t) - t * std::sqrt(1.0 - t * t)) / kPi;
    EXPECT_NEAR(lit / disk, expected, 0.005);
  }
}

// The sky is exact, unshadowed ambient light: a constant sky of radiance 0.3
// gives irradiance 0.3 pi everywhere, which at full weight (environment 1; the
// default 0.25 is toon_environment_test.cpp's) lifts the level by 0.3 pi / 3 under
// a key light of 3, moving the terminator to n.l = 0.5 - 0.1 pi, with no noise.
TEST(ToonIntegrator, EnvironmentIsExactAmbientLight) {
  ToonDesc toon = plain_toon(Color(1.f), 2, 0.5f);
  toon.shadow_color = Color(0.f);
  toon.environment = 1.f;
  SceneDesc d = far_sphere(toon, {directional({-1.f, 0.f, 0.f}, 3.f)});
  d.environment = ConstantEnvironmentDesc{Color(0.3f)};
  const std::vector<bool> mask = interior_mask(d);
  const RgbImage img = render_scene(d, 8);
  const BandCount c = count_bands(img, mask, {Color(0.f), Color(1.f)});
  EXPECT_LT(c.off_band, c.interior * 8 / 100);
  const double t = 0.5 - 0.1 * kPi;
  const double expected = (std::acos(t) - t * std::sqrt(1.0 - t * t)) / kPi;
  EXPECT_NEAR(double(c.per_band[1]) / double(c.per_band[0] + c.per_band[1]), expected, 0.01);
}

TEST(ToonIntegrator, ShadowFallsInTheDarkestBand) {
  const Color color(0.6f, 0.9f, 0.6f);
  SceneDesc d = small_scene(64, 64);
  d.camera.look_from = {0.f, 10.f, 0.f};
  d.camera.look_at = {0.f, 0.f, 0.f};
  d.camera.up = {0.f, 0.f, -1.f};
  d.camera.vfov = 30.f;
  d.materials.push_back({"toon", plain_toon(color, 3, 0.3f), {}});
  d.materials.push_back({"grey", DiffuseDesc{Color(0.5f)}, {}});
  d.objects.push_back(
      {"ground", QuadDesc{{-5.f, 0.f, -5.f}, {0.f, 0.f, 10.f}, {10.f, 0.f, 0.f}}, {}, "toon", true, {}});
  d.objects.push_back({"ball", SphereDesc{{0.f, 1.5f, 0.f}, 0.5f}, {}, "grey", true, {}});
  d.lights.push_back(directional({1.f, -1.f, 0.f}, 2.f));  // n.l = 0.71 on the ground: the top band
  const RgbImage img = render_scene(d, 8);
  const Camera camera(d.camera, 64, 64);
  auto pixel_at = [&](Point3 p) {
    Vec2 film;
    EXPECT_TRUE(camera.project(p, &film));
    return img.at(int(film.x), int(film.y));
  };
  const Color in_shadow = pixel_at({1.5f, 0.f, 0.f});  // below the ball along the light
  const Color in_light = pixel_at({-1.5f, 0.f, 1.5f});
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(in_shadow[c], color[c] * 0.25f, 1e-4f);
    EXPECT_NEAR(in_light[c], color[c], 1e-4f);
  }
}

// Seen in a perfect mirror (F0 = 1), a toon surface shows its bands, not the
// diffuse radiance other bounces see.
TEST(ToonIntegrator, MirrorsShowTheToonLook) {
  const Color color(0.9f, 0.6f, 0.3f);
  SceneDesc d = small_scene(64, 64);
  d.camera.look_from = {0.f, -1.9f, 10.f};
  d.camera.look_at = {0.f, -4.f, 0.f};
  d.camera.vfov = 16.f;  // the sphere itself is out of view; its reflection fills the frame
  d.materials.push_back({"toon", plain_toon(color, 3, 0.3f), {}});
  d.materials.push_back({"mirror", ConductorDesc{Color(1.f), 0.f}, {}});
  d.objects.push_back({"ball", SphereDesc{{0.f, 0.f, 0.f}, 1.f}, {}, "toon", true, {}});
  d.objects.push_back({"mirror",
                       QuadDesc{{-50.f, -2.f, -50.f}, {0.f, 0.f, 100.f}, {100.f, 0.f, 0.f}},
                       {},
                       "mirror",
                       true,
                       {}});
  d.lights.push_back(directional({-1.f, 0.f, -0.3f}, 2.f));
  const RgbImage img = render_scene(d, 8);
  std::vector<Color> values = band_values(color, 3);
  values.push_back(Color(0.f));  // the mirror reflecting the black sky
  const BandCount c = count_bands(img, std::vector<bool>(img.pixels.size(), true), values);
  EXPECT_LT(c.off_band, c.interior * 8 / 100);
  for (int k = 0; k < 3; ++k) EXPECT_GT(c.per_band[size_t(k)], 50) << "band " << k;
}

// Light from the camera: the half vector is the view direction, so the band is
// where (n.h)^k > 1 - size, a disk of radius^2 = 1 - (1 - size)^(2/k).
TEST(ToonIntegrator, SpecularBandAddsItsColourAroundTheHighlight) {
  ToonDesc toon = plain_toon(Color(0.5f), 2, 0.5f);
  toon.specular = true;
  toon.specular_color = Color(0.5f);
  toon.specular_size = 0.3f;
  toon.shininess = 10.f;
  SceneDesc d = far_sphere(toon, {directional({0.f, 0.f, -1.f})});
  const RgbImage img = render_scene(d, 16);
  const Color centre = img.at(kSize / 2, kSize / 2);
  EXPECT_NEAR(centre.g, 1.f, 1e-4f);
  const std::vector<bool> mask = interior_mask(d);
  int highlight = 0, interior = 0;
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    if (!mask[i]) continue;
    ++interior;
    if (img.pixels[i].g > 0.75f) ++highlight;
  }
  const double expected = 1.0 - std::pow(0.7, 2.0 / 10.0);
  EXPECT_NEAR(double(highlight) / double(interior), expected, 0.012);
}

// Rim where 1 - n.wo > 0.5 (open to the silhouette): the ring r > sqrt(0.75), a quarter of the disk.
TEST(ToonIntegrator, RimCoversTheOuterRing) {
  ToonDesc toon = plain_toon(Color(0.4f), 2, 0.f);
  toon.rim = true;
  toon.rim_color = Color(0.5f);
  toon.rim_threshold = 0.5f;
  toon.rim_width = 0.6f;
  const auto [img, mask] = render_with_coverage(far_sphere(toon, {directional({0.f, 0.f, -1.f})}), 16);
  double rim = 0.0, disk = 0.0;
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    rim += std::max(0.f, img.pixels[i].g - 0.4f * mask.pixels[i].g) / 0.5f;
    disk += mask.pixels[i].g;
  }
  EXPECT_NEAR(rim / disk, 0.25, 0.015);
}

// Every light type at once, with textures, ramps, rims, indirect light and a mix.
SceneDesc busy_scene() {
  SceneDesc d = small_scene(48, 48);
  d.camera.look_from = {0.f, 2.f, 6.f};
  d.camera.look_at = {0.f, 0.5f, 0.f};
  ToonDesc banded = plain_toon(Color(0.9f, 0.3f, 0.2f), 3, 0.3f);
  banded.softness = 0.05f;
  banded.specular = true;
  banded.rim = true;
  banded.receive_indirect = true;
  ToonDesc ramp = plain_toon(CheckerTextureDesc{}, 2, 0.5f);
  ramp.ramp = {Color(0.1f, 0.1f, 0.3f), Color(0.5f, 0.4f, 0.8f), Color(1.f, 0.9f, 0.7f)};
  ramp.bounce_indirect = false;
  ramp.ramp_axis = ToonRampAxis::facing;
  d.materials.push_back({"banded", banded, {}});
  d.materials.push_back({"ramp", ramp, {}});
  d.materials.push_back({"white", DiffuseDesc{Color(0.8f)}, {}});
  d.materials.push_back({"mirror", ConductorDesc{Color(0.9f), 0.f}, {}});
  d.materials.push_back({"blend", MixDesc{"banded", "white", Color(0.5f)}, {}});
  d.materials.push_back({"lamp", EmissiveDesc{Color(1.f, 0.9f, 0.8f), 10.f, false}, {}});
  d.objects.push_back(
      {"ground", QuadDesc{{-5.f, 0.f, -5.f}, {0.f, 0.f, 10.f}, {10.f, 0.f, 0.f}}, {}, "ramp", true, {}});
  d.objects.push_back({"a", SphereDesc{{-1.2f, 0.7f, 0.f}, 0.7f}, {}, "banded", true, {}});
  d.objects.push_back({"b", SphereDesc{{1.2f, 0.7f, 0.f}, 0.7f}, {}, "blend", true, {}});
  d.objects.push_back({"c", BoxDesc{{-0.4f, 0.f, -1.5f}, {0.4f, 1.5f, -1.2f}}, {}, "mirror", true, {}});
  d.objects.push_back({"lamp", SphereDesc{{0.f, 3.f, 1.f}, 0.2f}, {}, "lamp", true, {}});
  d.lights.push_back(directional({-0.5f, -1.f, -0.3f}, 1.5f));
  d.lights.push_back({"bulb", PointLightDesc{{2.f, 2.f, 2.f}, Color(1.f, 0.8f, 0.6f), 8.f}});
  d.lights.push_back(
      {"spot", SpotLightDesc{{-2.f, 3.f, 1.f}, {-1.f, 0.f, 0.f}, Color(0.6f, 0.7f, 1.f), 30.f, 30.f, 20.f}});
  d.environment = GradientEnvironmentDesc{};
  return d;
}

TEST(ToonIntegrator, MixedLightsAreFiniteAndStable) {
  const SceneDesc d = busy_scene();
  RenderStats stats;
  const RgbImage a = render_scene(d, 16, 2, &stats);
  EXPECT_EQ(stats.nonfinite_samples, 0u);
  for (const Color& c : a.pixels) ASSERT_TRUE(is_finite(c));
  EXPECT_GT(mean_color(a).g, 0.05f);
  // A fixed seed gives the same bands at any thread count: no flicker between renders.
  const RgbImage b = render_scene(d, 16, 3);
  EXPECT_TRUE(a.pixels == b.pixels);
}

// Light bouncing off a bright floor lifts the sphere's shadow band only when
// receive_indirect is on; the lit bands are what the direct light shows. The
// indirect light is relative to the key light, like the bands, so a stronger
// light gives the same picture.
TEST(ToonIntegrator, ReceiveIndirectLiftsTheShadowBand) {
  auto render = [](bool indirect, float intensity) {
    SceneDesc d = small_scene(32, 32);
    d.camera.look_from = {0.f, 0.f, 8.f};
    d.camera.look_at = {0.f, 0.f, 0.f};
    d.camera.vfov = 20.f;
    ToonDesc toon = plain_toon(Color(0.8f), 2, 0.5f);
    toon.receive_indirect = indirect;
    d.materials.push_back({"toon", toon, {}});
    d.materials.push_back({"floor", DiffuseDesc{Color(0.9f)}, {}});
    d.objects.push_back({"ball", SphereDesc{{0.f, 0.f, 0.f}, 1.f}, {}, "toon", true, {}});
    d.objects.push_back({"floor",
                         QuadDesc{{-20.f, -1.01f, -20.f}, {0.f, 0.f, 40.f}, {40.f, 0.f, 0.f}},
                         {},
                         "floor",
                         true,
                         {}});
    d.lights.push_back(directional({0.f, -1.f, 0.f}, intensity));
    return render_scene(d, 64);
  };
  const RgbImage off = render(false, 3.f), on = render(true, 3.f), on_bright = render(true, 30.f);
  // The lower half of the sphere faces away from the light: the shadow band.
  const Color dark_off = mean_color(off, 14, 21, 18, 25), dark_on = mean_color(on, 14, 21, 18, 25);
  EXPECT_NEAR(dark_off.g, 0.8f * 0.25f, 1e-3f);
  EXPECT_GT(dark_on.g, dark_off.g + 0.05f);
  EXPECT_NEAR(mean_color(on_bright, 14, 21, 18, 25).g, dark_on.g, 0.03f * dark_on.g);
  const Color lit_off = mean_color(off, 14, 5, 18, 8), lit_on = mean_color(on, 14, 5, 18, 8);
  EXPECT_NEAR(lit_off.g, 0.8f, 1e-3f);
  EXPECT_GE(lit_on.g, lit_off.g);
}

// ---------------------------------------------------------------- mix

SceneDesc furnace(std::vector<MaterialDesc> materials, const std::string& material) {
  SceneDesc d = small_scene(32, 32);
  d.camera.look_from = {0.f, 0.f, 4.f};
  d.camera.vfov = 20.f;
  d.materials = std::move(materials);
  d.objects.push_back({"sphere", SphereDesc{{0.f, 0.f, 0.f}, 1.f}, {}, material, true, {}});
  d.environment = ConstantEnvironmentDesc{Color(1.f)};
  return d;
}

std::vector<MaterialDesc> dark_and_light(ColorInput factor) {
  // The mix comes first: it may refer to materials later in the list.
  return {{"mix", MixDesc{"dark", "light", std::move(factor)}, {}},
          {"dark", DiffuseDesc{Color(0.2f)}, {}},
          {"light", DiffuseDesc{Color(0.8f)}, {}}};
}

TEST(MixMaterial, HalfAndHalfConvergesToTheAverage) {
  const RgbImage img = render_scene(furnace(dark_and_light(Color(0.5f)), "mix"), 256);
  const Color centre = mean_color(img, 10, 10, 22, 22);
  EXPECT_NEAR(centre.g, 0.5f, 0.005f);
}

TEST(MixMaterial, FactorZeroAndOneAreExactlyEachSide) {
  const RgbImage dark = render_scene(furnace(dark_and_light(Color(0.f)), "dark"), 16);
  const RgbImage light = render_scene(furnace(dark_and_light(Color(0.f)), "light"), 16);
  EXPECT_TRUE(render_scene(furnace(dark_and_light(Color(0.f)), "mix"), 16).pixels == dark.pixels);
  EXPECT_TRUE(render_scene(furnace(dark_and_light(Color(1.f)), "mix"), 16).pixels == light.pixels);
}

TEST(MixMaterial, NestedMixesAndTexturedFactors) {
  // mix2 = 0.25 * mix + 0.75 * black-ish; mix = half of 0.2 and 0.8.
  std::vector<MaterialDesc> m = dark_and_light(CheckerTextureDesc{Color(1.f), Color(0.f), 400.f});
  m.push_back({"black", DiffuseDesc{Color(0.f)}, {}});
  m.insert(m.begin(), {"outer", MixDesc{"black", "mix", Color(0.25f)}, {}});
  const RgbImage img = render_scene(furnace(m, "outer"), 256);
  EXPECT_NEAR(mean_color(img, 10, 10, 22, 22).g, 0.25f * 0.5f, 0.006f);
}

TEST(MixMaterial, CyclesAndUnknownNamesFailToCompile) {
  SceneDesc d = furnace(dark_and_light(Color(0.5f)), "mix");
  d.materials.push_back({"loop_a", MixDesc{"loop_b", "dark", Color(0.5f)}, {}});
  d.materials.push_back({"loop_b", MixDesc{"light", "loop_a", Color(0.5f)}, {}});
  d.materials.push_back({"self", MixDesc{"self", "dark", Color(0.5f)}, {}});
  d.materials.push_back({"behind", MixDesc{"loop_a", "dark", Color(0.5f)}, {}});
  d.materials.push_back({"lost", MixDesc{"nowhere", "dark", Color(0.5f)}, {}});
  const CompileResult r = compile_scene(d);
  EXPECT_FALSE(r.scene);
  std::string all;
  for (const std::string& e : r.errors) all += e + "\n";
  // compile_scene checks the document first, so the messages are the reader's.
  for (const char* part :
       {"materials[4].b: mixes refer to each other in a cycle: \"loop_a\" -> \"loop_b\" -> \"loop_a\"",
        "materials[5].a: mix \"self\" refers to itself", "materials[7].a: no material named \"nowhere\""})
    EXPECT_NE(all.find(part), std::string::npos) << part << "\n" << all;
  EXPECT_EQ(all.find("materials[0]"), std::string::npos) << all;
}

}  // namespace
}  // namespace inkray
