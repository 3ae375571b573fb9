// The viewport's encoding: the view transforms and their inverses (lines are
// composited through them, core/film/resolve.h), and the selection highlight, an
// inner border of the object's pixels in the given colour, of the asked
// thickness, with a one-pixel rim of a second colour just outside, which leaves
// everything else alone.
#include "core/render/display_encode.h"

#include "core/image/image_io.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inkray {
namespace {

// Where a transform is invertible (standard below display white, filmic below its
// white point, raw everywhere) the inverse undoes it: inverse(view(x)) == x to float
// rounding (relative 1e-5; the filmic curve flattens near its white point, where a
// rounding step of the display value is a larger step of x).
TEST(ViewTransform, InverseUndoesTheViewInItsRange) {
  for (float exposure : {-2.5f, 0.f, 1.f, 3.f}) {
    const float scale = std::exp2(exposure);
    for (ViewTransform t : {ViewTransform::standard, ViewTransform::filmic, ViewTransform::raw}) {
      SCOPED_TRACE(std::string(kViewTransformNames[size_t(t)]) + " " + std::to_string(exposure));
      const DisplayMapping mapping({exposure, t});
      const float top = t == ViewTransform::standard ? 1.f / scale
                        : t == ViewTransform::filmic ? 0.97f * filmic_white() / scale
                                                     : 50.f;
      for (int i = 0; i <= 1000; ++i) {
        const float x = top * float(i) / 1000.f;
        ASSERT_NEAR(mapping.from_display(mapping.to_display(x)), x, 1e-5f * std::max(x, 1e-3f)) << x;
      }
      // And the other way over the whole display range, which compositing relies on.
      for (int i = 0; i <= 1000; ++i) {
        const float d = float(i) / 1000.f;
        ASSERT_NEAR(mapping.to_display(mapping.from_display(d)), d, 2e-6f) << d;
      }
    }
  }
}

TEST(ViewTransform, FilmicCurveRisesToWhite) {
  EXPECT_EQ(filmic_curve(0.f), 0.f);
  EXPECT_EQ(filmic_curve_inverse(0.f), 0.f);
  EXPECT_NEAR(filmic_curve(filmic_white()), 1.f, 1e-6f);
  EXPECT_EQ(filmic_curve(2.f * filmic_white()), 1.f);
  float previous = 0.f;
  for (int i = 1; i <= 2000; ++i) {
    const float y = filmic_curve(0.01f * float(i));
    ASSERT_GE(y, previous);
    previous = y;
  }
}

// The PNG encoder and the viewport apply the same standard view.
TEST(ViewTransform, PngAndViewportAgreeOnExposure) {
  RgbImage image{64, 1, {}};
  for (int x = 0; x < 64; ++x) image.pixels.push_back(Color(float(x) / 16.f));
  for (float exposure : {-1.f, 0.f, 0.5f}) {
    const std::vector<uint8_t> png = encode_srgb8(image, exposure);
    const std::vector<uint8_t> shown = encode_display(image, {exposure, ViewTransform::standard});
    // Within one step: the viewport encodes sRGB through a table.
    for (size_t i = 0; i < 64; ++i) ASSERT_NEAR(int(png[3 * i]), int(shown[4 * i]), 1) << i;
  }
}

TEST(PaintHighlight, InnerBorderOfTheObjectInItsColour) {
  // A 6x6 object (id 3) in the middle of a 10x10 image of id 1.
  RgbImage ids{10, 10, std::vector<Color>(100, Color(1.f))};
  for (int y = 2; y < 8; ++y)
    for (int x = 2; x < 8; ++x) ids.pixels[size_t(y * 10 + x)] = Color(3.f);
  for (int thickness : {1, 2}) {
    SCOPED_TRACE(thickness);
    std::vector<uint8_t> rgba(400, 0);
    paint_highlight(rgba, ids, 3, {10, 20, 30}, thickness, {1, 2, 3});
    for (int y = 0; y < 10; ++y)
      for (int x = 0; x < 10; ++x) {
        const bool inside = x >= 2 && x < 8 && y >= 2 && y < 8;
        const int border = std::min({x - 2, 7 - x, y - 2, 7 - y});  // distance to the object's edge
        const bool painted = inside && border < thickness;
        // The rim: outside, sharing an edge (not only a corner) with the object.
        const bool rim =
            !inside && ((x >= 2 && x < 8 && (y == 1 || y == 8)) || (y >= 2 && y < 8 && (x == 1 || x == 8)));
        const uint8_t* px = &rgba[size_t(y * 10 + x) * 4];
        ASSERT_EQ(px[0], painted ? 10 : rim ? 1 : 0) << x << "," << y;
        ASSERT_EQ(px[1], painted ? 20 : rim ? 2 : 0) << x << "," << y;
        ASSERT_EQ(px[2], painted ? 30 : rim ? 3 : 0) << x << "," << y;
      }
  }
}

}  // namespace
}  // namespace inkray
