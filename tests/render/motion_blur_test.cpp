// Motion blur: with the shutter open for a time, each camera sample sees the scene
// at one instant of it. A sphere sliding across the shutter leaves the streak the
// analytic fraction of the shutter predicts, a moving camera blurs a still scene
// alike, strokes ride on their moving object, and a shutter that is closed (or over
// which nothing moves) renders exactly the image of a still.
#include "core/document/animation.h"
#include "core/npr/outlines/line_detector.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inkray {
namespace {

using testing::make_object;

// The streak scenes: a unit sphere seen from 100 units away, through an image 8
// units wide at its distance (kWidth x kHeight pixels), white on black. Across the
// shutter, frames 0.5 to 1.5 around frame 1, the sphere slides from x = -2 to x = 2
// or the camera slides from x = 2 to x = -2: the same streak either way.
constexpr int kWidth = 64, kHeight = 4;
constexpr float kDistance = 100.f, kHalfWidth = 4.f / kDistance, kHalfHeight = kHalfWidth * kHeight / kWidth;

TrackDesc linear_track(std::string target, Vec3 from, Vec3 to) {
  return {std::move(target),
          {KeyDesc{0.5, {from.x, from.y, from.z}, Interpolation::linear},
           KeyDesc{1.5, {to.x, to.y, to.z}, Interpolation::linear}}};
}

SceneDesc streak_scene(bool camera_moves) {
  SceneDesc d = testing::small_scene(kWidth, kHeight);
  d.camera.look_from = {0.f, 0.f, kDistance};
  d.camera.look_at = {0.f, 0.f, 0.f};
  d.camera.vfov = glm::degrees(2.f * std::atan(kHalfHeight));
  d.render.frame = 1.f;
  d.render.shutter_open = -0.5f;
  d.render.shutter_close = 0.5f;
  d.environment = ConstantEnvironmentDesc{Color(0.f)};
  d.materials = {{"white", UnlitDesc{}, {}}};
  d.objects = {make_object("ball", SphereDesc{Point3(0.f), 1.f}, "white")};
  if (camera_moves) {
    d.animation = {linear_track("camera/look_from", {2.f, 0.f, kDistance}, {-2.f, 0.f, kDistance}),
                   linear_track("camera/look_at", {2.f, 0.f, 0.f}, {-2.f, 0.f, 0.f})};
  } else {
    d.animation = {linear_track("objects/ball/transform/translate", {-2.f, 0.f, 0.f}, {2.f, 0.f, 0.f})};
  }
  return d;
}

// The fraction of the shutter during which the ray through film point (fx, fy)
// meets the sphere, whose centre relative to the camera moves from (-2, 0, 0) to
// (2, 0, 0): the instants where the centre lies within 1 of the ray's line, a
// quadratic in time.
double covered_fraction(double fx, double fy) {
  const glm::dvec3 o(0.0, 0.0, kDistance);
  const glm::dvec3 d = glm::normalize(
      glm::dvec3((2.0 * fx / kWidth - 1.0) * kHalfWidth, (1.0 - 2.0 * fy / kHeight) * kHalfHeight, -1.0));
  const glm::dvec3 a = glm::dvec3(-2.0, 0.0, 0.0) - o, b(4.0, 0.0, 0.0);
  const double ad = glm::dot(a, d), bd = glm::dot(b, d);
  const double qa = glm::dot(b, b) - bd * bd, qb = 2.0 * (glm::dot(a, b) - ad * bd),
               qc = glm::dot(a, a) - ad * ad - 1.0;
  const double disc = qb * qb - 4.0 * qa * qc;
  if (disc <= 0.0) return 0.0;
  const double t0 = (-qb - std::sqrt(disc)) / (2.0 * qa), t1 = (-qb + std::sqrt(disc)) / (2.0 * qa);
  return std::max(0.0, std::min(t1, 1.0) - std::max(t0, 0.0));
}

// A pixel's expected value: the covered fraction averaged over its footprint (the
// box filter of radius 0.5 spreads its samples uniformly over the pixel).
double expected_pixel(int x, int y) {
  constexpr int kSteps = 32;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i)
    for (int j = 0; j < kSteps; ++j) sum += covered_fraction(x + (i + 0.5) / kSteps, y + (j + 0.5) / kSteps);
  return sum / (kSteps * kSteps);
}

// Each sample is 0 or 1, so a pixel's mean over n samples has a standard deviation of
// at most 0.5 / sqrt(n) (the stratified samples do better): 1/64 at 1024 samples. A
// pixel may stray 4.5 of those from the analytic value, the row's mean error 1.
constexpr int kStreakSamples = 1024;
constexpr double kPixelTolerance = 0.07, kMeanTolerance = 0.016;

