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

// A session keeps the films of the sizes it stepped through and clears one when it
// comes back to its size (RenderSession::film_for): every buffer of it must be as new.
TEST(RenderDeterminism, AFilmUsedBeforeRendersAsANewOne) {
  SceneDesc d = load_example("cornell_outlines.json");
  d.render.width = 64;
  d.render.height = 48;
  const CompileResult compiled = compile_scene(d);
  ASSERT_TRUE(compiled.scene);
  AovSet aovs;
  for (int a = 0; a < int(kAovNames.size()); ++a) aovs.add(Aov(a));
  const auto render = [&](RenderSession& session) {
    for (int pass = 0; pass < 3; ++pass) EXPECT_TRUE(session.render_pass());
  };
  RenderSession fresh(2);
  fresh.set_scene(compiled.scene, aovs, 1);
  render(fresh);
  // Another scene of the same size fills every buffer of each film before: what is
  // left of it would show in every AOV, normals included.
  SceneDesc other = load_example("toon.json");
  other.render.width = d.render.width;
  other.render.height = d.render.height;
  const CompileResult other_compiled = compile_scene(other);
  ASSERT_TRUE(other_compiled.scene);
  RenderSession stepped(2);
  for (int divisor : {1, 8, 4, 2, 1, 8, 1}) {
    stepped.set_scene(other_compiled.scene, aovs, divisor);
    render(stepped);
  }
  stepped.set_scene(compiled.scene, aovs, 1);
  render(stepped);
  EXPECT_TRUE(stepped.film().resolve().pixels == fresh.film().resolve().pixels);
  for (int a = 0; a < int(kAovNames.size()); ++a) {
    SCOPED_TRACE(kAovNames[size_t(a)]);
    EXPECT_TRUE(stepped.film().resolve_aov(Aov(a)).pixels == fresh.film().resolve_aov(Aov(a)).pixels);
  }
  EXPECT_EQ(stepped.stats().spp, 3u);
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
