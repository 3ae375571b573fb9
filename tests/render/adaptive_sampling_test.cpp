// Adaptive sampling (core/render/adaptive_sampling.h): easy tiles stop early, hard
// ones go on, and the image's mean stays that of uniform sampling.
#include "core/document/json_io.h"
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inkray {
namespace {

SceneDesc small_cornell() {
  auto loaded = load_scene(std::string(INKRAY_SOURCE_DIR) + "/scenes/cornell.json");
  EXPECT_TRUE(loaded.scene);
  SceneDesc desc = *loaded.scene;
  desc.render.width = desc.render.height = 64;
  return desc;
}

struct Rendered {
  RgbImage image;
  std::vector<uint32_t> samples;  // per pixel
  RenderStats stats;
};

Rendered render(const SceneDesc& desc, int spp, const AdaptiveSampling& adaptive) {
  const CompileResult c = compile_scene(desc);
  EXPECT_TRUE(c.scene);
  RenderSession session(2);
  session.set_scene(c.scene);
  session.set_adaptive(adaptive);
  render_batch(session, {spp, 0.0});
  Rendered r{session.film().resolve(), {}, session.stats()};
  for (int y = 0; y < desc.render.height; ++y)
    for (int x = 0; x < desc.render.width; ++x) r.samples.push_back(session.film().samples_at(x, y));
  return r;
}

// A diffuse ball under a uniform sky, small in a wide frame: the sky seen directly has
// no noise at all, the ball's shading has.
SceneDesc ball_under_sky() {
  SceneDesc d = testing::one_sphere_scene(128, 128);
  d.environment = ConstantEnvironmentDesc{Color(0.8f)};
  d.camera.vfov = 60.f;
  return d;
}

TEST(AdaptiveSampling, EasyTilesStopAtTheMinimumAndHardOnesGoOn) {
  const Rendered r = render(ball_under_sky(), 256, {0.01, 16});
  uint32_t fewest = ~0u, most = 0;
  for (const uint32_t n : r.samples) fewest = std::min(fewest, n), most = std::max(most, n);
  // The sky stops at the minimum, the ball goes on; every count is even, so the
  // halves stay balanced.
  EXPECT_EQ(fewest, 16u);
  EXPECT_GT(most, 64u);
  EXPECT_EQ(r.samples[0], 16u) << "the top-left corner is sky";
  EXPECT_GT(r.samples[64 * 128 + 64], 64u) << "the centre is the ball";
  for (const uint32_t n : r.samples) EXPECT_EQ(n % 2, 0u);
  EXPECT_LT(r.stats.paths, uint64_t(256) * r.samples.size());
}

TEST(AdaptiveSampling, StopsWhenEveryTileIsBelowTheThreshold) {
  const Rendered r = render(ball_under_sky(), 1 << 16, {0.05, 8});
  EXPECT_EQ(r.stats.active_tiles, 0u);
  EXPECT_LT(r.stats.spp, 1u << 16);
}

TEST(AdaptiveSampling, MeanMatchesUniformSampling) {
  // Stopping a tile picks its sample count from the data; pooled, smoothed estimates keep
  // that from favouring lucky tiles. Compare the mean over every 16 x 16 tile with a
  // uniform render of independent samples, in units of their combined standard error.
  SceneDesc desc = small_cornell();
  const Rendered adaptive = render(desc, 128, {0.2, 16});
  desc.render.seed += 1;
  const Rendered uniform = render(desc, 128, {});
  ASSERT_LT(adaptive.stats.paths, uniform.stats.paths);
  double sum_a = 0.0, sum_u = 0.0;
  for (size_t i = 0; i < adaptive.image.pixels.size(); ++i) {
    sum_a += double(luminance(adaptive.image.pixels[i]));
    sum_u += double(luminance(uniform.image.pixels[i]));
  }
  EXPECT_NEAR(sum_a / sum_u, 1.0, 0.01);
  for (int ty = 0; ty < 4; ++ty)
    for (int tx = 0; tx < 4; ++tx) {
      double a = 0.0, u = 0.0;
      for (int y = ty * 16; y < ty * 16 + 16; ++y)
        for (int x = tx * 16; x < tx * 16 + 16; ++x) {
          a += double(luminance(adaptive.image.at(x, y)));
          u += double(luminance(uniform.image.at(x, y)));
        }
      EXPECT_NEAR(a, u, 0.05 * std::max(u, 1.0)) << "tile " << tx << "," << ty;
    }
}

}  // namespace
}  // namespace inkray
