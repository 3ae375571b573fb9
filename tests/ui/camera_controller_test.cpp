// Viewport navigation maths: orbit, pan, dolly, framing, focus.
#include "ui/viewport/camera_controller.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inkray {
namespace {

CameraDesc test_camera() {
  return {{.look_from = Point3(0.f, 0.f, 5.f), .look_at = Point3(0.f), .vfov = 40.f}};
}

TEST(CameraController, OrbitKeepsTargetAndDistance) {
  const CameraDesc c = orbit(test_camera(), 0.7f, 0.3f);
  EXPECT_EQ(c.look_at, Point3(0.f));
  EXPECT_NEAR(glm::length(c.look_from - c.look_at), 5.f, 1e-4f);
  EXPECT_NEAR(std::asin(c.look_from.y / 5.f), 0.3f, 1e-4f);
}

TEST(CameraController, QuarterTurnYaw) {
  const CameraDesc c = orbit(test_camera(), float(M_PI / 2), 0.f);
  EXPECT_NEAR(std::abs(c.look_from.x), 5.f, 1e-4f);
  EXPECT_NEAR(c.look_from.z, 0.f, 1e-4f);
}

TEST(CameraController, PitchStopsBeforeThePole) {
  const CameraDesc c = orbit(test_camera(), 0.f, 10.f);
  const Vec3 dir = glm::normalize(c.look_from - c.look_at);
  EXPECT_LT(dir.y, 0.9999f);
  EXPECT_GT(dir.y, 0.99f);
}

TEST(CameraController, PanMovesEyeAndTargetAcrossTheView) {
  const CameraDesc before = test_camera();
  const float height = 500.f;
  const CameraDesc c = pan(before, 100.f, 0.f, height);
  const Vec3 shift = c.look_at - before.look_at;
  EXPECT_NEAR(glm::length((c.look_from - before.look_from) - shift), 0.f, 1e-5f);
  EXPECT_NEAR(shift.z, 0.f, 1e-5f);  // across, not along, the view
  // 100 of 500 pixels at distance 5 spans 100/500 of the view height there.
  const float expected = 2.f * 5.f * std::tan(glm::radians(20.f)) * 100.f / height;
  EXPECT_NEAR(std::abs(shift.x), expected, 1e-4f);
  EXPECT_LT(shift.x, 0.f);  // dragging right moves the camera left
}

TEST(CameraController, DollyScalesDistance) {
  const CameraDesc c = dolly(test_camera(), 0.5f);
  EXPECT_NEAR(glm::length(c.look_from - c.look_at), 2.5f, 1e-5f);
  const CameraDesc far = CameraController{}.wheel(test_camera(), -1.f);
  EXPECT_GT(glm::length(far.look_from - far.look_at), 5.f);
  EXPECT_GT(glm::length(dolly(test_camera(), 0.f).look_from), 0.f);  // a bad factor changes nothing
}

TEST(CameraController, FrameFitsTheSphere) {
  const CameraDesc c = frame_sphere(test_camera(), Point3(1.f, 2.f, 3.f), 2.f);
  EXPECT_EQ(c.look_at, Point3(1.f, 2.f, 3.f));
  const float distance = glm::length(c.look_from - c.look_at);
  // The sphere's silhouette stays inside the vertical field of view.
  EXPECT_GT(distance * std::sin(glm::radians(20.f)), 2.f);
  EXPECT_LT(distance * std::sin(glm::radians(20.f)), 2.5f);
  EXPECT_NEAR(glm::normalize(c.look_from - c.look_at).z, 1.f, 1e-5f);  // same direction as before
}

TEST(CameraController, FocusAt) {
  EXPECT_FLOAT_EQ(focus_at(test_camera(), 3.5f).focus_distance, 3.5f);
  EXPECT_FLOAT_EQ(focus_at(test_camera(), -1.f).focus_distance, 0.f);
}

}  // namespace
}  // namespace inkray
