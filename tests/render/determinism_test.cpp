// Images do not depend on thread count or tile order, and no scene in scenes/
// produces a non-finite value.
#include "core/document/json_io.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace inkray {
namespace {

SceneDesc load_example(const std::string& name) {
  const auto loaded = load_scene(std::filesystem::path(INKRAY_SOURCE_DIR) / "scenes" / name);
  EXPECT_TRUE(loaded.scene) << (loaded.errors.empty() ? "" : loaded.errors.front());
  return loaded.scene ? *loaded.scene : SceneDesc{};
}

TEST(RenderDeterminism, SameImageAtOneAndTwoThreads) {
  SceneDesc d = load_example("cornell.json");
  d.render.width = 96;
  d.render.height = 96;
  const RgbImage one = testing::render_scene(d, 8, 1);
  const RgbImage two = testing::render_scene(d, 8, 2);
  const RgbImage three = testing::render_scene(d, 8, 3);
  ASSERT_EQ(one.pixels.size(), two.pixels.size());
  EXPECT_TRUE(one.pixels == two.pixels);
  EXPECT_TRUE(one.pixels == three.pixels);
}

TEST(RenderDeterminism, SeedChangesTheNoiseOnly) {
  SceneDesc d = load_example("cornell.json");
  d.render.width = 64;
  d.render.height = 64;
  const RgbImage a = testing::render_scene(d, 16);
  d.render.seed = 99;
  const RgbImage b = testing::render_scene(d, 16);
  EXPECT_FALSE(a.pixels == b.pixels);
  const Color ma = testing::mean_color(a), mb = testing::mean_color(b);
  EXPECT_NEAR(ma.g, mb.g, 0.03f * ma.g);
}

TEST(RenderDeterminism, NoNonFiniteValuesInAnyExampleScene) {
  const auto dir = std::filesystem::path(INKRAY_SOURCE_DIR) / "scenes";
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().filename().string());
    SceneDesc d = load_example(entry.path().filename().string());
    const float aspect = float(d.render.width) / float(d.render.height);
    d.render.height = 48;
    d.render.width = std::max(1, int(48 * aspect));
    RenderStats stats;
    const RgbImage img = testing::render_scene(d, 8, 2, &stats);
    EXPECT_EQ(stats.nonfinite_samples, 0u);
    for (const Color& c : img.pixels) ASSERT_TRUE(is_finite(c));
    ++scenes;
  }
  EXPECT_GE(scenes, 5);
}

}  // namespace
}  // namespace inkray
