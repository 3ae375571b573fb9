// Singular transforms (docs/architecture.md, "Singular transforms"): an object whose
// scale reaches zero, at a frame or within the shutter, is left out where its
// transform has no tame inverse, and rendered everywhere else. Scale keys through
// zero on every shape type and every axis, still and with motion blur: the render
// finishes (Embree aborts on the ray an infinite inverse gives), every pixel is
// finite, and a flat object draws exactly nothing.
#include "core/document/animation.h"
#include "core/geometry/instance_placement.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace inkray {
namespace {

using testing::make_object;

const std::filesystem::path kSource = INKRAY_SOURCE_DIR;

Transform scaled(Vec3 s) { return Transform::translate(Vec3(0.3f, 0.f, 0.f)) * Transform::scale(s); }

// ---------------------------------------------------------------- the pieces

TEST(SingularTransform, PlaceableRefusesFlatAndNonFiniteTransforms) {
  EXPECT_TRUE(placeable(scaled(Vec3(1.f))));
  EXPECT_TRUE(placeable(scaled(Vec3(-1.f, 1.f, 1.f))));  // a mirror is not singular
  EXPECT_TRUE(placeable(scaled(Vec3(1e-5f, 1.f, 1.f))));
  EXPECT_TRUE(placeable(scaled(Vec3(1e-20f))));  // tiny but round: the ratio counts
  EXPECT_FALSE(placeable(scaled(Vec3(1.f, 0.f, 1.f))));
  EXPECT_FALSE(placeable(scaled(Vec3(1.f, 1.f, 1e-8f))));
  EXPECT_FALSE(placeable(scaled(Vec3(0.f))));
  Transform nan = scaled(Vec3(1.f));
  nan.m[3][0] = std::nanf("");
  EXPECT_FALSE(placeable(nan));
}

TEST(SingularTransform, MotionPiecesLeaveOutTheInstantScaleCrossesZero) {
  // Still scales: one piece over the whole shutter.
  std::vector<MotionPiece> p = motion_pieces(scaled(Vec3(1.f)), scaled(Vec3(2.f)));
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].start, 0.f);
  EXPECT_EQ(p[0].end, 1.f);
  // 1 to -1 along y: zero at the middle, a piece either side with a gap of about 2e-6.
  p = motion_pieces(scaled(Vec3(1.f)), scaled(Vec3(1.f, -1.f, 1.f)));
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].start, 0.f);
  EXPECT_NEAR(p[0].end, 0.5f, 1e-5f);
  EXPECT_LT(p[0].end, 0.5f);
  EXPECT_GT(p[1].start, 0.5f);
  EXPECT_NEAR(p[1].start, 0.5f, 1e-5f);
  EXPECT_EQ(p[1].end, 1.f);
  // 1 to 0: traced until just before the close.
  p = motion_pieces(scaled(Vec3(1.f)), scaled(Vec3(1.f, 1.f, 0.f)));
  ASSERT_EQ(p.size(), 1u);
  EXPECT_LT(p[0].end, 1.f);
  EXPECT_GT(p[0].end, 0.999f);
  // Flat at both ends along the same axis: nowhere.
  EXPECT_TRUE(motion_pieces(scaled(Vec3(0.f, 1.f, 1.f)), scaled(Vec3(0.f, 2.f, 1.f))).empty());
  // Flipping two axes is a half turn: decomposed as Embree interpolates it (R by slerp,
  // S linearly), the object turns and grows and is never flat, so nothing is left out.
  p = motion_pieces(scaled(Vec3(1.f)), scaled(Vec3(-1.f, -3.f, 1.f)));
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].start, 0.f);
  EXPECT_EQ(p[0].end, 1.f);
  // Flipping all three is a half turn and one mirror: one scale still crosses zero.
  p = motion_pieces(scaled(Vec3(1.f)), scaled(Vec3(-1.f, -3.f, -2.f)));
  ASSERT_EQ(p.size(), 2u);
  EXPECT_LT(p[0].end, p[1].start);
  EXPECT_GT(p[1].start - p[0].end, 0.f);
  EXPECT_LT(p[1].start - p[0].end, 1e-5f);
  // A non-finite end gives nothing to trace.
  Transform inf = scaled(Vec3(1.f));
  inf.m[0][0] = kInfinity;
  EXPECT_TRUE(motion_pieces(scaled(Vec3(1.f)), inf).empty());
}

// ---------------------------------------------------------------- whole renders

ShapeVariant shape_of(int kind) {
  switch (kind) {
    case 0:
      return SphereDesc{Point3(0.f), 0.5f};
    case 1:
      return QuadDesc{Point3(-0.5f, -0.5f, 0.f), Vec3(1.f, 0.f, 0.f), Vec3(0.f, 1.f, 0.f)};
    case 2:
      return BoxDesc{Point3(-0.5f), Point3(0.5f)};
    default:
      return MeshDesc{"icosahedron.obj", 30.f};
  }
}

