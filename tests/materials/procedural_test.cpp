// The procedural node maths against hand-computed values: HSV edits, MixRGB modes, colour ramps,
// Fresnel and Layer Weight, and the statistical and edge-case properties of noise and Voronoi.
#include "core/materials/procedural.h"

#include "core/math/hash.h"

#include "support/color_checks.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace inkray {
namespace {

using testing::expect_color_near;

Vec3 random_point(Pcg32& rng, float half_extent) {
  return {(2.f * rng.next_float() - 1.f) * half_extent, (2.f * rng.next_float() - 1.f) * half_extent,
          (2.f * rng.next_float() - 1.f) * half_extent};
}

Vec3 random_direction(Pcg32& rng) {
  for (;;) {
    const Vec3 v = random_point(rng, 1.f);
    const float len2 = glm::dot(v, v);
    if (len2 > 1e-4f && len2 <= 1.f) return v / std::sqrt(len2);
  }
}

bool in_unit_range(float x) { return x >= 0.f && x <= 1.f; }

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kHuge = std::numeric_limits<float>::max();

const Color kRed{1.f, 0.f, 0.f}, kGreen{0.f, 1.f, 0.f}, kBlue{0.f, 0.f, 1.f};

// ---- HSV ----------------------------------------------------------------------------------------

// rgb_to_hsv / hsv_to_rgb come through procedural.h from core/math/color_space.h: hue in degrees.
TEST(ProceduralHsv, KnownColours) {
  expect_color_near(rgb_to_hsv(kRed), {0.f, 1.f, 1.f});
  expect_color_near(hsv_to_rgb({0.f, 1.f, 1.f}), kRed);
  for (float v : {0.f, 0.18f, 0.5f, 1.f})
    expect_color_near(rgb_to_hsv(Color(v)), {0.f, 0.f, v});  // grey: s = 0
}

TEST(ProceduralHsv, RoundTrip) {
  Pcg32 rng(11);
  for (int i = 0; i < 1000; ++i) {
    const Color c{rng.next_float(), rng.next_float(), rng.next_float()};
    expect_color_near(hsv_to_rgb(rgb_to_hsv(c)), c, 2e-6f);
  }
}

TEST(ProceduralHsv, AdjustIdentity) {
  Pcg32 rng(12);
  for (int i = 0; i < 1000; ++i) {
    const Color c{rng.next_float(), rng.next_float(), rng.next_float()};
    expect_color_near(hsv_adjust(c, 0.5f, 1.f, 1.f, 1.f), c, 1e-5f);
  }
  // Value is not clamped to 1: HDR colours pass through unchanged too.
  expect_color_near(hsv_adjust({4.f, 2.f, 1.f}, 0.5f, 1.f, 1.f, 1.f), {4.f, 2.f, 1.f}, 1e-5f);
}

TEST(ProceduralHsv, AdjustHueRotation) {
  // hue - 0.5 = +1/3 turn = 120 degrees: red -> green; -1/3 turn: red -> blue.
  expect_color_near(hsv_adjust(kRed, 0.5f + 1.f / 3.f, 1.f, 1.f, 1.f), kGreen, 1e-4f);
  expect_color_near(hsv_adjust(kRed, 0.5f - 1.f / 3.f, 1.f, 1.f, 1.f), kBlue, 1e-4f);
  // A full turn wraps back to the input.
  expect_color_near(hsv_adjust(kRed, 1.5f, 1.f, 1.f, 1.f), kRed, 1e-4f);
  // Half-way blend: fac 0.5 between red and green.
  expect_color_near(hsv_adjust(kRed, 0.5f + 1.f / 3.f, 1.f, 1.f, 0.5f), {0.5f, 0.5f, 0.f}, 1e-4f);
}

TEST(ProceduralHsv, AdjustSaturationValueAndFac) {
  const Color c{0.8f, 0.4f, 0.2f};                                        // h = 20 deg, s = 0.75, v = 0.8
  expect_color_near(hsv_adjust(c, 0.5f, 0.f, 1.f, 1.f), Color(0.8f));     // no saturation: grey at v
  expect_color_near(hsv_adjust(c, 0.5f, 1.f, 2.f, 1.f), 2.f * c, 1e-5f);  // value multiplies
  expect_color_near(hsv_adjust(c, 0.5f, 10.f, 1.f, 1.f), {0.8f, 0.26666667f, 0.f});  // s clamps to 1
  expect_color_near(hsv_adjust(c, 0.9f, 0.3f, 0.2f, 0.f), c, 0.f);                   // fac 0: the input
}

TEST(ProceduralHsv, AdjustNeverNegativeAndFinite) {
  const Color outs[] = {hsv_adjust({-1.f, 0.5f, 0.2f}, 0.7f, 2.f, 1.f, 1.f),
                        hsv_adjust({-1.f, -2.f, -3.f}, 0.5f, 1.f, 1.f, 0.f),
                        hsv_adjust({0.3f, 0.2f, 0.1f}, 0.5f, 1.f, -4.f, 1.f),
                        hsv_adjust({kHuge, 1.f, 0.f}, 1e30f, 1e30f, 1e30f, 1.f),
                        hsv_adjust({0.3f, 0.2f, 0.1f}, kNaN, kNaN, kNaN, kNaN)};
  for (const Color& c : outs) {
    EXPECT_TRUE(is_finite(c));
    EXPECT_GE(c.r, 0.f);
    EXPECT_GE(c.g, 0.f);
    EXPECT_GE(c.b, 0.f);
  }
}

// ---- MixRGB -------------------------------------------------------------------------------------

constexpr std::array<BlendMode, 5> kModes{BlendMode::mix, BlendMode::multiply, BlendMode::screen,
                                          BlendMode::overlay, BlendMode::add};
const Color kA{0.2f, 0.6f, 0.9f}, kB{0.5f, 0.3f, 0.8f};

TEST(ProceduralBlend, FacZeroReturnsA) {
  for (BlendMode mode : kModes) {
    SCOPED_TRACE(int(mode));
    expect_color_near(blend_colors(mode, 0.f, kA, kB), kA, 1e-6f);
    expect_color_near(blend_colors(mode, -3.f, kA, kB), kA, 1e-6f);  // fac clamps to 0
  }
}

// Each mode by hand at fac 1 and fac 0.5, for a = (0.2, 0.6, 0.9), b = (0.5, 0.3, 0.8).
struct BlendByHand {
  const char* name;
  BlendMode mode;
  Color at_one, at_half;
};
const BlendByHand kBlendsByHand[] = {
    {"mix", BlendMode::mix, kB, {0.35f, 0.45f, 0.85f}},
    {"multiply", BlendMode::multiply, {0.1f, 0.18f, 0.72f}, {0.15f, 0.39f, 0.81f}},
    // screen at 1: 1 - (1-b)(1-a) = 1 - (0.5*0.8, 0.7*0.4, 0.2*0.1);
    // at 0.5: 1 - (0.5 + 0.5(1-b))(1-a) = 1 - (0.75*0.8, 0.85*0.4, 0.6*0.1).
    {"screen", BlendMode::screen, {0.6f, 0.72f, 0.98f}, {0.4f, 0.66f, 0.94f}},
    // overlay at 1: r has a < 0.5 -> 2ab = 0.2; g, b: 1 - 2(1-b)(1-a) = 1 - 0.56, 1 - 0.04;
    // at 0.5: r = 0.2 * (0.5 + 0.5) = 0.2; g = 1 - (0.5 + 0.7) * 0.4 = 0.52; b = 1 - (0.5 + 0.2) * 0.1 =
    // 0.93.
    {"overlay", BlendMode::overlay, {0.2f, 0.44f, 0.96f}, {0.2f, 0.52f, 0.93f}},
    {"add", BlendMode::add, {0.7f, 0.9f, 1.7f}, {0.45f, 0.75f, 1.3f}},
};

TEST(ProceduralBlend, FacOneHandValues) {
  for (const BlendByHand& c : kBlendsByHand) {
    SCOPED_TRACE(c.name);
    expect_color_near(blend_colors(c.mode, 1.f, kA, kB), c.at_one);
  }
  // fac above 1 clamps to 1.
  expect_color_near(blend_colors(BlendMode::add, 7.f, kA, kB), {0.7f, 0.9f, 1.7f});
}

TEST(ProceduralBlend, FacHalfHandValues) {
  for (const BlendByHand& c : kBlendsByHand) {
    SCOPED_TRACE(c.name);
    expect_color_near(blend_colors(c.mode, 0.5f, kA, kB), c.at_half);
  }
}

TEST(ProceduralBlend, FiniteForExtremeInputs) {
  for (BlendMode mode : kModes) {
    EXPECT_TRUE(is_finite(blend_colors(mode, 0.7f, Color(-kHuge), Color(-kHuge))));
    EXPECT_TRUE(is_finite(blend_colors(mode, 1.f, Color(kHuge), Color(kHuge))));
    EXPECT_TRUE(is_finite(blend_colors(mode, kNaN, kA, kB)));
  }
}

// ---- Colour ramp --------------------------------------------------------------------------------

const std::vector<RampStop> kStops{{0.2f, kRed}, {0.6f, kBlue}, {0.8f, kGreen}};

TEST(ProceduralRamp, Constant) {
  const auto eval = [](float x) { return ramp_eval(kStops, x, RampInterpolation::constant); };
  expect_color_near(eval(0.1f), kRed, 0.f);  // below the first stop
  expect_color_near(eval(0.2f), kRed, 0.f);
  expect_color_near(eval(0.5f), kRed, 0.f);
  expect_color_near(eval(0.6f), kBlue, 0.f);
  expect_color_near(eval(0.7f), kBlue, 0.f);
  expect_color_near(eval(0.8f), kGreen, 0.f);
  expect_color_near(eval(0.95f), kGreen, 0.f);
  expect_color_near(eval(-4.f), kRed, 0.f);  // x clamps to [0, 1]
  expect_color_near(eval(9.f), kGreen, 0.f);
}

TEST(ProceduralRamp, Linear) {
  const auto eval = [](float x) { return ramp_eval(kStops, x, RampInterpolation::linear); };
  expect_color_near(eval(0.f), kRed, 0.f);
  expect_color_near(eval(0.2f), kRed, 0.f);
  expect_color_near(eval(0.3f), {0.75f, 0.f, 0.25f});
  expect_color_near(eval(0.4f), {0.5f, 0.f, 0.5f});
  expect_color_near(eval(0.6f), kBlue, 0.f);
  expect_color_near(eval(0.7f), {0.f, 0.5f, 0.5f});
  expect_color_near(eval(0.8f), kGreen, 0.f);
  expect_color_near(eval(1.f), kGreen, 0.f);
  expect_color_near(eval(-1.f), kRed, 0.f);
  expect_color_near(eval(2.f), kGreen, 0.f);
}

TEST(ProceduralRamp, Ease) {
  const auto eval = [](float x) { return ramp_eval(kStops, x, RampInterpolation::ease); };
  // x = 0.3: t = 0.25, 3t^2 - 2t^3 = 0.1875 - 0.03125 = 0.15625.
  expect_color_near(eval(0.3f), {0.84375f, 0.f, 0.15625f});
  expect_color_near(eval(0.4f), {0.5f, 0.f, 0.5f});  // t = 0.5 is a fixed point of the smoothing
  // x = 0.75: t = 0.75 -> 0.84375.
  expect_color_near(eval(0.75f), {0.f, 0.84375f, 0.15625f});
  expect_color_near(eval(0.2f), kRed, 0.f);
  expect_color_near(eval(0.6f), kBlue, 0.f);
  expect_color_near(eval(0.05f), kRed, 0.f);
  expect_color_near(eval(0.99f), kGreen, 0.f);
}

TEST(ProceduralRamp, ZeroAndOneStop) {
  for (RampInterpolation mode :
       {RampInterpolation::constant, RampInterpolation::linear, RampInterpolation::ease}) {
    expect_color_near(ramp_eval({}, 0.5f, mode), Color(0.f), 0.f);
    const RampStop one[] = {{0.4f, {0.1f, 0.2f, 0.3f}}};
    for (float x : {-1.f, 0.f, 0.4f, 0.7f, 1.f, 3.f})
      expect_color_near(ramp_eval(one, x, mode), one[0].color, 0.f);
  }
}

TEST(ProceduralRamp, CoincidentStops) {
  // A hard edge at 0.5: black -> red below it, blue -> white above; x on the edge takes the later stop.
  const RampStop stops[] = {{0.f, Color(0.f)}, {0.5f, kRed}, {0.5f, kBlue}, {1.f, Color(1.f)}};
  for (RampInterpolation mode : {RampInterpolation::linear, RampInterpolation::ease}) {
    expect_color_near(ramp_eval(stops, 0.5f, mode), kBlue, 0.f);
    expect_color_near(ramp_eval(stops, 0.25f, mode), {0.5f, 0.f, 0.f});
    expect_color_near(ramp_eval(stops, 0.4999f, mode), kRed, 1e-3f);
  }
  expect_color_near(ramp_eval(stops, 0.75f, RampInterpolation::linear), {0.5f, 0.5f, 1.f});
  expect_color_near(ramp_eval(stops, 0.5f, RampInterpolation::constant), kBlue, 0.f);
  // Every stop at one position.
  const RampStop same[] = {{0.5f, kRed}, {0.5f, kGreen}, {0.5f, kBlue}};
  for (RampInterpolation mode :
       {RampInterpolation::constant, RampInterpolation::linear, RampInterpolation::ease}) {
    expect_color_near(ramp_eval(same, 0.2f, mode), kRed, 0.f);
    expect_color_near(ramp_eval(same, 0.5f, mode), kBlue, 0.f);
    expect_color_near(ramp_eval(same, 0.9f, mode), kBlue, 0.f);
    EXPECT_TRUE(is_finite(ramp_eval(same, kNaN, mode)));
  }
}

// ---- Fresnel and Layer Weight -------------------------------------------------------------------

TEST(ProceduralFresnel, NormalIncidence) {
  for (float ior : {1.05f, 1.33f, 1.5f, 2.4f, 4.f}) {
    SCOPED_TRACE(ior);
    const float f0 = sqr((ior - 1.f) / (ior + 1.f));
    EXPECT_NEAR(fresnel_factor(ior, 1.f), f0, 1e-5f);
    EXPECT_NEAR(fresnel_factor(ior, -1.f), f0, 1e-5f);  // inside, 1/ior: the same at normal incidence
  }
  EXPECT_NEAR(fresnel_factor(1.5f, 1.f), 0.04f, 1e-5f);
}

TEST(ProceduralFresnel, GrazingTendsToOne) {
  for (float ior : {1.1f, 1.5f, 3.f}) {
    float previous = 0.f;
    for (float c : {1.f, 0.5f, 0.1f, 0.01f, 1e-3f, 1e-4f}) {
      const float f = fresnel_factor(ior, c);
      EXPECT_GE(f, previous);  // rises monotonically towards grazing
      previous = f;
    }
    EXPECT_GT(fresnel_factor(ior, 1e-4f), 0.99f);
    EXPECT_NEAR(fresnel_factor(ior, 0.f), 1.f, 1e-6f);
  }
}

TEST(ProceduralFresnel, InsideAndClamps) {
  // Inside glass at 0.3: sin = 0.954 > 1/1.5, total internal reflection.
  EXPECT_EQ(fresnel_factor(1.5f, -0.3f), 1.f);
  // ior below 1 clamps to 1.0001: practically no reflection, but still defined at grazing.
  EXPECT_EQ(fresnel_factor(0.5f, 0.7f), fresnel_factor(1.0001f, 0.7f));
  EXPECT_LT(fresnel_factor(0.5f, 1.f), 1e-8f);
  for (float ior : {-5.f, 0.f, 1.f, 1.0001f, 1e6f, 1e30f, kHuge, kNaN})
    for (float c : {-2.f, -1.f, -0.5f, -1e-6f, 0.f, 1e-6f, 0.5f, 1.f, 2.f, kNaN}) {
      const float f = fresnel_factor(ior, c);
      EXPECT_TRUE(in_unit_range(f)) << ior << " " << c << " -> " << f;
    }
}

TEST(ProceduralLayerWeight, FacingAtHalfBlendIsOneMinusCos) {
  for (float c : {-1.f, -0.6f, -0.1f, 0.f, 0.25f, 0.5f, 0.9f, 1.f})
    EXPECT_NEAR(layer_weight(0.5f, c).facing, 1.f - std::abs(c), 1e-6f) << c;
}

TEST(ProceduralLayerWeight, FacingExponents) {
  const float c = 0.64f;
  EXPECT_NEAR(layer_weight(0.25f, c).facing, 1.f - 0.8f, 1e-6f);     // exponent 0.5
  EXPECT_NEAR(layer_weight(0.75f, c).facing, 1.f - 0.4096f, 1e-6f);  // exponent 2
  EXPECT_NEAR(layer_weight(0.f, c).facing, 0.f, 1e-6f);              // exponent 0
  EXPECT_NEAR(layer_weight(1.f, c).facing, 1.f, 1e-6f);              // exponent 50000
  EXPECT_NEAR(layer_weight(0.f, 0.f).facing, 0.f, 1e-6f);            // pow(0, 0) = 1
}

TEST(ProceduralLayerWeight, FresnelOutput) {
  // blend 1/3 -> ior 1/(1 - 1/3) = 1.5: 0.04 at normal incidence.
  EXPECT_NEAR(layer_weight(1.f / 3.f, 1.f).fresnel, 0.04f, 1e-5f);
  for (float blend : {0.f, 0.2f, 0.5f, 0.9f})
    for (float c : {-0.8f, 0.1f, 0.7f})
      EXPECT_NEAR(layer_weight(blend, c).fresnel, fresnel_factor(1.f / (1.f - blend), c), 1e-6f);
  for (float blend : {-1.f, 1.f, 5.f, kNaN})
    for (float c : {-1.f, 0.f, 0.5f, 1.f, kNaN}) {
      const LayerWeight w = layer_weight(blend, c);
      EXPECT_TRUE(in_unit_range(w.fresnel) && in_unit_range(w.facing)) << blend << " " << c;
    }
}

// ---- Noise --------------------------------------------------------------------------------------

struct NoiseParams {
  float scale;
  int octaves;
  float roughness;
  float distortion;
};
constexpr NoiseParams kNoiseParams[] = {
    {1.f, 1, 0.5f, 0.f}, {5.f, 2, 0.5f, 0.f},  {5.f, 8, 1.f, 0.f},   {2.f, 16, 0.75f, 0.f},
    {3.f, 4, 0.5f, 1.f}, {0.5f, 6, 0.3f, 5.f}, {10.f, 3, 0.f, 0.3f},
};
constexpr NoiseKind kKinds[] = {NoiseKind::value, NoiseKind::gradient};

TEST(ProceduralNoise, RangeOverRandomPoints) {
  for (NoiseKind kind : kKinds)
    for (const NoiseParams& np : kNoiseParams) {
      SCOPED_TRACE(::testing::Message() << int(kind) << " scale " << np.scale << " octaves " << np.octaves);
      Pcg32 rng(21);
      int failures = 0;
      for (int i = 0; i < 10000; ++i) {
        const NoiseResult r =
            noise_texture(random_point(rng, 20.f), kind, np.scale, np.octaves, np.roughness, np.distortion);
        failures += !in_unit_range(r.fac) || !in_unit_range(r.color.r) || !in_unit_range(r.color.g) ||
                    !in_unit_range(r.color.b);
      }
      EXPECT_EQ(failures, 0);
    }
  Pcg32 rng(22);
  float lo[2] = {1.f, 1.f}, hi[2] = {0.f, 0.f};
  for (int i = 0; i < 10000; ++i) {
    const Vec3 p = random_point(rng, 50.f);
    const float n[2] = {value_noise(p), gradient_noise(p)};
    for (int k = 0; k < 2; ++k) {
      ASSERT_TRUE(in_unit_range(n[k])) << k;
      lo[k] = std::min(lo[k], n[k]);
      hi[k] = std::max(hi[k], n[k]);
    }
  }
  // Not squashed towards 0.5: both single octaves use most of [0, 1].
  for (int k = 0; k < 2; ++k) {
    EXPECT_LT(lo[k], 0.2f) << k;
    EXPECT_GT(hi[k], 0.8f) << k;
  }
}

TEST(ProceduralNoise, Deterministic) {
  Pcg32 rng(23);
  for (int i = 0; i < 200; ++i) {
    const Vec3 p = random_point(rng, 100.f);
    EXPECT_EQ(value_noise(p), value_noise(p));
    EXPECT_EQ(gradient_noise(p), gradient_noise(p));
    for (NoiseKind kind : kKinds) {
      const NoiseResult a = noise_texture(p, kind, 3.f, 5, 0.6f, 0.5f);
      const NoiseResult b = noise_texture(p, kind, 3.f, 5, 0.6f, 0.5f);
      EXPECT_EQ(a.fac, b.fac);
      EXPECT_EQ(a.color, b.color);
    }
  }
}

TEST(ProceduralNoise, Continuity) {
  // 1e-4 apart: single octaves have slopes of a few units at most, so differences stay near 1e-3.
  Pcg32 rng(24);
  float worst = 0.f;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 p = random_point(rng, 30.f);
    const Vec3 q = p + 1e-4f * random_direction(rng);
    worst = std::max(worst, std::abs(value_noise(p) - value_noise(q)));
    worst = std::max(worst, std::abs(gradient_noise(p) - gradient_noise(q)));
    for (NoiseKind kind : kKinds) {
      worst = std::max(worst, std::abs(noise_texture(p, kind, 2.f, 4, 0.5f, 0.f).fac -
                                       noise_texture(q, kind, 2.f, 4, 0.5f, 0.f).fac));
      const Color a = noise_texture(p, kind, 2.f, 4, 0.5f, 0.5f).color;
      const Color b = noise_texture(q, kind, 2.f, 4, 0.5f, 0.5f).color;
      worst = std::max(worst, max_component(glm::abs(a - b)));
    }
  }
  EXPECT_LT(worst, 1e-2f);
}

