// Stroke colours: the material's colour at the root, jittered in HSV, always
// finite and within the displayable range, and reproducible.
#include "core/npr/strokes/stroke_color.h"
#include "core/npr/strokes/stroke_placement.h"
#include "npr/strokes/stroke_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace inkray {
namespace {

float min_component(const Color& c) { return std::min({c.r, c.g, c.b}); }

std::vector<SurfacePoint> roots(size_t count) {
  return place_roots(testing::surface_of(testing::test_sphere()), count, 4);
}

TEST(StrokeColor, NoJitterKeepsTheMaterialColour) {
  const std::vector<Material> materials = {DiffuseMaterial{ConstantTexture{Color(0.7f, 0.2f, 0.1f)}}};
  StrokeEmitterDesc e = testing::test_emitter(100);
  e.hue_jitter = e.saturation_jitter = e.value_jitter = 0.f;
  for (const Color& c : stroke_colors(materials, 0, roots(100), e)) {
    EXPECT_NEAR(c.r, 0.7f, 1e-4f);
    EXPECT_NEAR(c.g, 0.2f, 1e-4f);
    EXPECT_NEAR(c.b, 0.1f, 1e-4f);
  }
}

TEST(StrokeColor, FullJitterStaysInRangeAndVaries) {
  const std::vector<Material> materials = {DiffuseMaterial{ConstantTexture{Color(0.9f, 0.5f, 0.05f)}}};
  StrokeEmitterDesc e = testing::test_emitter(2000);
  e.hue_jitter = 180.f;
  e.saturation_jitter = 1.f;
  e.value_jitter = 1.f;
  const auto pts = roots(2000);
  const std::vector<Color> colors = stroke_colors(materials, 0, pts, e);
  Color lo(1.f), hi(0.f);
  for (const Color& c : colors) {
    ASSERT_TRUE(is_finite(c));
    ASSERT_GE(min_component(c), 0.f);
    ASSERT_LE(max_component(c), 1.f + 1e-5f);
    lo = glm::min(lo, c);
    hi = glm::max(hi, c);
  }
  EXPECT_GT(min_component(hi - lo), 0.5f);
  EXPECT_EQ(colors, stroke_colors(materials, 0, pts, e));
}

TEST(StrokeColor, MixPaintsEachStrokeInOneOfItsColours) {
  const std::vector<Material> materials = {DiffuseMaterial{ConstantTexture{Color(1.f, 0.f, 0.f)}},
                                           DiffuseMaterial{ConstantTexture{Color(0.f, 0.f, 1.f)}},
                                           MixMaterial{0, 1, ConstantTexture{Color(0.5f)}}};
  StrokeEmitterDesc e = testing::test_emitter(1000);
  e.hue_jitter = e.saturation_jitter = e.value_jitter = 0.f;
  int red = 0;
  for (const Color& c : stroke_colors(materials, 2, roots(1000), e)) {
    ASSERT_TRUE(c == Color(1.f, 0.f, 0.f) || c == Color(0.f, 0.f, 1.f));
    red += c.r > 0.5f ? 1 : 0;
  }
  EXPECT_NEAR(red, 500, 60);
}

}  // namespace
}  // namespace inkray
