// The editor's renderer: a document submitted while a heavy one is still building
// supersedes it (the build is cancelled, not finished first) and is the one shown.
#include "core/render/progressive_renderer.h"

#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace inkray {
namespace {

TEST(ProgressiveRenderer, ANewDocumentSupersedesABuildInFlight) {
  SceneDesc heavy = testing::one_sphere_scene(32, 24);
  StrokeEmitterDesc e;
  e.name = "paint";
  e.object = "ball";
  e.count = 1500000;  // seconds of building
  e.seed = 9191;
  heavy.strokes = {e};
  SceneDesc light = testing::one_sphere_scene(32, 24);
  light.render.spp = 2;

  ProgressiveRenderer renderer(1);
  const uint64_t heavy_revision = renderer.submit(heavy);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // let the build start
  const uint64_t light_revision = renderer.submit(light);
  // Liveness, not speed: the light document must be shown however the race fell.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  std::shared_ptr<const ViewportSnapshot> shown;
  while (std::chrono::steady_clock::now() < give_up) {
    shown = renderer.latest();
    if (shown && shown->revision == light_revision) break;
    ASSERT_TRUE(!shown || shown->revision != heavy_revision) << "the superseded document was shown";
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(shown);
  EXPECT_EQ(shown->revision, light_revision);
  ASSERT_TRUE(renderer.scene());
  EXPECT_EQ(renderer.scene()->objects.size(), 1u);  // the light scene: no stroke object
  EXPECT_TRUE(renderer.take_messages().empty());    // a cancelled build is not an error
}

}  // namespace
}  // namespace inkray
