// Brushes: procedural alphas stay in [0, 1] and fade at the stroke's ends; the
// image brushes in resources/brushes/ load with transparent and opaque parts.
#include "core/npr/strokes/brush.h"
#include "npr/strokes/stroke_fixtures.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace inkray {
namespace {

const std::filesystem::path kBrushes = std::filesystem::path(INKRAY_SOURCE_DIR) / "resources" / "brushes";

double mean_coverage(const AlphaMask& m, int variant) {
  double sum = 0.0;
  for (int v = 0; v < m.height; ++v)
    for (int u = 0; u < m.width; ++u) sum += m.at(variant, u, v) / 255.0;
  return sum / double(m.width * m.height);
}

TEST(StrokeBrush, ProceduralAlphaInRangeAndFadesAtTheEnds) {
  for (float pressure : {0.f, 0.5f, 1.f}) {
    for (uint32_t variant = 0; variant < 4; ++variant) {
      double middle = 0.0;
      for (int i = 0; i <= 64; ++i) {
        const float u = float(i) / 64.f;
        for (int j = 0; j <= 64; ++j) {
          const float v = float(j) / 64.f;
          const float b = bristle_alpha(u, v, 12.f, pressure, variant), f = flat_alpha(u, v, pressure);
          ASSERT_TRUE(b >= 0.f && b <= 1.f) << u << " " << v;
          ASSERT_TRUE(f >= 0.f && f <= 1.f) << u << " " << v;
        }
        middle += bristle_alpha(u, 0.3f, 12.f, pressure, variant) / 65.0;
      }
      // Nothing at the sides or where the brush lands; paint in the middle.
      EXPECT_LT(bristle_alpha(0.f, 0.5f, 12.f, pressure, variant), 0.05f);
      EXPECT_LT(bristle_alpha(1.f, 0.5f, 12.f, pressure, variant), 0.05f);
      EXPECT_LT(bristle_alpha(0.5f, 0.f, 12.f, pressure, variant), 0.05f);
      EXPECT_LT(flat_alpha(0.5f, 1.f, pressure), 0.05f);
      EXPECT_GT(middle, 0.25);
    }
  }
}

TEST(StrokeBrush, ImageBrushesLoadWithTransparentAndOpaqueParts) {
  for (const char* name : {"dab.png", "dry_bristle.png", "palette_knife.png"}) {
    SCOPED_TRACE(name);
    StrokeEmitterDesc e = testing::test_emitter(1);
    e.brush = BrushKind::image;
    e.brush_image = std::string("brushes/") + name;
    std::string error;
    const auto mask = make_brush_mask(e, kBrushes.parent_path(), &error);
    ASSERT_TRUE(mask) << error;
    EXPECT_EQ(mask->variants, 2);
    // The stroke runs along the image's x: the mask is taller than wide.
    EXPECT_GT(mask->height, mask->width);
    const double mean = mean_coverage(*mask, 0);
    EXPECT_GT(mean, 0.15);
    EXPECT_LT(mean, 0.9);
    EXPECT_DOUBLE_EQ(mean, mean_coverage(*mask, 1));  // the mirrored variant
    // Transparent beyond the sides, painted along the middle.
    EXPECT_EQ(mask->coverage({0.f, 0.5f}, 0), 0.f);
    EXPECT_GT(mask->coverage({0.5f, 0.3f}, 0), 0.3f);
  }
}

TEST(StrokeBrush, MissingImageIsAnError) {
  StrokeEmitterDesc e = testing::test_emitter(1);
  e.brush = BrushKind::image;
  e.brush_image = "no_such_brush.png";
  std::string error;
  EXPECT_FALSE(make_brush_mask(e, kBrushes, &error));
  EXPECT_NE(error.find("no_such_brush.png"), std::string::npos) << error;
}

}  // namespace
}  // namespace inkray