constexpr int kWidth = 48, kHeight = 32;

// One shape of each kind in a row over a ground, lit and outlined, seen from the front
// and a little above. `keys` scales the shape of kind `animated` (all, when -1) along
// `axis` over frames 1, 2, 3.
SceneDesc row_scene(int animated, int axis, std::array<float, 3> keys, bool blur) {
  SceneDesc d = testing::small_scene(kWidth, kHeight);
  d.base_dir = kSource / "scenes/meshes";
  d.camera.look_from = Point3(0.f, 1.5f, 6.f);
  d.camera.look_at = Point3(0.f, 0.5f, 0.f);
  d.render.frame_end = 3;
  if (blur) {
    d.render.shutter_open = -0.25f;
    d.render.shutter_close = 0.25f;
  }
  d.outlines.enabled = true;
  d.materials = {{"toon", ToonDesc{}, {}}, {"glass", DielectricDesc{}, {}}};
  d.lights = {{"sun", DirectionalLightDesc{}}};
  d.objects = {make_object(
      "ground", QuadDesc{Point3(-5.f, 0.f, 5.f), Vec3(10.f, 0.f, 0.f), Vec3(0.f, 0.f, -10.f)}, "toon")};
  for (int kind = 0; kind < 4; ++kind) {
    ObjectDesc o = make_object("shape" + std::to_string(kind), shape_of(kind), kind == 1 ? "glass" : "toon");
    o.transform.translate = Vec3(-2.25f + 1.5f * kind, 0.8f, 0.f);
    d.objects.push_back(o);
    if (animated != -1 && animated != kind) continue;
    TrackDesc track{"objects/" + o.name + "/transform/scale", {}};
    for (int f = 0; f < 3; ++f) {
      std::vector<double> value{1.0, 1.0, 1.0};
      value[axis] = keys[f];
      track.keys.push_back(KeyDesc{double(f + 1), value, Interpolation::linear});
    }
    d.animation.push_back(track);
  }
  EXPECT_TRUE(check_animation(d).empty());
  return d;
}

void expect_finite(const RgbImage& img, const std::string& what) {
  ASSERT_EQ(img.pixels.size(), size_t(kWidth * kHeight)) << what;
  for (const Color& p : img.pixels)
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(p[k]) && p[k] >= 0.f) << what;
}

// Through zero (1, 0, 1) and through a mirror (1, -1, 1), on each axis, still and
// blurred, at frames on and around the key where the scale is zero.
TEST(SingularTransform, ScaleThroughZeroRendersFiniteOnEveryShape) {
  for (const std::array<float, 3> keys :
       {std::array<float, 3>{1.f, 0.f, 1.f}, std::array<float, 3>{1.f, -1.f, 1.f}})
    for (int axis = 0; axis < 3; ++axis)
      for (const bool blur : {false, true}) {
        const SceneDesc base = row_scene(-1, axis, keys, blur);
        for (const float frame : {1.5f, 1.9f, 2.f, 2.1f}) {
          const std::string what = "keys " + std::to_string(keys[1]) + " axis " + std::to_string(axis) +
                                   (blur ? " blurred" : " still") + " frame " + std::to_string(frame);
          SceneDesc d = base;  // compiled as it stands at its frame, the shutter's ends from the tracks
          d.render.frame = frame;
          expect_finite(testing::render_scene(d, 2), what);
        }
      }
}

// At the frame where its scale is zero and no shutter is open, an object draws
// nothing: the render is the render of the scene without it, pixel for pixel.
TEST(SingularTransform, AFlatObjectDrawsNothing) {
  for (int kind = 0; kind < 4; ++kind) {
    SceneDesc flat = scene_at_frame(row_scene(kind, 1, {1.f, 0.f, 1.f}, false), 2.0);
    flat.animation.clear();
    SceneDesc without = flat;
    without.objects.erase(without.objects.begin() + 1 + kind);
    const RgbImage a = testing::render_scene(flat, 2), b = testing::render_scene(without, 2);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    for (size_t i = 0; i < a.pixels.size(); ++i)
      ASSERT_EQ(a.pixels[i], b.pixels[i]) << "kind " << kind << " pixel " << i;
  }
}

// Blurred across a mirror flip, the object is drawn for the rest of the shutter: the
// image differs from the scene without it, and is nowhere black where it stands.
TEST(SingularTransform, AFlipInsideTheShutterStillDrawsTheObject) {
  SceneDesc d = row_scene(2, 0, {1.f, -1.f, 1.f}, true);
  d.render.frame = 2.f;
  SceneDesc without = d;
  without.objects.erase(without.objects.begin() + 3);
  without.animation.clear();
  const RgbImage a = testing::render_scene(d, 4), b = testing::render_scene(without, 4);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  double diff = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) diff += glm::length(glm::dvec3(a.pixels[i] - b.pixels[i]));
  EXPECT_GT(diff / double(a.pixels.size()), 1e-3);
}

}  // namespace
}  // namespace inkray