void expect_streak(const RgbImage& image) {
  ASSERT_EQ(image.width, kWidth);
  double error_sum = 0.0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const double expected = expected_pixel(x, y);
      const double got = image.pixels[size_t(y * kWidth + x)].r;
      EXPECT_NEAR(got, expected, kPixelTolerance) << "pixel " << x << ", " << y;
      error_sum += std::abs(got - expected);
    }
  EXPECT_LT(error_sum / (kWidth * kHeight), kMeanTolerance);
  // The streak's plateau: the middle pixels see the sphere half the shutter.
  EXPECT_NEAR(expected_pixel(kWidth / 2, 1), 0.5, 0.01);
}

// The same streak whichever moves: the sphere across the frame, or the camera past it.
class MotionBlurStreak : public ::testing::TestWithParam<bool> {};  // the parameter: the camera moves

TEST_P(MotionBlurStreak, MatchesTheAnalyticStreak) {
  const bool camera_moves = GetParam();
  const SceneDesc desc = streak_scene(camera_moves);
  const CompileResult c = compile_scene(desc);
  ASSERT_TRUE(c.scene) << c.errors.front();
  EXPECT_EQ(c.scene->world->geometry.moving(0), !camera_moves);
  EXPECT_EQ(c.scene->camera.moves(), camera_moves);
  // A ray without a time of its own (picking) sees the frame: halfway through this shutter.
  EXPECT_EQ(c.scene->camera.generate_ray(Vec2(32.f, 2.f), Vec2(0.5f)).time, 0.5f);
  expect_streak(testing::render_scene(desc, kStreakSamples));
}

INSTANTIATE_TEST_SUITE_P(MotionBlur, MotionBlurStreak, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& p) {
                           return p.param ? "MovingCamera" : "MovingSphere";
                         });

// Without the shutter open the same documents show the sphere sharp, where the
// frame has it: white across its middle.
TEST(MotionBlur, AClosedShutterShowsTheFrame) {
  for (const bool camera_moves : {false, true}) {
    SceneDesc desc = streak_scene(camera_moves);
    desc.render.shutter_open = desc.render.shutter_close = 0.f;
    const RgbImage image = testing::render_scene(desc, 16);
    EXPECT_EQ(image.pixels[size_t(kWidth + kWidth / 2)].r, 1.f);
    EXPECT_EQ(image.pixels[size_t(kWidth + kWidth / 2 + 16)].r, 0.f);
  }
}

// Something of everything: a moving sphere with strokes and outlines on a lit floor.
SceneDesc busy_scene() {
  SceneDesc d = testing::small_scene(40, 30);
  d.render.max_depth = 4;
  d.render.frame_start = 1;
  d.render.frame = 1.f;
  d.camera.look_from = {0.f, 1.5f, 6.f};
  d.camera.look_at = {0.f, 0.5f, 0.f};
  d.environment = GradientEnvironmentDesc{};
  d.outlines.enabled = true;
  d.materials = {{"red", DiffuseDesc{}, {}}, {"floor", DiffuseDesc{}, {}}};
  d.objects = {
      make_object("ball", SphereDesc{Point3(0.f), 1.f}, "red"),
      make_object("floor", QuadDesc{Point3(-5.f, -1.f, 5.f), Vec3(10.f, 0.f, 0.f), Vec3(0.f, 0.f, -10.f)},
                  "floor")};
  LightDesc light;
  light.name = "lamp";
  light.data = PointLightDesc{Point3(2.f, 4.f, 3.f), Color(1.f), 20.f};
  d.lights = {light};
  d.strokes = {StrokeEmitterDesc{
      .name = "paint", .object = "ball", .count = 150, .width_min = 0.06f, .width_max = 0.1f}};
  d.animation = {linear_track("objects/ball/transform/translate", {-1.f, 0.f, 0.f}, {1.f, 0.f, 0.f})};
  return d;
}

void expect_identical(const RgbImage& a, const RgbImage& b) {
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) differing += a.pixels[i] != b.pixels[i] ? 1 : 0;
  EXPECT_EQ(differing, 0u);
}

// A shutter whose opening equals its closing is no motion blur: the image is bit
// for bit the one without shutter keys, and the one of the still at that frame.
TEST(MotionBlur, ClosedShutterIsBitIdentical) {
  SceneDesc keyed = busy_scene();
  keyed.render.shutter_open = keyed.render.shutter_close = 0.3f;
  SceneDesc plain = busy_scene();
  SceneDesc still = scene_at_frame(busy_scene(), 1.0);
  still.animation.clear();
  const RgbImage image = testing::render_scene(plain, 4);
  expect_identical(testing::render_scene(keyed, 4), image);
  expect_identical(testing::render_scene(still, 4), image);
}

