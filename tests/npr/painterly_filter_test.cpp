// The painterly filters: flat stays flat, edges stay sharp, noise goes, mirror
// symmetry, thread-count determinism, flow-aligned smoothing, non-finite input.
// Set INKRAY_WRITE_FILTER_DEMO to also write before/after PNGs to /tmp.
#include "core/npr/painterly_filter.h"

#include "core/image/image_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace inkray {
namespace {

using Filter = RgbImage (*)(const RgbImage&, const PainterlyFilterParams&, ThreadBudget*);

struct NamedFilter {
  const char* name;
  Filter filter;
};
// Never cancelled here (compile_cancel_test covers that).
const NamedFilter kFilters[] = {
    {"kuwahara", [](const RgbImage& i, const PainterlyFilterParams& p,
                    ThreadBudget* t) { return kuwahara_filter(i, p, t); }},
    {"anisotropic", [](const RgbImage& i, const PainterlyFilterParams& p, ThreadBudget* t) {
       return anisotropic_kuwahara_filter(i, p, t);
     }}};

RgbImage make_image(int width, int height, const std::function<Color(int, int)>& pixel) {
  RgbImage image{width, height, std::vector<Color>(size_t(width) * size_t(height))};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.at(x, y) = pixel(x, y);
  return image;
}

RgbImage mirror(const RgbImage& image, bool horizontal) {
  return make_image(image.width, image.height, [&](int x, int y) {
    return horizontal ? image.at(image.width - 1 - x, y) : image.at(x, image.height - 1 - y);
  });
}

// Population variance of the green channel over [x0, x1) x [y0, y1).
double region_variance(const RgbImage& image, int x0, int y0, int x1, int y1) {
  double sum = 0, sum2 = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      sum += image.at(x, y).g;
      sum2 += double(image.at(x, y).g) * image.at(x, y).g;
    }
  const double count = double(x1 - x0) * double(y1 - y0);
  return sum2 / count - (sum / count) * (sum / count);
}

TEST(PainterlyFilter, ConstantImageStaysConstant) {
  const Color value(0.3f, 0.5f, 2.f);  // one channel above 1, as a render may have
  const RgbImage flat = make_image(37, 23, [&](int, int) { return value; });
  for (const NamedFilter& f : kFilters) {
    const RgbImage out = f.filter(flat, {}, nullptr);
    ASSERT_EQ(out.width, flat.width);
    ASSERT_EQ(out.height, flat.height);
    for (const Color& c : out.pixels)
      for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(c[ch], value[ch], 1e-6f) << f.name;
  }
}

// A 9x9 box blur moves pixels 2 px from the step by 0.6 * 3/9 = 0.2;
// the Kuwahara filters must keep them on their side.
TEST(PainterlyFilter, StepEdgeStaysSharp) {
  struct Step {
    Color left, right;
  };
  // The second step is a light next to a dark wall: linear values far above 1.
  const Step steps[] = {{Color(0.2f), Color(0.8f)}, {Color(0.05f), Color(20.f, 18.f, 15.f)}};
  for (const Step& step : steps) {
    const RgbImage image = make_image(64, 24, [&](int x, int) { return x < 32 ? step.left : step.right; });
    for (const NamedFilter& f : kFilters) {
      const RgbImage out = f.filter(image, {}, nullptr);
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
          if (x > 30 && x < 33) continue;
          const Color expected = x < 32 ? step.left : step.right;
          for (int ch = 0; ch < 3; ++ch)
            ASSERT_NEAR(out.at(x, y)[ch], expected[ch], 0.01f * expected[ch])
                << f.name << " at " << x << "," << y;
        }
    }
  }
}

TEST(PainterlyFilter, NoiseIsReduced) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> noise(-0.1f, 0.1f);
  const RgbImage image =
      make_image(96, 96, [&](int, int) { return Color(0.5f) + Color(noise(rng), noise(rng), noise(rng)); });
  const double before = region_variance(image, 8, 8, 88, 88);
  for (const NamedFilter& f : kFilters) {
    const double after = region_variance(f.filter(image, {}, nullptr), 8, 8, 88, 88);
    std::printf("[ info ] %s: noise variance %.3g -> %.3g (factor %.1f)\n", f.name, before, after,
                before / after);
    EXPECT_GT(before / after, 4.0) << f.name;
  }
}

