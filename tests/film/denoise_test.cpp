// The denoiser (core/film/denoise.h): what it must leave alone (noise-free images, the
// edges of ids and toon bands) and what it must remove (noise), on films written
// sample by sample and on a rendered scene against a converged reference.
#include "core/film/denoise.h"
#include "core/document/json_io.h"
#include "core/image/image_io.h"
#include "core/math/hash.h"
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inkray {
namespace {

FirstHit hit_at(int object, float band = -1.f, Color albedo = Color(0.5f)) {
  FirstHit h;
  h.albedo = albedo;
  h.normal = Normal3(0.f, 0.f, 1.f);
  h.depth = 5.f;
  h.object = object;
  h.material = object;
  h.band = band;
  return h;
}

// `spp` samples per pixel of value(x, y) plus uniform noise of `amplitude` (mean zero),
// with the features of hit(x, y).
template <class Value, class Hit>
std::unique_ptr<Film> noisy_film(int w, int h, int spp, float amplitude, const Value& value, const Hit& hit,
                                 uint64_t seed = 7) {
  auto film = std::make_unique<Film>(w, h, denoise_aovs());
  Pcg32 rng(seed);
  for (int pass = 0; pass < spp; ++pass)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const float n = amplitude * (2.f * rng.next_float() - 1.f);
        film->add_sample(x, y, uint32_t(pass), value(x, y) + Color(n));
        film->add_first_hit(x, y, hit(x, y));
      }
  return film;
}

double rmse(const RgbImage& a, const RgbImage& b) {
  double s = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const Color d = a.pixels[i] - b.pixels[i];
    s += double(glm::dot(d, d)) / 3.0;
  }
  return std::sqrt(s / double(a.pixels.size()));
}

// As a display shows them: clamped to [0, 1] and sRGB-encoded, as inkray-bench measures.
double rmse_display(const RgbImage& a, const RgbImage& b) {
  double s = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(linear_to_srgb(std::clamp(a.pixels[i][c], 0.f, 1.f))) -
                       double(linear_to_srgb(std::clamp(b.pixels[i][c], 0.f, 1.f)));
      s += d * d / 3.0;
    }
  return std::sqrt(s / double(a.pixels.size()));
}

TEST(Denoise, NoiseFreeImageComesBackUnchanged) {
  // Both halves agree exactly: the cross-validation sees no noise to remove, so the
  // raw mean wins everywhere, edges, gradients and all.
  const auto value = [](int x, int y) {
    return Color(float(x) / 40.f, float((x * y) % 7) / 7.f, y < 10 ? 1.f : 0.1f);
  };
  const auto hit = [](int x, int) { return hit_at(x < 20 ? 0 : 1); };
  const std::unique_ptr<Film> film = noisy_film(40, 24, 4, 0.f, value, hit);
  const Denoised d = denoise(*film);
  const RgbImage raw = film->resolve();
  ASSERT_EQ(d.image.pixels.size(), raw.pixels.size());
  for (size_t i = 0; i < raw.pixels.size(); ++i) EXPECT_EQ(d.image.pixels[i], raw.pixels[i]) << "pixel " << i;
  EXPECT_EQ(d.relative_error, 0.0);
}

TEST(Denoise, ConstantImageConvergesToTheConstant) {
  const Color c(0.3f, 0.5f, 0.2f);
  const auto value = [&](int, int) { return c; };
  const auto hit = [](int, int) { return hit_at(0); };
  const RgbImage truth{64, 64, std::vector<Color>(64 * 64, c)};
  double last = 1e9;
  for (const int spp : {4, 16, 64}) {
    const std::unique_ptr<Film> film = noisy_film(64, 64, spp, 0.25f, value, hit);
    const Denoised d = denoise(*film);
    const double raw = rmse(film->resolve(), truth), den = rmse(d.image, truth);
    // Noise of 0.25 / sqrt(3 spp) per pixel: a wide blur leaves a small fraction of it.
    EXPECT_LT(den, 0.2 * raw) << spp << " spp";
    EXPECT_LT(den, last) << spp << " spp";
    last = den;
    double mean = 0.0;
    for (const Color& p : d.image.pixels) mean += double(p.g);
    EXPECT_NEAR(mean / double(d.image.pixels.size()), c.g, 3e-3) << spp << " spp";
  }
}

// Two regions that differ in one hard feature, side by side, each noisy around its own
// level: pixels within 3 of the edge must keep their side's level.
template <class Hit>
void expect_edge_kept(const Hit& hit, const char* what) {
  const auto value = [](int x, int) { return Color(x < 24 ? 0.2f : 0.8f); };
  const std::unique_ptr<Film> film = noisy_film(48, 32, 8, 0.3f, value, hit);
  const Denoised d = denoise(*film);
  double worst = 0.0, band_error = 0.0;
  int count = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 21; x < 27; ++x) {
      const float truth = x < 24 ? 0.2f : 0.8f;
      const double e = std::abs(double(d.image.at(x, y).g) - truth);
      band_error += e * e;
      ++count;
      worst = std::max(worst, e);
    }
  // Raw noise is 0.3 / sqrt(3 * 8) = 0.06 rms; mixing across the edge would pull by up to 0.3.
  EXPECT_LT(std::sqrt(band_error / count), 0.05) << what;
  EXPECT_LT(worst, 0.2) << what;
}

TEST(Denoise, DoesNotMixAcrossObjectIds) {
  expect_edge_kept([](int x, int) { return hit_at(x < 24 ? 0 : 1); }, "object ids");
}

