// The gizmo's maths: picking handles from points on screen, and what axis, plane, ring
// and scale drags do to a transform, with a known camera.
#include "ui/viewport/gizmo.h"
#include "core/compiler/compile_objects.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

// 200 x 100 image pixels shown at 2 window pixels each, from 30, 20 in the window.
ViewMapping view_from(const Point3& eye) {
  CameraDesc c;
  c.look_from = eye;
  c.look_at = Point3(0.f);
  c.vfov = 40.f;
  return {Camera(c, 200, 100), Vec2(30.f, 20.f), 2.f};
}

ObjectDesc ball(const Point3& centre = Point3(0.f)) {
  ObjectDesc o;
  o.name = "ball";
  o.shape = SphereDesc{centre, 1.f};
  return o;
}

Vec2 on_screen(const ViewMapping& view, const Point3& p) {
  Vec2 w;
  EXPECT_TRUE(view.project(p, &w));
  return w;
}

void expect_near(const Vec3& a, const Vec3& b, float tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

const Point3 kEye(4.f, 3.f, 10.f);  // every axis and plane seen at an angle

TEST(Gizmo, FrameHasAConstantSizeOnScreen) {
  const ViewMapping view = view_from(kEye);
  const GizmoFrame f = gizmo_frame(ball(), GizmoMode::translate, view);
  ASSERT_TRUE(f.visible);
  const Vec2 a = on_screen(view, f.pivot);
  // A length across the view, at the pivot's depth, spans kGizmoPixels.
  const Vec3 right = glm::normalize(glm::cross(-Vec3(kEye), Vec3(0.f, 1.f, 0.f)));
  EXPECT_NEAR(glm::length(on_screen(view, f.pivot + f.length * right) - a), kGizmoPixels, 0.5f);
  EXPECT_FALSE(gizmo_frame(ball(Point3(0.f, 0.f, 20.f)), GizmoMode::translate, view).visible);  // behind
}

TEST(Gizmo, PicksTheHandleUnderAPoint) {
  const ViewMapping view = view_from(kEye);
  const GizmoFrame f = gizmo_frame(ball(), GizmoMode::translate, view);
  for (int a = 0; a < 3; ++a) {
    const Vec2 p = on_screen(view, f.pivot + 0.7f * f.length * f.axes[size_t(a)]);
    EXPECT_EQ(pick_handle(f, GizmoMode::translate, view, p), (GizmoHandle{HandleKind::axis, a})) << a;
    // A few pixels beside the stick still picks it; far off picks nothing.
    EXPECT_EQ(pick_handle(f, GizmoMode::translate, view, p + Vec2(0.f, 4.f)).axis, a);
  }
  const auto xy = plane_corners(f, 2);
  const Vec2 square = on_screen(view, 0.25f * (xy[0] + xy[1] + xy[2] + xy[3]));
  EXPECT_EQ(pick_handle(f, GizmoMode::translate, view, square), (GizmoHandle{HandleKind::plane, 2}));
  EXPECT_EQ(pick_handle(f, GizmoMode::translate, view, on_screen(view, f.pivot)).kind, HandleKind::view);
  EXPECT_EQ(pick_handle(f, GizmoMode::translate, view, Vec2(5.f, 5.f)).kind, HandleKind::none);

  const GizmoFrame r = gizmo_frame(ball(), GizmoMode::rotate, view);
  const Vec2 on_y_ring =
      on_screen(view, r.pivot + r.length * Vec3(1.f, 0.f, 0.f));  // the ring about Y passes +X
  const GizmoHandle ring = pick_handle(r, GizmoMode::rotate, view, on_y_ring);
  EXPECT_EQ(ring.kind, HandleKind::ring);
  EXPECT_TRUE(ring.axis == 1 || ring.axis == 2);  // +X lies on both rings; either is right
  const Vec2 only_y = on_screen(view, r.pivot + r.length * glm::normalize(Vec3(1.f, 0.f, 1.f)));
  EXPECT_EQ(pick_handle(r, GizmoMode::rotate, view, only_y), (GizmoHandle{HandleKind::ring, 1}));
}

TEST(Gizmo, AxisSeenEndOnIsHidden) {
  const ViewMapping view = view_from(Point3(0.f, 0.f, 10.f));  // looking down -Z
  const GizmoFrame f = gizmo_frame(ball(), GizmoMode::translate, view);
  EXPECT_FALSE(handle_shown(f, {HandleKind::axis, 2}, view));
  EXPECT_TRUE(handle_shown(f, {HandleKind::axis, 0}, view));
  EXPECT_FALSE(handle_shown(f, {HandleKind::plane, 0}, view));  // the YZ square, edge-on
}

TEST(Gizmo, AxisDragFollowsTheNearestPointOfTheAxis) {
  const ViewMapping view = view_from(kEye);
  const ObjectDesc o = ball();
  const GizmoFrame f = gizmo_frame(o, GizmoMode::translate, view);
  const Point3 grab = f.pivot + 0.7f * f.length * Vec3(1.f, 0.f, 0.f);
  GizmoDrag drag(o, GizmoMode::translate, {HandleKind::axis, 0}, view, on_screen(view, grab));
  expect_near(drag.drag_to(on_screen(view, grab + Vec3(1.5f, 0.f, 0.f)), false).translate,
              Vec3(1.5f, 0.f, 0.f), 1e-3f);
  // Off the axis on screen: only the X component moves.
  const TransformDesc off = drag.drag_to(on_screen(view, grab + Vec3(-0.5f, 2.f, 0.f)), false);
  EXPECT_NEAR(off.translate.y, 0.f, 1e-6f);
  EXPECT_NEAR(off.translate.z, 0.f, 1e-6f);
  EXPECT_NEAR(drag.value().delta.x, off.translate.x, 1e-6f);
}

TEST(Gizmo, PlaneDragFollowsTheRayOnThePlane) {
  const ViewMapping view = view_from(kEye);
  const ObjectDesc o = ball();
  const GizmoFrame f = gizmo_frame(o, GizmoMode::translate, view);
  const auto xz = plane_corners(f, 1);
  const Point3 grab = 0.25f * (xz[0] + xz[1] + xz[2] + xz[3]);
  GizmoDrag drag(o, GizmoMode::translate, {HandleKind::plane, 1}, view, on_screen(view, grab));
  expect_near(drag.drag_to(on_screen(view, grab + Vec3(1.f, 0.f, -2.f)), false).translate,
              Vec3(1.f, 0.f, -2.f), 1e-3f);
}

TEST(Gizmo, RingDragTurnsAboutThePivot) {
  const ViewMapping view = view_from(kEye);
  const ObjectDesc o = ball(Point3(0.f, 1.f, 0.f));  // the pivot is off the origin
  const GizmoFrame f = gizmo_frame(o, GizmoMode::rotate, view);
  expect_near(f.pivot, Point3(0.f, 1.f, 0.f), 1e-6f);
  GizmoDrag drag(o, GizmoMode::rotate, {HandleKind::ring, 2}, view,
                 on_screen(view, f.pivot + f.length * Vec3(1.f, 0.f, 0.f)));
  const TransformDesc t = drag.drag_to(on_screen(view, f.pivot + f.length * Vec3(0.f, 1.f, 0.f)), false);
  ASSERT_EQ(t.rotate.size(), 1u);
  expect_near(t.rotate[0].axis, Vec3(0.f, 0.f, 1.f), 1e-6f);
  EXPECT_NEAR(t.rotate[0].degrees, 90.f, 0.05f);
  // The pivot stays put: +X of the ball turns to +Y.
  expect_near(transform_from_desc(t).point(Point3(0.f, 1.f, 0.f)), f.pivot, 1e-4f);
  expect_near(transform_from_desc(t).point(Point3(1.f, 1.f, 0.f)), Point3(0.f, 2.f, 0.f), 1e-4f);
}

TEST(Gizmo, RingDragCountsWholeTurns) {
  const ViewMapping view = view_from(kEye);
  const ObjectDesc o = ball();
  const GizmoFrame f = gizmo_frame(o, GizmoMode::rotate, view);
  const auto at = [&](float degrees) {
    const float r = glm::radians(degrees);
    return on_screen(view, f.pivot + f.length * Vec3(std::cos(r), std::sin(r), 0.f));
  };
  GizmoDrag drag(o, GizmoMode::rotate, {HandleKind::ring, 2}, view, at(0.f));
  for (float d = 30.f; d <= 390.f; d += 30.f) drag.drag_to(at(d), false);
  EXPECT_NEAR(drag.value().degrees, 390.f, 0.1f);
}

TEST(Gizmo, RingSeenEdgeOnTurnsByTheAngleOnScreen) {
  const ViewMapping view = view_from(Point3(0.f, 0.5f, 10.f));  // the ring about Y is nearly a line
  const ObjectDesc o = ball();
  const GizmoFrame f = gizmo_frame(o, GizmoMode::rotate, view);
  EXPECT_TRUE(handle_shown(f, {HandleKind::ring, 1}, view));
  const Vec2 centre = on_screen(view, f.pivot);
  GizmoDrag drag(o, GizmoMode::rotate, {HandleKind::ring, 1}, view, centre + Vec2(60.f, 0.f));
  // A quarter turn anticlockwise on screen; Y leans towards the viewer, so it is positive.
  EXPECT_NEAR(drag.drag_to(centre + Vec2(0.f, -60.f), false).rotate[0].degrees, 90.f, 1e-3f);
}

TEST(Gizmo, ScaleByTheRatioOfDistances) {
  const ViewMapping view = view_from(kEye);
  const ObjectDesc o = ball(Point3(0.f, 1.f, 0.f));
  const GizmoFrame f = gizmo_frame(o, GizmoMode::scale, view);
  const Vec3 x = f.axes[0];
  GizmoDrag axis(o, GizmoMode::scale, {HandleKind::axis, 0}, view,
                 on_screen(view, f.pivot + 0.5f * f.length * x));
  const TransformDesc t = axis.drag_to(on_screen(view, f.pivot + f.length * x), false);
  expect_near(t.scale, Vec3(2.f, 1.f, 1.f), 1e-3f);
  expect_near(transform_from_desc(t).point(Point3(0.f, 1.f, 0.f)), f.pivot, 1e-4f);

  const Vec2 centre = on_screen(view, f.pivot);
  GizmoDrag uniform(o, GizmoMode::scale, {HandleKind::view, -1}, view, centre + Vec2(12.f, 0.f));
  const TransformDesc u = uniform.drag_to(centre + Vec2(0.f, -30.f), false);
  expect_near(u.scale, Vec3(2.5f), 1e-4f);
  expect_near(transform_from_desc(u).point(Point3(0.f, 1.f, 0.f)), f.pivot, 1e-4f);
}

TEST(Gizmo, ScaleAlongARotatedObjectsOwnAxis) {
  const ViewMapping view = view_from(kEye);
  ObjectDesc o = ball();
  o.transform.rotate.push_back({Vec3(0.f, 0.f, 1.f), 90.f});  // local X is world Y
  const GizmoFrame f = gizmo_frame(o, GizmoMode::scale, view);
  expect_near(f.axes[0], Vec3(0.f, 1.f, 0.f), 1e-5f);
}

TEST(Gizmo, CtrlSnaps) {
  const ViewMapping view = view_from(kEye);
  const ObjectDesc o = ball();  // radius 1.7 about its box: a 0.1 grid
  GizmoFrame f = gizmo_frame(o, GizmoMode::translate, view);
  const Point3 grab = f.pivot + 0.7f * f.length * Vec3(1.f, 0.f, 0.f);
  GizmoDrag move(o, GizmoMode::translate, {HandleKind::axis, 0}, view, on_screen(view, grab));
  EXPECT_NEAR(move.drag_to(on_screen(view, grab + Vec3(1.234f, 0.f, 0.f)), true).translate.x, 1.2f, 1e-5f);
  EXPECT_NEAR(move.drag_to(on_screen(view, grab + Vec3(1.234f, 0.f, 0.f)), false).translate.x, 1.234f, 1e-3f);

  f = gizmo_frame(o, GizmoMode::rotate, view);
  const auto at = [&](float degrees) {
    const float r = glm::radians(degrees);
    return on_screen(view, f.pivot + f.length * Vec3(std::cos(r), std::sin(r), 0.f));
  };
  GizmoDrag turn(o, GizmoMode::rotate, {HandleKind::ring, 2}, view, at(0.f));
  EXPECT_NEAR(turn.drag_to(at(50.f), true).rotate[0].degrees, 45.f, 1e-4f);

  f = gizmo_frame(o, GizmoMode::scale, view);
  GizmoDrag grow(o, GizmoMode::scale, {HandleKind::axis, 1}, view,
                 on_screen(view, f.pivot + 0.5f * f.length * f.axes[1]));
  EXPECT_NEAR(grow.drag_to(on_screen(view, f.pivot + 0.617f * f.length * f.axes[1]), true).scale.y, 1.2f,
              1e-5f);

  EXPECT_FLOAT_EQ(translate_snap_step(1.f), 0.1f);
  EXPECT_FLOAT_EQ(translate_snap_step(150.f), 10.f);
}

}  // namespace
}  // namespace inkray