// Shapes over noise: enough structure that the sector weights and the tensor matter.
RgbImage structured_test_image(int width, int height, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> noise(-0.05f, 0.05f);
  return make_image(width, height, [&](int x, int y) {
    const float dx = float(x) - 0.3f * float(width), dy = float(y) - 0.6f * float(height);
    Color c = dx * dx + dy * dy < 120.f ? Color(0.8f, 0.3f, 0.1f) : Color(0.1f, 0.2f, 0.4f);
    if (x + 2 * y > width) c += Color(0.3f, 0.3f, 0.f);
    if ((x / 7 + y / 5) % 3 == 0) c *= 0.6f;
    return c + Color(noise(rng), noise(rng), noise(rng));
  });
}

TEST(PainterlyFilter, MirroringTheInputMirrorsTheOutput) {
  const RgbImage image = structured_test_image(41, 33, 3);
  for (const NamedFilter& f : kFilters)
    for (bool horizontal : {true, false}) {
      const RgbImage a = f.filter(mirror(image, horizontal), {}, nullptr);
      const RgbImage b = mirror(f.filter(image, {}, nullptr), horizontal);
      float worst = 0.f;
      for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(a.pixels[i][ch] - b.pixels[i][ch]));
      // Not bit-exact (sums run in another order), but the sector table is built symmetric: ~2e-6 measured.
      EXPECT_LT(worst, 1e-5f) << f.name << (horizontal ? " horizontal" : " vertical");
    }
}

TEST(PainterlyFilter, AnyThreadCountGivesIdenticalResult) {
  const RgbImage image = structured_test_image(67, 45, 11);
  ThreadBudget one(1), four(4);
  for (const NamedFilter& f : kFilters) {
    const RgbImage serial = f.filter(image, {}, &one);
    // Without a budget the rows run in the caller's arena: every hardware thread.
    for (const RgbImage& parallel : {f.filter(image, {}, &four), f.filter(image, {}, nullptr)}) {
      ASSERT_EQ(serial.pixels.size(), parallel.pixels.size());
      for (size_t i = 0; i < serial.pixels.size(); ++i)
        ASSERT_EQ(serial.pixels[i], parallel.pixels[i]) << f.name;
    }
  }
}

// Noisy diagonal stripes. Along the stripes we measure the noise left on each
// diagonal line; across them, the contrast of the line means (the stripes).
TEST(PainterlyFilter, AnisotropicSmoothsAlongStripesMoreThanAcross) {
  constexpr int kSize = 128;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> noise(-0.08f, 0.08f);
  const RgbImage image = make_image(kSize, kSize, [&](int x, int y) {
    const float u = float(x + y) / std::sqrt(2.f);
    return Color(0.45f + 0.2f * std::sin(2.f * kPi * u / 12.f) + noise(rng));
  });
  struct Spread {
    double along = 0, across = 0;
  };
  const auto measure = [&](const RgbImage& im) {
    std::vector<double> line_mean;
    Spread spread;
    double residual = 0;
    int count = 0;
    for (int s = 40; s < 2 * kSize - 40; ++s) {  // the diagonals x + y = s, away from the borders
      double sum = 0, sum2 = 0;
      int n = 0;
      for (int x = std::max(12, s - kSize + 13); x <= std::min(kSize - 13, s - 12); ++x) {
        const double v = im.at(x, s - x).g;
        sum += v, sum2 += v * v, ++n;
      }
      line_mean.push_back(sum / n);
      residual += sum2 - sum * sum / n;
      count += n;
    }
    spread.along = residual / count;
    double m = 0, m2 = 0;
    for (double v : line_mean) m += v, m2 += v * v;
    m /= double(line_mean.size());
    spread.across = m2 / double(line_mean.size()) - m * m;
    return spread;
  };
  const Spread before = measure(image);
  const Spread iso = measure(kuwahara_filter(image, {}, nullptr));
  const Spread aniso = measure(anisotropic_kuwahara_filter(image, {}, nullptr));
  const double along = before.along / aniso.along, across = before.across / aniso.across;
  std::printf(
      "[ info ] stripes: along-stripe noise reduced %.1fx (isotropic %.1fx), across contrast reduced %.2fx "
      "(isotropic %.2fx)\n",
      along, before.along / iso.along, across, before.across / iso.across);
  EXPECT_GT(along, 3.0 * across);
  EXPECT_GT(along, 1.25 * before.along / iso.along);  // the ellipse reaches further along the flow
  EXPECT_LT(across, 1.5);                             // the stripes themselves survive
}