TEST(ProceduralNoise, MeanIsHalf) {
  for (NoiseKind kind : kKinds) {
    Pcg32 rng(25);
    double single = 0.0, fractal = 0.0, colour_g = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const Vec3 p = random_point(rng, 200.f);
      single += kind == NoiseKind::value ? value_noise(p) : gradient_noise(p);
      const NoiseResult r = noise_texture(p, kind, 1.f, 6, 0.5f, 0.2f);
      fractal += r.fac;
      colour_g += r.color.g;
    }
    EXPECT_NEAR(single / n, 0.5, 0.05) << int(kind);
    EXPECT_NEAR(fractal / n, 0.5, 0.05) << int(kind);
    EXPECT_NEAR(colour_g / n, 0.5, 0.05) << int(kind);
  }
}

TEST(ProceduralNoise, LatticeValues) {
  // Asserted contract: value_noise at integer (i, j, k) is exactly
  // u32_to_unit_float(hash_combine(uint32_t(i), uint32_t(j), uint32_t(k), 0u)); gradient noise is 0.5 there.
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j)
      for (int k = -3; k <= 3; ++k) {
        const Vec3 p{float(i), float(j), float(k)};
        EXPECT_EQ(value_noise(p), u32_to_unit_float(hash_combine(uint32_t(i), uint32_t(j), uint32_t(k), 0u)));
        EXPECT_EQ(gradient_noise(p), 0.5f);
      }
  const int far = 1000000;
  EXPECT_EQ(value_noise(Vec3(float(far), float(-far), 7.f)),
            u32_to_unit_float(hash_combine(uint32_t(far), uint32_t(-far), 7u, 0u)));
}

