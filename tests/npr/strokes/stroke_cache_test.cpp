// Strokes are kept between compiles: an edit that does not touch the emitter
// or its object reuses the ribbons and only repaints them, and the result is
// the same as building them afresh.
#include "core/compiler/compile.h"

#include "stroke_fixtures.h"
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

SceneDesc painted_ball(Color paint, int seed) {
  SceneDesc d = testing::sized_scene(32, 32);
  d.materials.push_back({"m", DiffuseDesc{paint}, {}});
  d.objects.push_back({"thing", SphereDesc{{0.f, 0.f, 0.f}, 1.f}, {}, "m", true, {}});
  StrokeEmitterDesc e = testing::test_emitter(400, seed);
  e.hue_jitter = 0.f;
  e.saturation_jitter = 0.f;
  e.value_jitter = 0.f;
  d.strokes.push_back(e);
  return d;
}

// The stroke ribbons of a compiled scene (the emitter's object comes last).
TriangleMesh strokes_of(const SceneDesc& d) {
  const CompileResult c = compile_scene(d);
  EXPECT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
  const auto& shape = c.scene->world->geometry.shape(c.scene->world->geometry.shape_count() - 1);
  EXPECT_TRUE(std::holds_alternative<TriangleMesh>(shape));
  return std::get<TriangleMesh>(shape);
}

TEST(StrokeCache, CachedStrokesEqualFreshOnes) {
  const TriangleMesh fresh = strokes_of(painted_ball(Color(0.8f, 0.2f, 0.1f), 1));
  const TriangleMesh cached = strokes_of(painted_ball(Color(0.8f, 0.2f, 0.1f), 1));
  strokes_of(painted_ball(Color(0.8f, 0.2f, 0.1f), 2));  // pushes seed 1 out of the cache
  const TriangleMesh rebuilt = strokes_of(painted_ball(Color(0.8f, 0.2f, 0.1f), 1));
  EXPECT_EQ(fresh.positions, cached.positions);
  EXPECT_EQ(fresh.colors, cached.colors);
  EXPECT_EQ(fresh.positions, rebuilt.positions);
  EXPECT_EQ(fresh.indices, rebuilt.indices);
}

TEST(StrokeCache, MaterialEditRepaintsWithoutRegrowing) {
  const TriangleMesh red = strokes_of(painted_ball(Color(0.8f, 0.2f, 0.1f), 1));
  const TriangleMesh blue = strokes_of(painted_ball(Color(0.1f, 0.2f, 0.8f), 1));
  EXPECT_EQ(red.positions, blue.positions);
  ASSERT_FALSE(blue.colors.empty());
  // The HSV round trip of the (zero) jitter may move a colour by an ulp.
  for (const Color& c : blue.colors) EXPECT_LT(max_component(glm::abs(c - Color(0.1f, 0.2f, 0.8f))), 1e-6f);
}

TEST(StrokeCache, EmitterEditRegrows) {
  const TriangleMesh one = strokes_of(painted_ball(Color(0.5f), 1));
  const TriangleMesh two = strokes_of(painted_ball(Color(0.5f), 2));
  EXPECT_NE(one.positions, two.positions);
}

}  // namespace
}  // namespace inkray