TEST(PainterlyFilter, NonFinitePixelsDoNotSpread) {
  RgbImage image = structured_test_image(24, 20, 9);
  image.at(10, 10) = Color(kInfinity, 0.5f, 0.5f);
  image.at(3, 15) = Color(std::numeric_limits<float>::quiet_NaN());
  image.at(0, 0) = Color(-kInfinity);
  image.at(20, 4) = Color(3e38f);  // finite but near the float limit
  for (const NamedFilter& f : kFilters) {
    const RgbImage out = f.filter(image, {}, nullptr);
    for (const Color& c : out.pixels) ASSERT_TRUE(is_finite(c)) << f.name;
  }
}

TEST(PainterlyFilter, TinyRadiusAndTinyImages) {
  const RgbImage image = structured_test_image(9, 7, 1);
  PainterlyFilterParams tiny;
  tiny.radius = 0.5f;
  // A half-pixel disc holds only the centre, so every sector agrees on it.
  const RgbImage out = kuwahara_filter(image, tiny, nullptr);
  for (size_t i = 0; i < out.pixels.size(); ++i) EXPECT_EQ(out.pixels[i], image.pixels[i]);
  for (const Color& c : anisotropic_kuwahara_filter(image, tiny, nullptr).pixels) EXPECT_TRUE(is_finite(c));

  const RgbImage single = make_image(1, 1, [](int, int) { return Color(0.25f, 4.f, 0.f); });
  const RgbImage empty;
  PainterlyFilterParams odd;
  odd.sectors = 3;
  odd.sharpness = 64.f;
  for (const NamedFilter& f : kFilters) {
    for (const PainterlyFilterParams& p : {PainterlyFilterParams{}, tiny, odd})
      EXPECT_EQ(f.filter(single, p, nullptr).pixels, single.pixels) << f.name;
    EXPECT_TRUE(f.filter(empty, {}, nullptr).pixels.empty());
  }
}

// Smooth pseudo-random texture in [0, 1]: octaves of bilinear value noise.
float fractal_noise(float x, float y) {
  const auto lattice = [](int i, int j) {
    uint32_t h = uint32_t(i) * 374761393u + uint32_t(j) * 668265263u;
    h = (h ^ (h >> 13)) * 1274126177u;
    return float(h >> 8) / float(1u << 24);
  };
  float sum = 0.f, amplitude = 0.5f;
  for (int octave = 0; octave < 4; ++octave, x *= 2.f, y *= 2.f, amplitude *= 0.5f) {
    const int i = int(std::floor(x)), j = int(std::floor(y));
    const float tx = x - float(i), ty = y - float(j);
    sum += amplitude * glm::mix(glm::mix(lattice(i, j), lattice(i + 1, j), tx),
                                glm::mix(lattice(i, j + 1), lattice(i + 1, j + 1), tx), ty);
  }
  return sum / 0.9375f;
}