TEST(ProceduralNoise, SingleOctaveMatchesBuildingBlocks) {
  Pcg32 rng(26);
  for (int i = 0; i < 100; ++i) {
    const Vec3 p = random_point(rng, 10.f);
    EXPECT_EQ(noise_texture(p, NoiseKind::value, 1.f, 1, 0.5f, 0.f).fac, value_noise(p));
    EXPECT_EQ(noise_texture(p, NoiseKind::gradient, 1.f, 1, 0.5f, 0.f).fac, gradient_noise(p));
    // Roughness 0 silences every octave after the first.
    EXPECT_EQ(noise_texture(p, NoiseKind::value, 1.f, 9, 0.f, 0.f).fac, value_noise(p));
  }
}

TEST(ProceduralNoise, ColourChannelsDecorrelated) {
  for (NoiseKind kind : kKinds) {
    Pcg32 rng(27);
    const int n = 5000;
    double s[3] = {}, ss[3] = {}, cross[3] = {};  // cross: rg, gb, br
    for (int i = 0; i < n; ++i) {
      const Color c = noise_texture(random_point(rng, 100.f), kind, 1.f, 3, 0.5f, 0.f).color;
      for (int k = 0; k < 3; ++k) {
        s[k] += c[k];
        ss[k] += double(c[k]) * c[k];
        cross[k] += double(c[k]) * c[(k + 1) % 3];
      }
    }
    for (int k = 0; k < 3; ++k) {
      const int l = (k + 1) % 3;
      const double cov = cross[k] / n - s[k] / n * s[l] / n;
      const double var_k = ss[k] / n - sqr(float(s[k] / n)), var_l = ss[l] / n - sqr(float(s[l] / n));
      EXPECT_LT(std::abs(cov / std::sqrt(var_k * var_l)), 0.2) << int(kind) << " channel " << k;
    }
  }
}

