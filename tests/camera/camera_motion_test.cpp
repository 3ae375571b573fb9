// A camera that moves while the shutter is open: its rays at the opening and
// closing are those of the cameras there, in between its parameters are
// interpolated, and every ray carries its instant.
#include "core/camera/camera.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

CameraParams at(Point3 from, Point3 target, float vfov) {
  return {.look_from = from, .look_at = target, .vfov = vfov};
}

void expect_same_ray(const Ray& a, const Ray& b, float tolerance) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(a.o[i], b.o[i], tolerance);
    EXPECT_NEAR(a.d[i], b.d[i], tolerance);
  }
}

TEST(CameraMotion, EndsAreTheCamerasAtTheShuttersOpeningAndClosing) {
  const CameraParams open = at({-1.f, 0.f, 5.f}, {-1.f, 0.f, 0.f}, 30.f);
  const CameraParams close = at({1.f, 1.f, 4.f}, {0.5f, 0.f, 0.f}, 40.f);
  const CameraParams frame = at({0.f, 0.5f, 4.5f}, {0.f, 0.f, 0.f}, 35.f);
  const Camera moving(frame, open, close, 64, 48);
  EXPECT_TRUE(moving.moves());
  for (const Vec2 film : {Vec2(0.f), Vec2(32.f, 24.f), Vec2(60.f, 5.f)}) {
    expect_same_ray(moving.generate_ray(film, Vec2(0.5f), 0.f),
                    Camera(open, 64, 48).generate_ray(film, Vec2(0.5f)), 1e-6f);
    expect_same_ray(moving.generate_ray(film, Vec2(0.5f), 1.f),
                    Camera(close, 64, 48).generate_ray(film, Vec2(0.5f)), 1e-5f);
  }
  // Halfway: the interpolated parameters; the time rides on the ray.
  const Ray mid = moving.generate_ray(Vec2(32.f, 24.f), Vec2(0.5f), 0.5f);
  EXPECT_EQ(mid.time, 0.5f);
  expect_same_ray(mid,
                  Camera(at({0.f, 0.5f, 4.5f}, {-0.25f, 0.f, 0.f}, 35.f), 64, 48)
                      .generate_ray(Vec2(32.f, 24.f), Vec2(0.5f)),
                  1e-6f);
  // Everything but its rays is the frame's camera.
  EXPECT_EQ(moving.origin(), frame.look_from);
  EXPECT_NEAR(moving.world_to_pixels(1.f, 1.f), Camera(frame, 64, 48).world_to_pixels(1.f, 1.f), 1e-4f);
}

TEST(CameraMotion, AStillCameraGivesTheSameRaysAtEveryInstant) {
  const CameraParams d = at({1.f, 2.f, 3.f}, {0.f, 0.f, 0.f}, 45.f);
  const Camera still(d, d, d, 32, 32);
  EXPECT_FALSE(still.moves());
  const Camera plain(d, 32, 32);
  for (const float t : {0.f, 0.3f, 0.99f}) {
    const Ray a = still.generate_ray(Vec2(7.f, 9.f), Vec2(0.2f, 0.7f), t);
    const Ray b = plain.generate_ray(Vec2(7.f, 9.f), Vec2(0.2f, 0.7f));
    EXPECT_EQ(a.o, b.o);
    EXPECT_EQ(a.d, b.d);
    EXPECT_EQ(a.time, t);
  }
}

// A focus distance of 0 focuses on look_at at each end, and in between on the
// interpolated distance: thin-lens rays of one film point meet there.
TEST(CameraMotion, FocusFollowsTheTarget) {
  CameraParams open = at({0.f, 0.f, 4.f}, {0.f, 0.f, 0.f}, 30.f),
               close = at({0.f, 0.f, 8.f}, {0.f, 0.f, 0.f}, 30.f);
  open.aperture = close.aperture = 0.5f;
  const Camera moving(open, open, close, 32, 32);
  const Ray a = moving.generate_ray(Vec2(16.f), Vec2(0.1f, 0.5f), 0.5f);
  const Ray b = moving.generate_ray(Vec2(16.f), Vec2(0.9f, 0.5f), 0.5f);
  // Both meet the axis at distance 6 from the eye at z = 6: at the origin.
  const float ta = -a.o.z / a.d.z, tb = -b.o.z / b.d.z;
  EXPECT_NEAR(a.o.x + ta * a.d.x, 0.f, 1e-4f);
  EXPECT_NEAR(b.o.x + tb * b.d.x, 0.f, 1e-4f);
}

}  // namespace
}  // namespace inkray