TEST(Denoise, DoesNotMixAcrossToonBands) {
  // One object, one material: only the toon band tells the sides apart.
  expect_edge_kept([](int x, int) { return hit_at(0, x < 24 ? 0.f : 1.f); }, "toon bands");
}

TEST(Denoise, ARimRowAveragesToItsMeanWhicheverIdsEachPixelDrew) {
  // A lamp (radiance 15, object 1) above a ceiling (0.1, object 0); the row between has
  // the lamp in a tenth of each pixel. A pixel that drew the lamp is an edge pixel, one
  // that did not looks like ceiling: the row is denoised towards its mean only if the
  // latter count as edge pixels too, between edge pixels along the row.
  constexpr int kW = 64, kH = 12, kRim = 6, kSpp = 16;
  constexpr float kShare = 0.1f;
  auto film = std::make_unique<Film>(kW, kH, denoise_aovs());
  Pcg32 rng(11);
  for (int pass = 0; pass < kSpp; ++pass)
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const bool lamp = y < kRim || (y == kRim && rng.next_float() < kShare);
        // The ceiling's light is noisy, the lamp's is not.
        film->add_sample(x, y, uint32_t(pass), Color(lamp ? 15.f : 0.1f * (0.5f + rng.next_float())));
        film->add_first_hit(x, y, hit_at(lamp ? 1 : 0, -1.f, Color(lamp ? 1.f : 0.5f)));
      }
  const Denoised d = denoise(*film);
  const RgbImage raw = film->resolve();
  const float truth = kShare * 15.f + (1.f - kShare) * 0.1f;
  double raw_error = 0.0, denoised_error = 0.0;
  for (int x = 0; x < kW; ++x) {
    raw_error += std::pow(double(raw.at(x, kRim).g - truth), 2.0);
    denoised_error += std::pow(double(d.image.at(x, kRim).g - truth), 2.0);
  }
  EXPECT_LT(denoised_error, 0.5 * raw_error) << "raw " << raw_error << ", denoised " << denoised_error;
  // The lamp keeps its value, and the ceiling does not take the lamp's.
  EXPECT_EQ(d.image.at(10, kRim - 1).g, 15.f);
  EXPECT_NEAR(d.image.at(10, kRim + 2).g, 0.1f, 0.02f);
}

TEST(Denoise, KeepsAlbedoTexture) {
  // A checker of albedo (a brush texture, a stroke's alpha-tested detail) lit evenly:
  // the radiance is albedo * E, and demodulating keeps the checker while the light's
  // noise goes.
  const auto albedo = [](int x, int y) { return ((x / 2 + y / 2) % 2) ? Color(0.9f) : Color(0.1f); };
  const auto value = [&](int x, int y) { return albedo(x, y) * 0.7f; };
  const auto hit = [&](int x, int y) { return hit_at(0, -1.f, albedo(x, y)); };
  auto film = std::make_unique<Film>(48, 48, denoise_aovs());
  Pcg32 rng(3);
  for (int pass = 0; pass < 8; ++pass)
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 48; ++x) {
        film->add_sample(x, y, uint32_t(pass), value(x, y) * (1.f + 0.5f * (2.f * rng.next_float() - 1.f)));
        film->add_first_hit(x, y, hit(x, y));
      }
  RgbImage truth{48, 48, std::vector<Color>(48 * 48)};
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) truth.at(x, y) = value(x, y);
  const Denoised d = denoise(*film);
  EXPECT_LT(rmse(d.image, truth), 0.35 * rmse(film->resolve(), truth));
}

TEST(Denoise, LowersTheErrorOfARenderedSceneAndEstimatesIt) {
  auto loaded = load_scene(std::string(INKRAY_SOURCE_DIR) + "/scenes/cornell.json");
  ASSERT_TRUE(loaded.scene);
  SceneDesc desc = *loaded.scene;
  desc.render.width = desc.render.height = 64;
  testing::RenderedFilm noisy = testing::render_film(desc, 16, denoise_aovs());
  SceneDesc ref_desc = desc;
  ref_desc.render.seed += 1000;
  const RgbImage reference = testing::render_scene(ref_desc, 1024);
  const Film& film = noisy.session->film();
  const Denoised d = denoise(film);
  const double raw = rmse_display(film.resolve(), reference), den = rmse_display(d.image, reference);
  EXPECT_LT(den, 0.6 * raw) << "raw " << raw << ", denoised " << den;
  // The estimates, made without the reference, are of the right size: relative RMS
  // error of luminance, as Film::estimated_relative_error.
  const auto relative_error = [&](const RgbImage& img) {
    double diff2 = 0.0, lum = 0.0;
    for (size_t i = 0; i < reference.pixels.size(); ++i) {
      const double e = double(luminance(img.pixels[i])) - double(luminance(reference.pixels[i]));
      diff2 += e * e;
      lum += double(luminance(reference.pixels[i]));
    }
    const double n = double(reference.pixels.size());
    return std::sqrt(diff2 / n) / (lum / n);
  };
  const double truth = relative_error(d.image), raw_truth = relative_error(film.resolve());
  std::printf("relative error: denoised %.4f (estimated %.4f), raw %.4f (estimated %.4f)\n", truth,
              d.relative_error, raw_truth, film.estimated_relative_error());
  EXPECT_GT(d.relative_error, truth / 3.0);
  EXPECT_LT(d.relative_error, truth * 3.0);
  EXPECT_LT(d.relative_error, film.estimated_relative_error());
}

}  // namespace
}  // namespace inkray