TEST(ProceduralNoise, FiniteForExtremeInputs) {
  const Vec3 points[] = {Vec3(1e6f, -1e6f, 1e6f),
                         Vec3(1e6f + 0.5f, 3.25f, -1e6f),
                         Vec3(1e30f),
                         Vec3(-kHuge),
                         Vec3(kHuge, -kHuge, 0.f),
                         Vec3(0.f),
                         Vec3(kNaN)};
  const NoiseParams params[] = {{1.f, 16, 1.f, 0.f},    {0.f, 4, 0.5f, 1.f},     {-3.f, 4, 0.5f, 1.f},
                                {1e30f, 4, 0.5f, 0.f},  {kHuge, 16, 1.f, kHuge}, {1.f, -5, -1.f, -2.f},
                                {1.f, 100, 5.f, 1e30f}, {kNaN, 3, kNaN, kNaN}};
  for (NoiseKind kind : kKinds)
    for (const Vec3& p : points) {
      EXPECT_TRUE(in_unit_range(value_noise(p)));
      EXPECT_TRUE(in_unit_range(gradient_noise(p)));
      for (const NoiseParams& np : params) {
        const NoiseResult r = noise_texture(p, kind, np.scale, np.octaves, np.roughness, np.distortion);
        EXPECT_TRUE(in_unit_range(r.fac) && in_unit_range(r.color.r) && in_unit_range(r.color.g) &&
                    in_unit_range(r.color.b))
            << int(kind) << " " << p.x << " scale " << np.scale;
      }
    }
}