// A synthetic scene: sky, a bright sun, shaded balls, foliage, stripes, a swirl and render-like noise.
RgbImage demo_pattern(int width, int height) {
  std::mt19937 rng(17);
  std::normal_distribution<float> noise(0.f, 0.04f);
  return make_image(width, height, [&](int x, int y) {
    const float u = float(x) / float(width), v = float(y) / float(height);
    Color c = glm::mix(Color(0.25f, 0.45f, 0.9f), Color(0.95f, 0.55f, 0.3f), v);
    const float leaves = fractal_noise(float(x) / 12.f, float(y) / 12.f);
    if (v < 0.45f && u > 0.3f && u < 0.62f && leaves > 0.45f + 0.8f * v)
      c = glm::mix(Color(0.05f, 0.15f, 0.03f), Color(0.35f, 0.6f, 0.1f),
                   fractal_noise(float(x) / 3.f, float(y) / 3.f));
    const auto ball = [&](float cx, float cy, float r, Color albedo) {
      const float dx = (u - cx) * float(width) / r, dy = (v - cy) * float(height) / r;
      if (dx * dx + dy * dy < 1.f) c = albedo * (0.15f + std::max(0.f, 0.8f - 0.6f * dx - 0.5f * dy));
    };
    ball(0.78f, 0.22f, 22.f, Color(40.f, 35.f, 25.f));  // the sun: far above 1
    ball(0.25f, 0.62f, 70.f, Color(0.8f, 0.15f, 0.1f) * (0.6f + 0.8f * fractal_noise(u * 40.f, v * 30.f)));
    ball(0.52f, 0.70f, 50.f, Color(0.2f, 0.7f, 0.25f));
    if (v > 0.82f) c = ((x / 12 + y / 12) % 2) ? Color(0.7f) : Color(0.1f);
    if (u > 0.72f && v > 0.45f && v < 0.8f) {
      const float dx = u * float(width) - 0.86f * float(width),
                  dy = v * float(height) - 0.62f * float(height);
      const float swirl = std::sin(0.35f * std::sqrt(dx * dx + dy * dy) + 3.f * std::atan2(dy, dx));
      c = Color(0.5f + 0.4f * swirl, 0.4f, 0.5f - 0.4f * swirl);
    }
    if (u < 0.15f && v < 0.6f) c = Color(0.3f + 0.25f * std::sin(float(x + y) * 0.6f), 0.3f, 0.2f);
    return c + Color(noise(rng), noise(rng), noise(rng));
  });
}

// The same crop of several images side by side, enlarged so single pixels show.
RgbImage detail_strip(const std::vector<RgbImage>& images, int x0, int y0, int size, int zoom) {
  const int cell = size * zoom;
  return make_image(cell * int(images.size()), cell, [&](int x, int y) {
    return images[size_t(x / cell)].at(x0 + x % cell / zoom, y0 + y / zoom);
  });
}

TEST(PainterlyFilter, WritesDemoWhenAsked) {
  if (!std::getenv("INKRAY_WRITE_FILTER_DEMO"))
    GTEST_SKIP() << "set INKRAY_WRITE_FILTER_DEMO to write /tmp PNGs";
  std::vector<RgbImage> images = {demo_pattern(480, 320)};
  PainterlyFilterParams params;
  params.radius = 6.f;
  ThreadBudget pool(0);
  for (const NamedFilter& f : kFilters) images.push_back(f.filter(images[0], params, &pool));
  const char* names[] = {"input", "kuwahara", "anisotropic"};
  std::string error;
  for (size_t i = 0; i < images.size(); ++i) {
    const std::string file = std::string("/tmp/inkray_painterly_") + names[i] + ".png";
    ASSERT_TRUE(write_image(file, images[i], &error)) << error;
    std::printf("[ info ] wrote %s\n", file.c_str());
  }
  // Input, isotropic, anisotropic: the foliage and the red ball, then the stripes and the swirl.
  ASSERT_TRUE(
      write_image("/tmp/inkray_painterly_detail_foliage.png", detail_strip(images, 150, 60, 120, 2), &error))
      << error;
  ASSERT_TRUE(
      write_image("/tmp/inkray_painterly_detail_swirl.png", detail_strip(images, 350, 150, 110, 2), &error))
      << error;
  ASSERT_TRUE(
      write_image("/tmp/inkray_painterly_detail_stripes.png", detail_strip(images, 0, 100, 110, 2), &error))
      << error;
}

}  // namespace
}  // namespace inkray
