// The view's compiled settings carry each document setting they stand for.
#include "core/compiler/compile_view.h"

#include <gtest/gtest.h>

#include <array>

namespace inkray {
namespace {

TEST(CompileView, EachLineTypeKeepsItsOwnColourAndOpacity) {
  OutlineDesc outlines;
  // In LineType's order, written out so that the order itself is checked.
  const std::array<LineStyleDesc*, kLineTypeCount> styles = {&outlines.depth,        &outlines.crease,
                                                             &outlines.intersection, &outlines.material,
                                                             &outlines.object,       &outlines.silhouette};
  for (int t = 0; t < kLineTypeCount; ++t) {
    styles[size_t(t)]->color = Color(0.1f * float(t + 1), 0.f, 1.f);
    styles[size_t(t)]->opacity = 0.05f * float(t + 1);
  }
  const ResolveSettings r = compile_resolve_settings(RenderSettings{}, outlines);
  for (int t = 0; t < kLineTypeCount; ++t) {
    EXPECT_EQ(r.lines[size_t(t)].color, Color(0.1f * float(t + 1), 0.f, 1.f)) << kLineTypeNames[size_t(t)];
    EXPECT_EQ(r.lines[size_t(t)].opacity, 0.05f * float(t + 1)) << kLineTypeNames[size_t(t)];
  }
}

TEST(CompileView, SampleAndFilterSettingsAreTheDocuments) {
  RenderSettings render;
  render.width = 321;
  render.height = 123;
  render.max_depth = 7;
  render.seed = 99;
  render.clamp = 4.5f;
  render.filter = PixelFilter::gaussian;
  render.filter_radius = 1.5f;
  render.shutter_open = -0.25f;
  render.shutter_close = 0.25f;
  render.painterly = PainterlyFilter::kuwahara;
  render.painterly_radius = 6.f;
  render.painterly_sharpness = 3.f;
  const SampleSettings s = compile_sample_settings(render);
  EXPECT_EQ(s.width, 321);
  EXPECT_EQ(s.height, 123);
  EXPECT_EQ(s.max_depth, 7);
  EXPECT_EQ(s.seed, 99u);
  EXPECT_EQ(s.clamp, 4.5f);
  EXPECT_EQ(s.filter, PixelFilter::gaussian);
  EXPECT_EQ(s.filter_radius, 1.5f);
  EXPECT_TRUE(s.motion_blur);
  const ResolveSettings r = compile_resolve_settings(render, OutlineDesc{});
  EXPECT_EQ(r.painterly, PainterlyFilter::kuwahara);
  EXPECT_EQ(r.painterly_radius, 6.f);
  EXPECT_EQ(r.painterly_sharpness, 3.f);
}

}  // namespace
}  // namespace inkray
