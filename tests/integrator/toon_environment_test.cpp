// The environment in the toon light level (toon_shading.cpp): weighted by the
// material's `environment`, so a bright sky no longer lifts every side into the top
// band; 0 leaves it out exactly; `environment_shadows` shadows it; both read and
// write as JSON.
#include "core/camera/camera.h"
#include "core/document/json_io.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

using namespace inkray::testing;

constexpr int kSize = 96;
const Color kLit(0.9f, 0.5f, 0.3f);
const Color kShadow = kLit * 0.25f;

// A unit sphere seen from far away, nearly orthographically (as in toon_test.cpp),
// under a key light from +x and a bright constant sky: radiance 1, irradiance pi,
// a little more than the key's 3.
SceneDesc sphere_under_bright_sky(ToonDesc toon) {
  SceneDesc d = small_scene(kSize, kSize);
  d.camera.look_from = {0.f, 0.f, 200.f};
  d.camera.vfov = 2.f * glm::degrees(std::atan(1.15f / 200.f));
  d.materials.push_back({"m", toon, {}});
  d.objects.push_back({"sphere", SphereDesc{{0.f, 0.f, 0.f}, 1.f}, {}, "m", true, {}});
  d.lights.push_back({"sun", DirectionalLightDesc{{-1.f, 0.f, 0.f}, Color(1.f), 3.f}});
  d.environment = ConstantEnvironmentDesc{Color(1.f)};
  return d;
}

ToonDesc two_bands() {
  ToonDesc t;
  t.color = kLit;
  t.shadow_color = Color(0.25f);
  t.bands = 2;
  t.threshold = 0.5f;
  t.softness = 0.f;
  t.specular = false;
  return t;
}

// Pixels wholly covered by the sphere: an unlit white render is exactly 1 there.
std::vector<bool> interior_mask(const SceneDesc& scene) {
  SceneDesc d = scene;
  d.materials[0].data = UnlitDesc{Color(1.f)};
  d.lights.clear();
  d.environment = ConstantEnvironmentDesc{Color(0.f)};
  const RgbImage img = render_scene(d, 4);
  std::vector<bool> mask(img.pixels.size());
  for (size_t i = 0; i < mask.size(); ++i) mask[i] = img.pixels[i].g == 1.f;
  return mask;
}

struct Bands {
  int interior = 0, lit = 0, shadow = 0;
};

Bands count_bands(const RgbImage& img, const std::vector<bool>& mask) {
  Bands b;
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    if (!mask[i]) continue;
    ++b.interior;
    if (max_component(glm::abs(img.pixels[i] - kLit)) < 1e-4f) ++b.lit;
    if (max_component(glm::abs(img.pixels[i] - kShadow)) < 1e-4f) ++b.shadow;
  }
  return b;
}

// At the default weight (0.25) the sky counts as a light of 0.25 pi next to the
// key's 3: the level is n.l + pi / 12, and the terminator sits at n.l = 0.5 - pi / 12
// = 0.238, so 35% of the visible disk is lit and 65% in shadow (bound: 25% each). At
// full weight the sky alone reaches the threshold: no shadow band is left.
TEST(ToonEnvironment, DefaultKeepsBothBandsUnderABrightSky) {
  const ToonDesc toon = two_bands();
  EXPECT_EQ(toon.environment, 0.25f);
  const SceneDesc d = sphere_under_bright_sky(toon);
  const std::vector<bool> mask = interior_mask(d);
  const Bands b = count_bands(render_scene(d, 8), mask);
  ASSERT_GT(b.interior, 2000);
  EXPECT_GT(b.lit, b.interior / 4);
  EXPECT_GT(b.shadow, b.interior / 4);
  const double t = 0.5 - kPi / 12.0;
  const double expected = (std::acos(t) - t * std::sqrt(1.0 - t * t)) / kPi;
  EXPECT_NEAR(double(b.lit) / double(b.lit + b.shadow), expected, 0.01);

  ToonDesc full = toon;
  full.environment = 1.f;
  const Bands washed = count_bands(render_scene(sphere_under_bright_sky(full), 8), mask);
  EXPECT_LT(washed.shadow, washed.interior / 50) << "the sky at full weight lifts every side";
}

// Weight 0: the light level is that of the same scene without a sky, to the bit.
TEST(ToonEnvironment, ZeroWeightIsNoSky) {
  ToonDesc toon = two_bands();
  toon.bands = 3;
  toon.softness = 0.05f;
  toon.environment = 0.f;
  const SceneDesc with_sky = sphere_under_bright_sky(toon);
  SceneDesc without = with_sky;
  without.environment = ConstantEnvironmentDesc{Color(0.f)};
  const std::vector<bool> mask = interior_mask(with_sky);
  const RgbImage a = render_scene(with_sky, 4), b = render_scene(without, 4);
  int compared = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    if (!mask[i]) continue;
    ASSERT_EQ(a.pixels[i], b.pixels[i]) << i;
    ++compared;
  }
  EXPECT_GT(compared, 2000);
}

