// The toon material's shading curves: bands, ramps, specular band and rim, as
// pure functions of the light level and angles.
#include "core/materials/toon.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

ToonMaterial hard_toon(int bands, float threshold) {
  ToonMaterial m;
  m.color = ConstantTexture{Color(1.f)};
  m.bands = bands;
  m.threshold = threshold;
  m.softness = 0.f;
  return m;
}

TEST(ToonMaterial, SoftStepIsHardAtZeroWidth) {
  EXPECT_EQ(toon_soft_step(0.49f, 0.5f, 0.f), 0.f);
  EXPECT_EQ(toon_soft_step(0.5f, 0.5f, 0.f), 1.f);
  EXPECT_EQ(toon_soft_step(0.44f, 0.5f, 0.1f), 0.f);
  EXPECT_FLOAT_EQ(toon_soft_step(0.5f, 0.5f, 0.1f), 0.5f);
  EXPECT_EQ(toon_soft_step(0.56f, 0.5f, 0.1f), 1.f);
}

TEST(ToonMaterial, TwoBandsSplitAtThreshold) {
  const ToonMaterial m = hard_toon(2, 0.4f);
  EXPECT_EQ(toon_band_level(m, 0.f), 0.f);
  EXPECT_EQ(toon_band_level(m, 0.39f), 0.f);
  EXPECT_EQ(toon_band_level(m, 0.4f), 1.f);
  EXPECT_EQ(toon_band_level(m, 1.f), 1.f);
}

TEST(ToonMaterial, MoreBandsAreEvenFromThresholdUp) {
  // Four bands from 0.4: edges at 0.4, 0.6, 0.8.
  const ToonMaterial m = hard_toon(4, 0.4f);
  EXPECT_FLOAT_EQ(toon_band_level(m, 0.3f), 0.f);
  EXPECT_FLOAT_EQ(toon_band_level(m, 0.5f), 1.f / 3.f);
  EXPECT_FLOAT_EQ(toon_band_level(m, 0.7f), 2.f / 3.f);
  EXPECT_FLOAT_EQ(toon_band_level(m, 0.9f), 1.f);
}

TEST(ToonMaterial, BandColoursRunFromShadowToLit) {
  ToonMaterial m = hard_toon(3, 0.5f);
  m.shadow_color = Color(0.2f, 0.3f, 0.4f);
  const Color base(0.5f, 1.f, 0.8f);
  ToonLightInput in;
  in.level = 0.1f;
  EXPECT_EQ(toon_base_color(m, base, in), base * m.shadow_color);
  in.level = 0.6f;
  EXPECT_EQ(toon_base_color(m, base, in), base * glm::mix(m.shadow_color, Color(1.f), 0.5f));
  in.level = 1.f;
  EXPECT_EQ(toon_base_color(m, base, in), base);
  // A coloured light tints the lit band, not the darkest one.
  in.tint = Color(1.f, 0.5f, 0.f);
  EXPECT_EQ(toon_base_color(m, base, in), base * in.tint);
  in.level = 0.f;
  EXPECT_EQ(toon_base_color(m, base, in), base * m.shadow_color);
}

TEST(ToonMaterial, SoftnessBlendsNeighbouringBands) {
  ToonMaterial m = hard_toon(2, 0.5f);
  m.softness = 0.1f;
  EXPECT_FLOAT_EQ(toon_band_level(m, 0.5f), 0.5f);
  EXPECT_GT(toon_band_level(m, 0.52f), 0.5f);
  EXPECT_LT(toon_band_level(m, 0.52f), 1.f);
}

