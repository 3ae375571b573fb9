// HSV <-> RGB: known values, round trips, hue wrap and clamping of jitter.
#include "core/math/color_space.h"

#include "support/color_checks.h"

#include <gtest/gtest.h>

#include <random>

namespace inkray {
namespace {

using testing::expect_color_near;

TEST(ColorSpace, KnownValues) {
  struct Case {
    Color rgb, hsv;
  };
  const Case cases[] = {
      {{1.f, 0.f, 0.f}, {0.f, 1.f, 1.f}},        {{0.f, 1.f, 0.f}, {120.f, 1.f, 1.f}},
      {{0.f, 0.f, 1.f}, {240.f, 1.f, 1.f}},      {{1.f, 1.f, 0.f}, {60.f, 1.f, 1.f}},
      {{0.f, 1.f, 1.f}, {180.f, 1.f, 1.f}},      {{1.f, 0.f, 1.f}, {300.f, 1.f, 1.f}},
      {{0.5f, 0.25f, 0.f}, {30.f, 1.f, 0.5f}},   {{0.8f, 0.4f, 0.4f}, {0.f, 0.5f, 0.8f}},
      {{0.2f, 0.4f, 0.3f}, {150.f, 0.5f, 0.4f}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(::testing::Message() << c.rgb.x << " " << c.rgb.y << " " << c.rgb.z);
    expect_color_near(rgb_to_hsv(c.rgb), c.hsv);
    expect_color_near(hsv_to_rgb(c.hsv), c.rgb);
  }
}

TEST(ColorSpace, GreyHasNoHueOrSaturation) {
  for (float v : {0.f, 0.18f, 0.5f, 1.f}) {
    expect_color_near(rgb_to_hsv(Color(v)), {0.f, 0.f, v});
    // Any hue gives the same grey when saturation is 0.
    expect_color_near(hsv_to_rgb({123.f, 0.f, v}), Color(v));
  }
}

TEST(ColorSpace, RoundTripOnRandomColours) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (int i = 0; i < 10000; ++i) {
    const Color rgb(u(rng), u(rng), u(rng));
    const Color hsv = rgb_to_hsv(rgb);
    ASSERT_GE(hsv.x, 0.f);
    ASSERT_LT(hsv.x, 360.f);
    ASSERT_GE(hsv.y, 0.f);
    ASSERT_LE(hsv.y, 1.f);
    expect_color_near(hsv_to_rgb(hsv), rgb, 2e-6f);
  }
}

TEST(ColorSpace, HueWraps) {
  expect_color_near(hsv_to_rgb({360.f, 1.f, 1.f}), {1.f, 0.f, 0.f});
  expect_color_near(hsv_to_rgb({-120.f, 1.f, 1.f}), hsv_to_rgb({240.f, 1.f, 1.f}));
  expect_color_near(hsv_to_rgb({725.f, 0.5f, 0.7f}), hsv_to_rgb({5.f, 0.5f, 0.7f}));
  expect_color_near(hsv_to_rgb({-1e-9f, 1.f, 1.f}), {1.f, 0.f, 0.f});
  // Red shifted by -30 degrees is a magenta-red of hue 330.
  EXPECT_NEAR(rgb_to_hsv(jitter_hsv({1.f, 0.f, 0.f}, -30.f, 0.f, 0.f)).x, 330.f, 1e-3f);
  // Hue just below 360 stays just below 360 and does not round to an invalid 360.
  EXPECT_LT(rgb_to_hsv({1.f, 0.f, 1e-7f}).x, 360.f);
}

TEST(ColorSpace, JitterClampsSaturationAndValue) {
  const Color c{0.8f, 0.4f, 0.2f};
  expect_color_near(jitter_hsv(c, 0.f, 0.f, 0.f), c);
  const Color brighter = rgb_to_hsv(jitter_hsv(c, 0.f, 5.f, 5.f));
  EXPECT_FLOAT_EQ(brighter.y, 1.f);
  EXPECT_FLOAT_EQ(brighter.z, 1.f);
  expect_color_near(jitter_hsv(c, 0.f, 0.f, -5.f), Color(0.f));
  expect_color_near(jitter_hsv(c, 0.f, -5.f, 0.f), Color(0.8f));
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  for (int i = 0; i < 1000; ++i) {
    const Color j = jitter_hsv(Color(0.5f + 0.5f * u(rng), 0.3f, 0.6f), 400.f * u(rng), u(rng), u(rng));
    ASSERT_TRUE(is_finite(j));
    ASSERT_GE(glm::min(j.r, glm::min(j.g, j.b)), 0.f);
    ASSERT_LE(max_component(j), 1.f);
  }
}

}  // namespace
}  // namespace inkray
