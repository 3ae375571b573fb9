// Long work stops when asked: a compile of a heavy stroke scene and the painterly
// filters give up once their Cancel is requested, from another thread or by a
// deadline. Each test would see a finished result if the checks were missing.
#include "core/npr/painterly_filter.h"
#include "core/compiler/compile.h"

#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace inkray {
namespace {

// 1.5 million strokes (27 million vertices, within the budget): seconds of building.
SceneDesc heavy_stroke_scene() {
  SceneDesc s = testing::one_sphere_scene(8, 8);
  // The seed: a placement no other test has cached.
  s.strokes = {StrokeEmitterDesc{.name = "paint", .object = "ball", .seed = 4242, .count = 1500000}};
  return s;
}

TEST(CompileCancel, AFlagSetByAnotherThreadStopsStrokeBuilding) {
  std::atomic<bool> flag{false};
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    flag.store(true);
  });
  CompileOptions options;
  options.cancel = Cancel(&flag);
  const CompileResult c = compile_scene(heavy_stroke_scene(), options);
  canceller.join();
  EXPECT_TRUE(c.cancelled);
  EXPECT_FALSE(c.scene);
  ASSERT_EQ(c.errors.size(), 1u);
  EXPECT_EQ(c.errors[0], "cancelled while building the scene");
}

TEST(CompileCancel, APassedDeadlineStopsBeforeAnyObject) {
  SceneDesc s = heavy_stroke_scene();
  CompileOptions options;
  options.cancel = Cancel::at(Cancel::Clock::now());
  const CompileResult c = compile_scene(s, options);
  EXPECT_TRUE(c.cancelled);
  EXPECT_FALSE(c.scene);

  // Without a request the same scene (fewer strokes) compiles.
  s.strokes[0].count = 100;
  const CompileResult ok = compile_scene(s, CompileOptions{});
  EXPECT_TRUE(ok.scene);
  EXPECT_FALSE(ok.cancelled);
}

TEST(CompileCancel, PainterlyFiltersStopFilteringRows) {
  RgbImage image{64, 48, std::vector<Color>(64 * 48, Color(0.5f))};
  std::atomic<bool> flag{true};
  const Cancel cancel(&flag);
  PainterlyFilterParams params;
  params.radius = 8.f;
  ThreadBudget pool(2);
  for (ThreadBudget* p : {static_cast<ThreadBudget*>(nullptr), &pool}) {
    for (const RgbImage& out :
         {kuwahara_filter(image, params, p, cancel), anisotropic_kuwahara_filter(image, params, p, cancel)}) {
      // Cut short, the result is empty rather than a partly filtered image.
      EXPECT_TRUE(out.pixels.empty());
    }
  }
  flag.store(false);
  const RgbImage done = kuwahara_filter(image, params, &pool, cancel);
  EXPECT_NEAR(done.at(10, 10).r, 0.5f, 1e-5f);
}

}  // namespace
}  // namespace inkray
