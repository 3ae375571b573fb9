// The editor's renderer: a document submitted while a heavy one is still building
// supersedes it (the build is cancelled, not finished first) and is the one shown.
#include "core/render/progressive_renderer.h"
#include "core/document/json_io.h"

#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace inkray {
namespace {

TEST(ProgressiveRenderer, ANewDocumentSupersedesABuildInFlight) {
  SceneDesc heavy = testing::one_sphere_scene(32, 24);
  // 1.5 million strokes: seconds of building.
  heavy.strokes = {StrokeEmitterDesc{.name = "paint", .object = "ball", .seed = 9191, .count = 1500000}};
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
  EXPECT_EQ(renderer.scene()->world->objects.size(), 1u);  // the light scene: no stroke object
  EXPECT_TRUE(renderer.take_messages().empty());           // a cancelled build is not an error
}

// Turning the viewport's denoiser on denoises the samples already taken (the same
// accumulation, no restart) and reports the denoised estimate beside the raw one.
TEST(ProgressiveRenderer, DenoisingTheViewportKeepsItsSamples) {
  auto loaded = load_scene(std::string(INKRAY_SOURCE_DIR) + "/scenes/cornell.json");
  ASSERT_TRUE(loaded.scene);
  SceneDesc d = *loaded.scene;
  d.render.width = d.render.height = 48;
  ProgressiveRenderer renderer(2);
  renderer.set_limits({16, 0.0, 0.0});
  renderer.submit(d);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  std::shared_ptr<const ViewportSnapshot> shown;
  while (std::chrono::steady_clock::now() < deadline) {
    shown = renderer.latest();
    if (shown && shown->finished) break;
    renderer.wait_for_generation(renderer.generation(),
                                 std::chrono::steady_clock::now() + std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(shown && shown->finished);
  EXPECT_FALSE(shown->denoised);
  const uint64_t accumulation = shown->accumulation;
  ViewportView view;
  view.denoise = true;
  const uint64_t before = renderer.generation();
  renderer.set_view(view);
  ASSERT_TRUE(
      renderer.wait_for_generation(before, std::chrono::steady_clock::now() + std::chrono::seconds(30)));
  shown = renderer.latest();
  EXPECT_TRUE(shown->denoised);
  EXPECT_EQ(shown->accumulation, accumulation);
  EXPECT_EQ(shown->stats.spp, 16u);
  EXPECT_EQ(shown->denoised_spp, 16u);
  EXPECT_GT(shown->denoised_error, 0.0);
  EXPECT_LT(shown->denoised_error, shown->stats.relative_error);
}

}  // namespace
}  // namespace inkray