// An open shutter over which nothing moves changes nothing either: tracks that end
// before it opens, or that change only what is read at the frame (a light).
TEST(MotionBlur, OpenShutterOverStillnessIsBitIdentical) {
  SceneDesc quiet = busy_scene();
  quiet.render.shutter_open = 0.6f;  // frames 1.6 to 2: after the last key
  quiet.render.shutter_close = 1.f;
  SceneDesc lamp = busy_scene();
  lamp.animation = {
      TrackDesc{"lights/lamp/intensity",
                {KeyDesc{0.5, {10.0}, Interpolation::linear}, KeyDesc{1.5, {30.0}, Interpolation::linear}}}};
  lamp.render.shutter_open = -0.5f;
  lamp.render.shutter_close = 0.5f;
  for (const SceneDesc& desc : {quiet, lamp}) {
    const CompileResult c = compile_scene(desc);
    ASSERT_TRUE(c.scene) << c.errors.front();
    EXPECT_FALSE(moves_during_shutter(*c.scene));
    SceneDesc closed = desc;
    closed.render.shutter_open = closed.render.shutter_close = 0.f;
    expect_identical(testing::render_scene(desc, 4), testing::render_scene(closed, 4));
  }
}

// Lines of a moving object are traced at each sample's instant; adaptive line
// sampling, which assumes lines stand still in a pixel, gives way to full sampling.
TEST(MotionBlur, MovingScenesSampleTheirLinesInFull) {
  SceneDesc moving = busy_scene();
  moving.render.shutter_open = -0.5f;
  moving.render.shutter_close = 0.5f;
  const CompileResult on = compile_scene(moving);
  ASSERT_TRUE(on.scene) << on.errors.front();
  EXPECT_TRUE(moves_during_shutter(*on.scene));
  EXPECT_FALSE(on.scene->lines.adaptive);
  const CompileResult off = compile_scene(busy_scene());
  ASSERT_TRUE(off.scene) << off.errors.front();
  EXPECT_TRUE(off.scene->lines.adaptive);
}

// Strokes on a moving sphere ride on it. The sphere is unlit red, its strokes take
// its colour (no jitter) and are lit by a blue sky: in the blue channel both are
// black and the sky is 1, so blue measures how many camera samples see the sky. Strokes
// that left the surface would hide sky the bare sphere leaves visible.
SceneDesc painted_scene(bool strokes, bool shutter) {
  SceneDesc d = testing::small_scene(48, 32);
  d.render.max_depth = 3;
  d.render.frame = 1.f;
  d.render.shutter_open = shutter ? -0.5f : 0.f;
  d.render.shutter_close = shutter ? 0.5f : 0.f;
  d.camera.look_from = {0.f, 0.f, 7.f};
  d.camera.look_at = {0.f, 0.f, 0.f};
  d.environment = ConstantEnvironmentDesc{Color(0.f, 0.f, 1.f)};
  d.materials = {{"red", UnlitDesc{Color(1.f, 0.f, 0.f)}, {}}};
  d.objects = {make_object("ball", SphereDesc{Point3(0.f), 1.f}, "red")};
  d.animation = {linear_track("objects/ball/transform/translate", {-1.2f, 0.f, 0.f}, {1.2f, 0.f, 0.f})};
  if (strokes) {
    StrokeEmitterDesc e;
    e.name = "paint";
    e.object = "ball";
    e.count = 300;
    e.width_min = 0.08f;
    e.width_max = 0.12f;
    e.hue_jitter = e.saturation_jitter = e.value_jitter = 0.f;
    d.strokes = {e};
  }
  return d;
}

// Sky hidden by strokes, in camera samples per pixel summed over the image, and the
// red the strokes took from the sphere.
struct StrokeFootprint {
  double sky_hidden = 0.0, red_hidden = 0.0;
};
StrokeFootprint stroke_footprint(bool shutter) {
  const RgbImage bare = testing::render_scene(painted_scene(false, shutter), 16);
  const RgbImage painted = testing::render_scene(painted_scene(true, shutter), 16);
  StrokeFootprint f;
  for (size_t i = 0; i < bare.pixels.size(); ++i) {
    f.sky_hidden += std::max(0.f, bare.pixels[i].b - painted.pixels[i].b);
    f.red_hidden += std::max(0.f, bare.pixels[i].r - painted.pixels[i].r);
  }
  return f;
}

TEST(MotionBlur, StrokesStayWithinTheirObjectsBlurredFootprint) {
  const StrokeFootprint still = stroke_footprint(false);
  const StrokeFootprint moving = stroke_footprint(true);
  // The strokes are there and blurred with the sphere: they cover much of it...
  EXPECT_GT(still.red_hidden, 10.0);
  EXPECT_GT(moving.red_hidden, 0.5 * still.red_hidden);
  // ...and hide no more sky than the few ribbon tips past a still sphere's outline
  // do (a pixel of sky in all is 1.0 here).
  EXPECT_LT(moving.sky_hidden, std::max(2.0 * still.sky_hidden, 1.0));
}

}  // namespace
}  // namespace inkray
