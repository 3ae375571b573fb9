// The selection highlight is an inner border of the object's pixels in the
// given colour, of the asked thickness, with a one-pixel rim of a second colour just
// outside, and leaves everything else alone.
#include "core/render/display_encode.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

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
        const bool rim = !inside && ((x >= 2 && x < 8 && (y == 1 || y == 8)) || (y >= 2 && y < 8 && (x == 1 || x == 8)));
        const uint8_t* px = &rgba[size_t(y * 10 + x) * 4];
        ASSERT_EQ(px[0], painted ? 10 : rim ? 1 : 0) << x << "," << y;
        ASSERT_EQ(px[1], painted ? 20 : rim ? 2 : 0) << x << "," << y;
        ASSERT_EQ(px[2], painted ? 30 : rim ? 3 : 0) << x << "," << y;
      }
  }
}

}  // namespace
}  // namespace inkray