TEST(ProceduralNoise, ZeroScaleEvaluatesAtOrigin) {
  for (NoiseKind kind : kKinds)
    for (float scale : {0.f, -2.f}) {
      const NoiseResult a = noise_texture({3.7f, -1.2f, 8.f}, kind, scale, 5, 0.5f, 0.4f);
      const NoiseResult b = noise_texture(Vec3(0.f), kind, 1.f, 5, 0.5f, 0.4f);
      EXPECT_EQ(a.fac, b.fac);
      EXPECT_EQ(a.color, b.color);
    }
}

// ---- Voronoi ------------------------------------------------------------------------------------

TEST(ProceduralVoronoi, RegularGridAtCellCentres) {
  // Randomness 0: feature points at cell centres, so p = (cell + 0.5) / scale sits on one.
  const float scale = 4.f;  // a power of two keeps p * scale exact
  for (const Vec3 cell : {Vec3(0.f), Vec3(3.f, -2.f, 7.f), Vec3(-10.f, 5.f, -1.f)}) {
    const Vec3 p = (cell + 0.5f) / scale;
    const VoronoiResult r = voronoi_texture(p, scale, 0.f);
    EXPECT_NEAR(r.distance, 0.f, 1e-6f);
    expect_color_near(r.position, p, 1e-6f);
  }
}

