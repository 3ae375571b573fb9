// Film accumulation, the half-buffer noise estimate and AOV gating.
#include "core/film/film.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

TEST(Film, MeanOfSamplesAndDroppedNonFinite) {
  Film film(2, 1, {});
  film.add_sample(0, 0, 0, Color(1.f));
  film.add_sample(0, 0, 1, Color(3.f));
  film.add_sample(0, 0, 2, Color(std::numeric_limits<float>::quiet_NaN()));
  film.add_sample(1, 0, 0, Color(kInfinity));
  const RgbImage img = film.resolve();
  EXPECT_EQ(img.at(0, 0), Color(2.f));
  EXPECT_EQ(img.at(1, 0), Color(0.f));
  EXPECT_EQ(film.nonfinite_samples(), 2u);
  EXPECT_EQ(film.samples_at(0, 0), 2u);
}

TEST(Film, NoiseEstimateIsZeroForConstantAndPositiveForNoise) {
  Film flat(8, 8, {}), noisy(8, 8, {});
  for (uint32_t pass = 0; pass < 4; ++pass)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) {
        flat.add_sample(x, y, pass, Color(0.5f));
        noisy.add_sample(x, y, pass, Color(pass % 2 ? 1.f : 0.f));
      }
  EXPECT_EQ(flat.estimated_relative_error(), 0.0);
  // Halves differ by 1 everywhere, the mean is 0.5: sqrt(1/4) / 0.5 = 1.
  EXPECT_NEAR(noisy.estimated_relative_error(), 1.0, 1e-6);
}

TEST(Film, NoiseImageIsPerPixelHalfDifferenceOverMean) {
  Film film(3, 1, {});
  for (uint32_t pass = 0; pass < 4; ++pass) {
    film.add_sample(0, 0, pass, Color(0.5f));                  // constant: no noise
    film.add_sample(1, 0, pass, Color(pass % 2 ? 3.f : 1.f));  // halves 1 and 3
  }
  film.add_sample(2, 0, 0, Color(2.f));  // only the even half has samples
  const RgbImage noise = film.resolve_noise();
  ASSERT_EQ(noise.pixels.size(), 3u);
  EXPECT_EQ(noise.pixels[0], Color(0.f));
  // |1 - 3| / 2 / mean 2 = 0.5, the same in every channel.
  EXPECT_NEAR(noise.pixels[1].r, 0.5f, 1e-6f);
  EXPECT_EQ(noise.pixels[1].r, noise.pixels[1].g);
  EXPECT_EQ(noise.pixels[1].r, noise.pixels[1].b);
  EXPECT_EQ(noise.pixels[2], Color(0.f));
}

TEST(Film, AovsAreOnlyKeptWhenAsked) {
  AovSet set;
  set.add(Aov::depth);
  Film film(1, 1, set);
  FirstHit hit;
  hit.object = 3;
  hit.depth = 2.f;
  film.add_first_hit(0, 0, hit);
  hit.depth = 4.f;
  film.add_first_hit(0, 0, hit);
  EXPECT_EQ(film.resolve_aov(Aov::depth).at(0, 0), Color(3.f));
  EXPECT_EQ(film.resolve_aov(Aov::albedo).at(0, 0), Color(0.f));
}

}  // namespace
}  // namespace inkray