// A toon ground under a roof (y = 0.5 over x < 0), lit by a constant sky alone, seen
// from below the roof's height. Unshadowed, the sky lights both sides alike; with
// its shadows the ground under the roof, which sees little sky, falls to the
// shadow band while the open ground stays lit.
TEST(ToonEnvironment, ShadowedSkyDarkensWhatIsCovered) {
  auto render = [](bool shadows, Color* under, Color* open) {
    SceneDesc d = small_scene(96, 64);
    d.camera.look_from = {0.f, 0.4f, 8.f};
    d.camera.look_at = {0.f, 0.f, 0.f};
    d.camera.vfov = 40.f;
    ToonDesc toon = two_bands();
    toon.environment_shadows = shadows;
    d.materials.push_back({"toon", toon, {}});
    d.materials.push_back({"grey", DiffuseDesc{Color(0.5f)}, {}});
    d.objects.push_back(
        {"ground", QuadDesc{{-10.f, 0.f, -10.f}, {0.f, 0.f, 20.f}, {20.f, 0.f, 0.f}}, {}, "toon", true, {}});
    d.objects.push_back(
        {"roof", QuadDesc{{-10.f, 0.5f, -10.f}, {0.f, 0.f, 20.f}, {10.f, 0.f, 0.f}}, {}, "grey", true, {}});
    d.environment = ConstantEnvironmentDesc{Color(0.8f)};
    const RgbImage img = render_scene(d, 64);
    const Camera camera(d.camera, 96, 64);
    auto window = [&](Point3 p) {
      Vec2 film;
      EXPECT_TRUE(camera.project(p, &film));
      const int x = std::clamp(int(film.x), 1, 94), y = std::clamp(int(film.y), 1, 62);
      EXPECT_EQ(x, int(film.x));
      EXPECT_EQ(y, int(film.y));
      return mean_color(img, x - 1, y - 1, x + 2, y + 2);
    };
    // 2.5 from the roof's edge, which is 0.5 high: 2% of the cosine-weighted sky
    // is on the other side of the edge.
    *under = window({-2.5f, 0.f, 2.f});
    *open = window({2.5f, 0.f, 2.f});
  };
  Color under, open;
  render(false, &under, &open);
  EXPECT_NEAR(under.g, kLit.g, 1e-4f);
  EXPECT_NEAR(open.g, kLit.g, 1e-4f);
  render(true, &under, &open);
  EXPECT_GT(open.g, kLit.g * 0.9f) << "the open ground sees nearly all the sky";
  EXPECT_LT(under.g, kShadow.g + 0.3f * (kLit.g - kShadow.g)) << "the covered ground sees little of it";
}

TEST(ToonEnvironment, ParametersRoundTripThroughJson) {
  const char* text = R"({"format": "inkray-scene", "version": 1,
    "materials": [{"name": "cel", "type": "toon", "environment": 0.6, "environment_shadows": true},
                  {"name": "plain", "type": "toon"}],
    "objects": [{"name": "ball", "material": "cel"}]})";
  const SceneLoadResult r = parse_scene(text, {}, "t.json");
  ASSERT_TRUE(r) << (r.errors.empty() ? "" : r.errors.front());
  const ToonDesc& cel = std::get<ToonDesc>(r.scene->materials[0].data);
  EXPECT_EQ(cel.environment, 0.6f);
  EXPECT_TRUE(cel.environment_shadows);
  const ToonDesc& plain = std::get<ToonDesc>(r.scene->materials[1].data);
  EXPECT_EQ(plain.environment, 0.25f);
  EXPECT_FALSE(plain.environment_shadows);

  const std::string written = scene_to_string(*r.scene);
  EXPECT_NE(written.find("\"environment_shadows\": true"), std::string::npos) << written;
  const SceneLoadResult again = parse_scene(written, {}, "t.json");
  ASSERT_TRUE(again);
  EXPECT_EQ(again.scene->materials, r.scene->materials);

  const char* out_of_range = R"({"format": "inkray-scene", "version": 1,
    "materials": [{"name": "cel", "type": "toon", "environment": -1}]})";
  EXPECT_FALSE(parse_scene(out_of_range, {}, "t.json"));
}

}  // namespace
}  // namespace inkray