TEST(ProceduralVoronoi, DistanceBounds) {
  // Scaled space has unit cells. With randomness 0 the features form a unit grid of cell centres, and
  // the farthest any point gets from its own cell's centre is half the cube diagonal, sqrt(3)/2 (at a
  // corner), so F1 <= sqrt(3)/2 (sqrt(3)/(2 scale) in unscaled units). With any randomness in [0, 1] a
  // feature stays inside its own cell, so F1 <= sqrt(3), the full diagonal.
  Pcg32 rng(31);
  float worst_regular = 0.f;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 p = random_point(rng, 10.f);
    for (float scale : {0.5f, 1.f, 3.f, 17.f}) {
      const VoronoiResult regular = voronoi_texture(p, scale, 0.f);
      worst_regular = std::max(worst_regular, regular.distance);
      EXPECT_LE(glm::length(p - regular.position), std::sqrt(3.f) / (2.f * scale) + 1e-4f);
      const VoronoiResult jittered = voronoi_texture(p, scale, 1.f);
      EXPECT_LE(jittered.distance, std::sqrt(3.f) + 1e-5f);
      // distance is measured in scaled space, position is unscaled.
      EXPECT_NEAR(jittered.distance, glm::length(p - jittered.position) * scale, 1e-3f);
    }
  }
  EXPECT_LE(worst_regular, std::sqrt(3.f) / 2.f + 1e-5f);
  EXPECT_GT(worst_regular, 0.7f);  // 5000 points get close to the corners
  // Exactly at a cell corner: equidistant from eight centres.
  EXPECT_NEAR(voronoi_texture(Vec3(1.f), 1.f, 0.f).distance, std::sqrt(3.f) / 2.f, 1e-6f);
}

