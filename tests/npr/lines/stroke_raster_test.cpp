// Strokes drawn into images: the width profile of a tapered line, dash lengths, no
// darkening where a stroke crosses itself, compositing in the display's space, thin
// lines fading rather than breaking, and brushes read across the stroke.
#include "core/npr/lines/stroke_raster.h"

#include "tests/npr/lines/line_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace inkray {
namespace {

using namespace test;

// White strokes over black in the standard view: a pixel's value is its alpha.
RgbImage alpha_of(const std::vector<LineStroke>& strokes, int width, int height) {
  RgbImage image = filled_image(width, height, Color(0.f));
  draw_strokes(strokes, DisplayEncoding{}, image);
  return image;
}

LineStyle white_style(float width) {
  LineStyle s;
  s.color = Color(1.f);
  s.width = width;
  return s;
}

float column_sum(const RgbImage& image, int x) {
  float sum = 0.f;
  for (int y = 0; y < image.height; ++y) sum += image.at(x, y).r;
  return sum;
}

TEST(StrokeRaster, TaperedLineWidthProfile) {
  LineStyle style = white_style(6.f);
  style.taper_start = style.taper_end = 0.25f;
  const Chain chain = straight_chain(Vec2(20.f, 40.3f), Vec2(180.f, 40.3f));
  const RgbImage image = alpha_of(stroke_chains({chain}, {line_set("s", style)}, 1080), 200, 80);
  // The drawn width of each column: its summed alpha.
  for (int x = 70; x < 130; ++x) EXPECT_NEAR(column_sum(image, x), 6.f, 0.05f) << x;
  EXPECT_LT(column_sum(image, 20), 0.3f);
  EXPECT_LT(column_sum(image, 179), 0.3f);
  EXPECT_LT(column_sum(image, 22), 1.f);
  EXPECT_NEAR(column_sum(image, 10), 0.f, 1e-6f);
  EXPECT_NEAR(column_sum(image, 190), 0.f, 1e-6f);
  // Rising and falling through each taper (40 px at each end).
  for (int x = 21; x < 58; x += 4) EXPECT_LT(column_sum(image, x), column_sum(image, x + 4)) << x;
  for (int x = 142; x < 178; x += 4) EXPECT_GT(column_sum(image, x), column_sum(image, x + 4)) << x;
}

TEST(StrokeRaster, DashRunsHaveTheirLength) {
  LineStyle style = white_style(2.f);
  style.dash = 10.f;
  style.gap = 5.f;
  const Chain chain = straight_chain(Vec2(20.f, 20.5f), Vec2(170.f, 20.5f));
  const RgbImage image = alpha_of(stroke_chains({chain}, {line_set("s", style)}, 1080), 200, 40);
  std::vector<std::pair<int, int>> runs;  // first and last pixel of each run along the row
  for (int x = 0; x < image.width; ++x) {
    if (image.at(x, 20).r <= 0.5f) continue;
    if (!runs.empty() && runs.back().second == x - 1)
      runs.back().second = x;
    else
      runs.push_back({x, x});
  }
  ASSERT_EQ(runs.size(), 10u);
  for (size_t i = 0; i < runs.size(); ++i) {
    EXPECT_NEAR(float(runs[i].second - runs[i].first + 1), 10.f, 1.f) << i;
    EXPECT_NEAR(float(runs[i].first), 20.f + 15.f * float(i), 1.f) << i;
  }
}

TEST(StrokeRaster, AStrokeDoesNotDarkenWhereItCrossesItself) {
  LineStyle style = white_style(4.f);
  style.opacity = 0.5f;
  // Out and back over itself, then across: every pixel covered at most half.
  Chain chain = straight_chain(Vec2(10.f, 30.f), Vec2(90.f, 30.f));
  const Chain back = straight_chain(Vec2(90.f, 30.f), Vec2(20.f, 32.f));
  const Chain across = straight_chain(Vec2(20.f, 32.f), Vec2(50.f, 5.f));
  chain.points.insert(chain.points.end(), back.points.begin() + 1, back.points.end());
  chain.points.insert(chain.points.end(), across.points.begin() + 1, across.points.end());
  const RgbImage one = alpha_of(stroke_chains({chain}, {line_set("s", style)}, 1080), 100, 60);
  float most = 0.f;
  for (const Color& c : one.pixels) most = std::max(most, c.r);
  EXPECT_NEAR(most, 0.5f, 1e-5f);
  // Two strokes over each other do composite: 0.5 OVER 0.5.
  const Chain line = straight_chain(Vec2(10.f, 30.f), Vec2(90.f, 30.f));
  const RgbImage two = alpha_of(stroke_chains({line, line}, {line_set("s", style)}, 1080), 100, 60);
  EXPECT_NEAR(two.at(50, 30).r, 0.75f, 1e-5f);
}

TEST(StrokeRaster, CompositesInTheDisplaysSpace) {
  LineStyle style = white_style(6.f);
  style.color = Color(0.5f);
  const std::vector<LineStroke> strokes =
      stroke_chains({straight_chain(Vec2(5.f, 10.5f), Vec2(35.f, 10.5f))}, {line_set("s", style)}, 1080);
  // Over light brighter than white, a solid grey line shows as that grey in each view.
  for (ViewTransform view : {ViewTransform::standard, ViewTransform::filmic, ViewTransform::raw}) {
    const DisplayEncoding display{1.f, view};
    RgbImage image = filled_image(40, 20, Color(4.f));
    draw_strokes(strokes, display, image);
    const DisplayMapping mapping(display);
    EXPECT_NEAR(mapping.to_display(image.at(20, 10)).r, 0.5f, 1e-4f) << kViewTransformNames[size_t(view)];
    EXPECT_EQ(image.at(20, 2), Color(4.f));  // untouched beyond the line
  }
  // Half covered: half way between what is shown and the line, on the display.
  style.opacity = 0.5f;
  const std::vector<LineStroke> half =
      stroke_chains({straight_chain(Vec2(5.f, 10.5f), Vec2(35.f, 10.5f))}, {line_set("s", style)}, 1080);
  const DisplayEncoding filmic{0.f, ViewTransform::filmic};
  RgbImage image = filled_image(40, 20, Color(0.3f));
  draw_strokes(half, filmic, image);
  const DisplayMapping mapping(filmic);
  EXPECT_NEAR(mapping.to_display(image.at(20, 10)).r, 0.5f * (mapping.to_display(0.3f) + 0.5f), 1e-4f);
}

TEST(StrokeRaster, ThinLinesFadeInsteadOfBreakingUp) {
  const LineStyle style = white_style(0.4f);
  const Chain chain = straight_chain(Vec2(5.f, 10.3f), Vec2(95.f, 13.7f));
  const RgbImage image = alpha_of(stroke_chains({chain}, {line_set("s", style)}, 1080), 100, 24);
  for (int x = 10; x < 90; ++x) {
    EXPECT_NEAR(column_sum(image, x), 0.4f, 0.02f) << x;  // the width, as coverage
    float most = 0.f;
    for (int y = 0; y < image.height; ++y) most = std::max(most, image.at(x, y).r);
    EXPECT_LE(most, 0.4f + 1e-5f);
  }
}

TEST(StrokeRaster, BrushIsReadAcrossAndAlongTheStroke) {
  // Opaque on the left half of u, clear on the right.
  auto half = std::make_shared<AlphaTexture>();
  half->width = 2, half->height = 1;
  half->texels = {255, 0};
  LineStyle style = white_style(8.f);
  style.brush = half;
  const Chain chain = straight_chain(Vec2(10.f, 20.f), Vec2(90.f, 20.f));  // travelling right
  const RgbImage image = alpha_of(stroke_chains({chain}, {line_set("s", style)}, 1080), 100, 40);
  // Left of travel in an image whose y points down is above the line.
  EXPECT_GT(image.at(50, 17).r, 0.9f);
  EXPECT_LT(image.at(50, 22).r, 0.1f);

  // Along: opaque for the first half of v only, over the whole stroke or per repeat.
  auto first_half = std::make_shared<AlphaTexture>();
  first_half->width = 1, first_half->height = 2;
  first_half->texels = {255, 0};
  style.brush = first_half;
  RgbImage along = alpha_of(stroke_chains({chain}, {line_set("s", style)}, 1080), 100, 40);
  EXPECT_GT(along.at(30, 20).r, 0.9f);
  EXPECT_LT(along.at(70, 20).r, 0.1f);
  style.brush_repeat = 20.f;
  along = alpha_of(stroke_chains({chain}, {line_set("s", style)}, 1080), 100, 40);
  EXPECT_GT(along.at(14, 20).r, 0.9f);
  EXPECT_LT(along.at(26, 20).r, 0.1f);
  EXPECT_GT(along.at(54, 20).r, 0.9f);
  EXPECT_LT(along.at(66, 20).r, 0.1f);
}

TEST(StrokeRaster, StrokesOffTheImageAndEmptyImagesAreSafe) {
  const LineStyle style = white_style(3.f);
  const std::vector<LineStroke> strokes =
      stroke_chains({straight_chain(Vec2(-50.f, -5.f), Vec2(150.f, 45.f))}, {line_set("s", style)}, 1080);
  RgbImage image = alpha_of(strokes, 100, 40);
  EXPECT_GT(image.at(50, 20).r, 0.9f);
  RgbImage empty;
  draw_strokes(strokes, DisplayEncoding{}, empty);
  EXPECT_TRUE(empty.pixels.empty());
}

}  // namespace
}  // namespace inkray
