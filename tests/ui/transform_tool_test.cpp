// Blender's G/R/S as a state machine: keys, typed values, axis constraints, snapping,
// confirm and cancel, with no window.
#include "ui/viewport/transform_tool.h"
#include "core/compiler/compile_objects.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

// Looking down -Z from 10 units: the image is the XY plane, Y up.
ViewMapping front_view() {
  const CameraParams c{.look_from = Point3(0.f, 0.f, 10.f), .look_at = Point3(0.f)};
  return {Camera(c, 200, 100), Vec2(0.f), 2.f};
}

ObjectDesc ball() {
  ObjectDesc o;
  o.name = "ball";
  o.shape = SphereDesc{Point3(0.f), 1.f};
  o.transform.translate = Vec3(1.f, 0.f, 0.f);
  return o;
}

Vec2 pivot_on_screen(const ViewMapping& view) {
  Vec2 p;
  EXPECT_TRUE(view.project(Point3(1.f, 0.f, 0.f), &p));
  return p;
}

void type(TransformTool& tool, const char* text) {
  for (const char* c = text; *c; ++c) tool.type(*c);
}

TEST(TransformTool, MoveAlongXByATypedValue) {
  const ViewMapping view = front_view();
  TransformTool tool;
  tool.begin(GizmoMode::translate, ball(), view, Vec2(150.f, 90.f));
  ASSERT_TRUE(tool.active());
  tool.constrain(0);
  type(tool, "2");
  EXPECT_EQ(tool.header().rfind("Move X: 2.000", 0), 0u) << tool.header();
  tool.mouse_move(Vec2(10.f, 10.f), false);  // a typed value outweighs the mouse
  const TransformDesc t = tool.confirm();
  EXPECT_FALSE(tool.active());
  EXPECT_EQ(t.translate, Vec3(3.f, 0.f, 0.f));
}

TEST(TransformTool, MinusNegatesAndBackspaceEdits) {
  TransformTool tool;
  tool.begin(GizmoMode::translate, ball(), front_view(), Vec2(150.f, 90.f));
  type(tool, "-2.5");
  EXPECT_TRUE(tool.typing());
  EXPECT_EQ(tool.transform().translate, Vec3(-1.5f, 0.f, 0.f));  // no axis: along X
  tool.backspace();
  tool.backspace();
  EXPECT_EQ(tool.transform().translate, Vec3(-1.f, 0.f, 0.f));  // "-2"
  type(tool, "-");
  EXPECT_EQ(tool.transform().translate, Vec3(3.f, 0.f, 0.f));  // "2"
  type(tool, "x.5.1");                                         // letters and a second point are ignored
  EXPECT_NEAR(tool.transform().translate.x, 3.51f, 1e-5f);
  tool.constrain(2);
  EXPECT_NEAR(tool.transform().translate.z, 2.51f, 1e-5f);
  EXPECT_EQ(tool.transform().translate.x, 1.f);
}

TEST(TransformTool, AxisKeysToggle) {
  TransformTool tool;
  tool.begin(GizmoMode::translate, ball(), front_view(), Vec2(150.f, 90.f));
  EXPECT_EQ(tool.axis(), -1);
  tool.constrain(0);
  EXPECT_EQ(tool.axis(), 0);
  tool.constrain(0);
  EXPECT_EQ(tool.axis(), -1);
  tool.constrain(1);
  tool.constrain(2);
  EXPECT_EQ(tool.axis(), 2);
}

TEST(TransformTool, MoveFollowsTheMouseInTheViewPlane) {
  const ViewMapping view = front_view();
  TransformTool tool;
  const Vec2 start = pivot_on_screen(view);
  tool.begin(GizmoMode::translate, ball(), view, start);
  // 2 window pixels an image pixel; the view is 2 * 10 * tan(20 deg) = 7.28 units for 100 pixels.
  const float units_per_window_pixel = 2.f * 10.f * std::tan(glm::radians(20.f)) / 200.f;
  tool.mouse_move(start + Vec2(40.f, -20.f), false);
  const Vec3 t = tool.transform().translate;
  EXPECT_NEAR(t.x, 1.f + 40.f * units_per_window_pixel, 1e-3f);
  EXPECT_NEAR(t.y, 20.f * units_per_window_pixel, 1e-3f);
  EXPECT_NEAR(t.z, 0.f, 1e-4f);
  EXPECT_EQ(tool.header().rfind("Move: ", 0), 0u) << tool.header();
  // Constrained to Y, the horizontal part of the drag does nothing (the nearest point of
  // the axis to a ray seen in perspective is a little lower than the cursor).
  tool.constrain(1);
  const Vec3 c = tool.transform().translate;
  EXPECT_NEAR(c.x, 1.f, 1e-5f);
  EXPECT_NEAR(c.y, 20.f * units_per_window_pixel, 0.05f);
  // Ctrl: on the 0.1 grid.
  tool.mouse_move(start + Vec2(40.f, -20.f), true);
  EXPECT_NEAR(tool.transform().translate.y, 0.7f, 1e-5f);
}