TEST(ProceduralVoronoi, ColourConstantNearFeaturePoint) {
  Pcg32 rng(32);
  for (int i = 0; i < 200; ++i) {
    const float scale = 2.5f;
    const VoronoiResult r = voronoi_texture(random_point(rng, 20.f), scale, 1.f);
    const VoronoiResult at = voronoi_texture(r.position, scale, 1.f);
    EXPECT_NEAR(at.distance, 0.f, 1e-4f);
    for (int k = 0; k < 10; ++k) {
      // Within 1e-3 scaled units of the feature: another feature that close is vanishingly unlikely.
      const VoronoiResult nearby =
          voronoi_texture(r.position + (1e-3f / scale) * random_direction(rng), scale, 1.f);
      EXPECT_EQ(nearby.color, r.color);
      expect_color_near(nearby.position, r.position, 1e-5f);
    }
    EXPECT_TRUE(in_unit_range(r.color.r) && in_unit_range(r.color.g) && in_unit_range(r.color.b));
  }
}

TEST(ProceduralVoronoi, NeighbouringCellsDiffer) {
  // Randomness 0 at two adjacent cell centres: different cells, different hash colours.
  const VoronoiResult a = voronoi_texture({0.5f, 0.5f, 0.5f}, 1.f, 0.f);
  const VoronoiResult b = voronoi_texture({1.5f, 0.5f, 0.5f}, 1.f, 0.f);
  EXPECT_NE(a.color, b.color);
}

