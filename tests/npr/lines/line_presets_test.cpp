// The named line styles: each is what its name promises. Set INKRAY_WRITE_LINE_DEMO to
// also write /tmp/inkray_line_presets.png (and .svg, .pdf, and zoomed crops), every
// preset drawing a circle, an S-curve and a corner, to look at.
#include "core/document/line_set_desc.h"
#include "core/world/line_sets.h"

#include "core/image/image_io.h"
#include "core/npr/lines/line_strokes.h"
#include "core/npr/lines/stroke_raster.h"
#include "core/npr/lines/vector_lines.h"
#include "core/npr/strokes/brush.h"
#include "tests/npr/lines/line_fixtures.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace inkray {

// A preset as the compiler passes it on: the document's style block, no brush loaded.
static LineStyle line_preset(std::string_view name) {
  LineSetStyleDesc desc;
  ParamPresets<LineSetStyleDesc>::apply(name, desc);
  LineStyle style;
  static_cast<LineStyleParams&>(style) = desc;
  return style;
}
namespace {

using namespace test;

TEST(LinePresets, EachNameGivesItsStyle) {
  for (std::string_view name : kLinePresetNames) EXPECT_NE(line_preset(name), LineStyle{}) << name;
  EXPECT_EQ(line_preset("no such preset"), LineStyle{});
  EXPECT_GT(line_preset("ink").taper_start, 0.f);
  EXPECT_GT(line_preset("ink").taper_end, 0.f);
  EXPECT_EQ(line_preset("ink").width, 3.f);
  EXPECT_EQ(line_preset("pencil").passes, 2);
  EXPECT_EQ(line_preset("sketch").passes, 3);
  EXPECT_EQ(line_preset("brush").brush, nullptr);  // the compiler attaches it
  EXPECT_EQ(line_preset("technical").dash, 0.f);
  EXPECT_EQ(line_preset("technical").taper_start, 0.f);
  EXPECT_EQ(line_preset("technical_hidden").dash, 6.f);
  EXPECT_EQ(line_preset("technical_hidden").gap, 4.f);
}

TEST(LinePresets, DemoImage) {
  if (!std::getenv("INKRAY_WRITE_LINE_DEMO")) GTEST_SKIP() << "set INKRAY_WRITE_LINE_DEMO to write the demo";
  const int panel = 360, count = int(kLinePresetNames.size());
  RgbImage image = filled_image(panel * 3, panel * ((count + 2) / 3), Color(0.85f, 0.83f, 0.78f));
  std::vector<LineSet> sets;
  std::vector<Chain> chains;
  for (int i = 0; i < count; ++i) {
    const Vec2 origin(float(panel * (i % 3)), float(panel * (i / 3)));
    Chain circle = circle_chain(origin + Vec2(100.f, 110.f), 70.f);
    Chain s = s_curve_chain(origin + Vec2(250.f, 30.f), 45.f);
    Chain corner = straight_chain(origin + Vec2(30.f, 230.f), origin + Vec2(180.f, 330.f));
    const Chain back = straight_chain(origin + Vec2(180.f, 330.f), origin + Vec2(330.f, 220.f));
    corner.points.insert(corner.points.end(), back.points.begin() + 1, back.points.end());
    for (Chain* c : {&circle, &s, &corner}) {
      c->object = i;
      chains.push_back(*c);
    }
    LineSet set =
        line_set(std::string(kLinePresetNames[size_t(i)]), line_preset(kLinePresetNames[size_t(i)]));
    if (kLinePresetNames[size_t(i)] == "brush") {  // as the compiler will give it its brush
      std::string error;
      StrokeEmitterDesc emitter;
      emitter.pressure = 0.3f;
      emitter.bristles = 4.f;
      set.style.brush = make_brush_mask(emitter, {}, &error);
    }
    set.select.objects.assign(size_t(count), false);
    set.select.objects[size_t(i)] = true;
    sets.push_back(set);
  }
  const RgbImage background = image;
  const std::vector<LineStroke> strokes = stroke_chains(chains, sets, 1080);
  draw_strokes(strokes, DisplayEncoding{}, image);
  std::string error;
  ASSERT_TRUE(write_image("/tmp/inkray_line_presets.png", image, &error)) << error;
  ASSERT_TRUE(write_lines_svg("/tmp/inkray_line_presets.svg", image.width, image.height, strokes, sets,
                              &background, &error))
      << error;
  ASSERT_TRUE(write_lines_pdf("/tmp/inkray_line_presets.pdf", image.width, image.height, strokes, &background,
                              &error))
      << error;
  // Each panel's S-curve's middle and the corner's tip, four times as large.
  const int zoom = 4, crop = 100;
  for (int i = 0; i < count; ++i) {
    RgbImage zoomed = filled_image(crop * zoom * 2, crop * zoom, Color(0.f));
    const int ox = panel * (i % 3), oy = panel * (i / 3);
    const int from[2][2] = {{ox + 200, oy + 80}, {ox + 130, oy + 240}};
    for (int part = 0; part < 2; ++part)
      for (int y = 0; y < crop * zoom; ++y)
        for (int x = 0; x < crop * zoom; ++x)
          zoomed.at(part * crop * zoom + x, y) = image.at(from[part][0] + x / zoom, from[part][1] + y / zoom);
    const std::string file = "/tmp/inkray_line_zoom_" + std::string(kLinePresetNames[size_t(i)]) + ".png";
    ASSERT_TRUE(write_image(file, zoomed, &error)) << error;
  }
}

}  // namespace
}  // namespace inkray