TEST(TransformTool, CancelGivesBackTheTransformBefore) {
  TransformTool tool;
  const ObjectDesc o = ball();
  tool.begin(GizmoMode::scale, o, front_view(), Vec2(150.f, 90.f));
  type(tool, "3");
  EXPECT_EQ(tool.transform().scale, Vec3(3.f));
  EXPECT_EQ(tool.cancel(), o.transform);
  EXPECT_FALSE(tool.active());
}

TEST(TransformTool, RotateByTypedDegreesAboutAnAxis) {
  TransformTool tool;
  tool.begin(GizmoMode::rotate, ball(), front_view(), Vec2(150.f, 90.f));
  tool.constrain(2);
  type(tool, "90");
  EXPECT_EQ(tool.header().rfind("Rotate Z: 90.0", 0), 0u) << tool.header();
  const TransformDesc t = tool.confirm();
  ASSERT_EQ(t.rotate.size(), 1u);
  EXPECT_EQ(t.rotate[0].axis, Vec3(0.f, 0.f, 1.f));
  EXPECT_FLOAT_EQ(t.rotate[0].degrees, 90.f);
  EXPECT_NEAR(t.translate.x, 1.f, 1e-5f);  // about its own centre
}

TEST(TransformTool, RotateFollowsTheMouseAroundThePivot) {
  const ViewMapping view = front_view();
  TransformTool tool;
  const Vec2 pivot = pivot_on_screen(view);
  tool.begin(GizmoMode::rotate, ball(), view, pivot + Vec2(50.f, 0.f));
  tool.mouse_move(pivot + Vec2(0.f, -50.f), false);  // a quarter turn anticlockwise on screen
  const TransformDesc t = tool.transform();
  ASSERT_EQ(t.rotate.size(), 1u);
  EXPECT_NEAR(t.rotate[0].axis.z, 1.f, 0.01f);  // about the view axis, towards the viewer
  EXPECT_NEAR(t.rotate[0].degrees, 90.f, 1.f);
  tool.mouse_move(pivot + Vec2(35.f, -50.f), true);
  EXPECT_NEAR(tool.transform().rotate[0].degrees, 60.f, 1e-4f);  // 55 degrees, snapped
}

TEST(TransformTool, ScaleByDistanceUniformlyOrAlongAnAxis) {
  const ViewMapping view = front_view();
  TransformTool tool;
  const Vec2 pivot = pivot_on_screen(view);
  tool.begin(GizmoMode::scale, ball(), view, pivot + Vec2(20.f, 0.f));
  tool.mouse_move(pivot + Vec2(0.f, 40.f), false);
  EXPECT_NEAR(tool.transform().scale.x, 2.f, 1e-4f);
  EXPECT_NEAR(tool.transform().scale.z, 2.f, 1e-4f);
  tool.constrain(0);
  EXPECT_NEAR(tool.transform().scale.x, 2.f, 1e-4f);
  EXPECT_EQ(tool.transform().scale.y, 1.f);
  EXPECT_NEAR(transform_from_desc(tool.transform()).point(Point3(0.f)).x, 1.f, 1e-5f);  // the pivot stays
  tool.mouse_move(pivot + Vec2(24.7f, 0.f), true);
  EXPECT_NEAR(tool.transform().scale.x, 1.2f, 1e-5f);
  type(tool, "0");
  EXPECT_NEAR(tool.confirm().scale.x, 0.01f, 1e-6f);  // never flat
}

TEST(TransformTool, EventsWithoutABeginChangeNothing) {
  TransformTool tool;
  tool.constrain(0);
  tool.type('3');
  tool.mouse_move(Vec2(5.f, 5.f), true);
  EXPECT_FALSE(tool.active());
  EXPECT_EQ(tool.header(), "");
}

}  // namespace
}  // namespace inkray