TEST(ProceduralVoronoi, FiniteEverywhere) {
  const Vec3 points[] = {Vec3(1e6f),   Vec3(-1e6f, 1e6f + 0.25f, 3.f), Vec3(1e30f),
                         Vec3(-kHuge), Vec3(kHuge, 0.f, -kHuge),       Vec3(kNaN)};
  for (const Vec3& p : points)
    for (float scale : {1.f, 5.f, 0.f, -1.f, 1e-35f, 1e-20f, 1e30f, kHuge, kNaN})
      for (float randomness : {0.f, 0.5f, 1.f, -1.f, 3.f, kNaN}) {
        const VoronoiResult r = voronoi_texture(p, scale, randomness);
        EXPECT_TRUE(std::isfinite(r.distance) && is_finite(r.color) && is_finite(r.position))
            << p.x << " scale " << scale << " randomness " << randomness;
        EXPECT_LE(r.distance, std::sqrt(3.f) + 1e-5f);
      }
  // Coordinates around 1e6 keep their fractional part: regular-grid bound still holds.
  EXPECT_LE(voronoi_texture({1e6f + 0.25f, -1e6f, 0.5f}, 1.f, 0.f).distance, std::sqrt(3.f) / 2.f + 1e-5f);
}

TEST(ProceduralVoronoi, ZeroScaleEvaluatesAtOrigin) {
  const VoronoiResult origin = voronoi_texture(Vec3(0.f), 1.f, 0.7f);
  for (float scale : {0.f, -3.f}) {
    const VoronoiResult r = voronoi_texture({5.f, -2.f, 9.f}, scale, 0.7f);
    EXPECT_EQ(r.distance, origin.distance);
    EXPECT_EQ(r.color, origin.color);
    EXPECT_EQ(r.position, Vec3(0.f));  // no meaningful unscaled position when everything maps to the origin
  }
}

}  // namespace
}  // namespace inkray