TEST(ToonMaterial, RampStopsAreEvenlySpaced) {
  const std::vector<Color> stops = {Color(0.f), Color(1.f, 0.f, 0.f), Color(1.f)};
  EXPECT_EQ(toon_ramp_eval(stops, 0.f), Color(0.f));
  EXPECT_EQ(toon_ramp_eval(stops, 0.5f), Color(1.f, 0.f, 0.f));
  EXPECT_EQ(toon_ramp_eval(stops, 1.f), Color(1.f));
  EXPECT_EQ(toon_ramp_eval(stops, 2.f), Color(1.f));
  EXPECT_EQ(toon_ramp_eval(stops, -1.f), Color(0.f));
  const Color quarter = toon_ramp_eval(stops, 0.25f);
  EXPECT_FLOAT_EQ(quarter.r, 0.5f);
  EXPECT_FLOAT_EQ(quarter.g, 0.f);
  EXPECT_EQ(toon_ramp_eval({Color(0.3f)}, 0.7f), Color(0.3f));

  ToonMaterial m = hard_toon(2, 0.5f);
  m.ramp = std::make_shared<const std::vector<Color>>(stops);
  ToonLightInput in;
  in.level = 0.5f;
  EXPECT_EQ(toon_base_color(m, Color(0.5f), in), Color(0.5f, 0.f, 0.f));
}

TEST(ToonMaterial, RampImageIsLightAcrossAndAxisUp) {
  auto image = std::make_shared<RgbImage>();
  image->width = 2;
  image->height = 2;
  // Row 0 is the top (v = 1).
  image->pixels = {Color(0.f, 0.f, 1.f), Color(1.f, 1.f, 1.f), Color(0.f), Color(1.f, 0.f, 0.f)};
  EXPECT_EQ(toon_ramp_image_eval(*image, 0.f, 0.f), Color(0.f));
  EXPECT_EQ(toon_ramp_image_eval(*image, 1.f, 0.f), Color(1.f, 0.f, 0.f));
  EXPECT_EQ(toon_ramp_image_eval(*image, 0.f, 1.f), Color(0.f, 0.f, 1.f));
  EXPECT_EQ(toon_ramp_image_eval(*image, 1.f, 1.f), Color(1.f));
  EXPECT_EQ(toon_ramp_image_eval(*image, 0.5f, 0.f), Color(0.5f, 0.f, 0.f));

  ToonMaterial m = hard_toon(2, 0.5f);
  m.ramp_image = image;
  m.ramp = std::make_shared<const std::vector<Color>>(std::vector<Color>{Color(0.5f)});  // the image wins
  ToonLightInput in;
  in.level = 1.f;
  in.ramp_v = 1.f;
  EXPECT_EQ(toon_base_color(m, Color(1.f), in), Color(1.f));
}

TEST(ToonMaterial, SpecularBandCutFromBlinnPhong) {
  ToonMaterial m = hard_toon(2, 0.5f);
  m.specular_size = 0.1f;
  m.shininess = 40.f;
  // (n.h)^40 > 0.9 exactly where n.h > 0.9^(1/40).
  const float edge = std::pow(0.9f, 1.f / 40.f);
  EXPECT_EQ(toon_specular_coverage(m, edge + 1e-4f, 1.f), 1.f);
  EXPECT_EQ(toon_specular_coverage(m, edge - 1e-4f, 1.f), 0.f);
  EXPECT_EQ(toon_specular_coverage(m, 1.f, 0.5f), 0.f)
      << "a light at half strength makes no band of size 0.1";
  m.specular_size = 0.6f;
  EXPECT_EQ(toon_specular_coverage(m, 1.f, 0.5f), 1.f);
  m.specular = false;
  EXPECT_EQ(toon_specular_coverage(m, 1.f, 1.f), 0.f);
}

TEST(ToonMaterial, RimIsABandOfFacingRatio) {
  ToonMaterial m = hard_toon(2, 0.5f);
  m.rim = true;
  m.rim_threshold = 0.5f;
  m.rim_width = 0.3f;
  EXPECT_EQ(toon_rim_coverage(m, 1.f), 0.f);   // facing the viewer
  EXPECT_EQ(toon_rim_coverage(m, 0.4f), 1.f);  // 1 - n.wo = 0.6
  EXPECT_EQ(toon_rim_coverage(m, 0.1f), 0.f);  // beyond the band's outer edge 0.8
  m.rim_width = 0.5f;                          // reaches the silhouette: open there
  EXPECT_EQ(toon_rim_coverage(m, 0.f), 1.f);
  m.rim = false;
  EXPECT_EQ(toon_rim_coverage(m, 0.f), 0.f);
}

}  // namespace
}  // namespace inkray
