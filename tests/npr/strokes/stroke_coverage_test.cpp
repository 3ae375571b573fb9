// Coverage: strokes sized to cover a surface once over cover the same share of
// it whether they are 150 big ones or 2000 small ones of the same total area,
// measured as the share of camera rays on the object that first hit a stroke.
#include "core/compiler/compile.h"
#include "npr/strokes/stroke_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inkray {
namespace {

// A unit ball seen from 4 away, and one emitter of `count` strokes of one size
// whose areas add up to the ball's (4 pi).
SceneDesc ball(int count, float width, float length) {
  SceneDesc d;
  d.render.width = d.render.height = 160;
  d.camera.look_from = {0.f, 0.f, 4.f};
  d.camera.look_at = {0.f, 0.f, 0.f};
  d.camera.vfov = 32.f;
  d.materials.push_back({"m", DiffuseDesc{Color(0.6f)}, {}});
  d.objects.push_back({"thing", SphereDesc{{0.f, 0.f, 0.f}, 1.f}, {}, "m", true, {}});
  StrokeEmitterDesc e = testing::test_emitter(count, 17);
  e.width_min = e.width_max = width;
  e.length_min = e.length_max = length;
  d.strokes.push_back(e);
  return d;
}

// The share of rays on the ball (or its strokes) whose first hit is a stroke.
double covered(const SceneDesc& d) {
  const CompileResult c = compile_scene(d);
  EXPECT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
  if (!c.scene) return 0.0;
  const RenderScene& scene = *c.scene;
  int on_object = 0, on_stroke = 0;
  for (int y = 0; y < 160; ++y)
    for (int x = 0; x < 160; ++x) {
      Hit hit;
      const Ray ray = scene.camera.generate_ray(Vec2(float(x) + 0.5f, float(y) + 0.5f), Vec2(0.5f));
      if (!scene.world->geometry.intersect(ray, kInfinity, &hit)) continue;
      const bool stroke = scene.world->objects[hit.geometry].name == "paint";
      on_object += 1;
      on_stroke += stroke ? 1 : 0;
    }
  EXPECT_GT(on_object, 5000);
  return double(on_stroke) / double(on_object);
}

TEST(StrokeCoverage, BigAndSmallStrokesOfTheSameTotalAreaCoverAlike) {
  const float area = 4.f * kPi;
  // 150 strokes with scenes/strokes_150.json's proportions (length 3.7 widths).
  const float big_width = std::sqrt(area / (150.f * 3.7f));
  const float small_width = big_width * std::sqrt(150.f / 2000.f);
  const double big = covered(ball(150, big_width, 3.7f * big_width));
  const double small = covered(ball(2000, small_width, 3.7f * small_width));
  // Once over, with the bristle brush's gaps: well short of full cover.
  EXPECT_GT(small, 0.25);
  EXPECT_LT(small, 0.95);
  // The stated tolerance: within 10% of each other.
  EXPECT_NEAR(big / small, 1.0, 0.1) << "big " << big << " small " << small;
}

}  // namespace
}  // namespace inkray
