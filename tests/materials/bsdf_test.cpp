// BSDF tests: chi-square fits of every non-delta sampler against its pdf,
// sample/eval agreement, energy conservation, white furnace, reciprocity and
// the geometry of the delta lobes.
#include "core/materials/bsdf.h"

#include "core/materials/fresnel.h"
#include "core/sampling/warp.h"
#include "tests/support/chi_square.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

namespace inkray {
namespace {

namespace ts = test_support;

// A direction with the given cosine to +z (negative: below the surface), at an
// azimuth that is not aligned with the histogram's phi bins.
Vec3 dir_with_cos(float cos_theta, float phi = 0.7f) {
  const float s = safe_sqrt(1.f - sqr(cos_theta));
  return {s * std::cos(phi), s * std::sin(phi), cos_theta};
}

double relative_difference(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale > 0.0 ? std::abs(a - b) / scale : 0.0;
}

// The weight with the radiance-mode 1/etap^2 of a transmission undone: the
// fraction of *flux* carried, which is what energy conservation bounds (going
// out of glass, radiance itself grows by etap^2 and may exceed 1).
float energy_weight(const BsdfSample& s) {
  const float w = luminance(s.f) * std::abs(s.wi.z) / s.pdf;
  return s.is_transmission ? w * sqr(s.eta) : w;
}

// Mean energy weight over n stratified samples (failed samples count as 0).
double mean_energy(const Bsdf& bsdf, const Vec3& wo, int n, uint64_t seed) {
  Pcg32 rng(seed);
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const float u_lobe = (float(k) + rng.next_float()) / float(n);
    if (const auto s = bsdf_sample(bsdf, wo, u_lobe, Vec2(rng.next_float(), rng.next_float())))
      sum += energy_weight(*s);
  }
  return sum / n;
}

std::string format_float(float v) {
  std::string s = std::to_string(int(std::lround(v * 100.f)));
  return std::string(s.size() < 3 ? 3 - s.size() : 0, '0') + s;  // 0.05 -> "005"
}

// ---- Cases shared by the chi-square and energy tests, all with white parameters.

struct NamedBsdf {
  std::string name;
  Bsdf bsdf;
  bool flip_wo = false;  // test from below the surface (inside the dielectric)
};

std::vector<NamedBsdf> rough_bsdfs() {
  std::vector<NamedBsdf> out{{"lambert", LambertBsdf{Color(1.f)}}};
  for (const float alpha : {0.05f, 0.2f, 0.5f, 1.0f})
    out.push_back({"conductor_a" + format_float(alpha), ConductorBsdf{Color(1.f), alpha}});
  for (const float alpha : {0.1f, 0.3f, 0.8f}) {
    const std::string a = "_a" + format_float(alpha);
    out.push_back({"glass_out" + a, DielectricBsdf{1.5f, alpha, Color(1.f)}});
    out.push_back({"glass_in" + a, DielectricBsdf{1.5f, alpha, Color(1.f)}, true});
    out.push_back({"inv_glass_out" + a, DielectricBsdf{1.f / 1.5f, alpha, Color(1.f)}});
  }
  return out;
}

struct SamplingCase {
  std::string name;
  Bsdf bsdf;
  Vec3 wo;
  uint64_t seed = 0;  // distinct per case, so that the tests are independent
};

std::vector<SamplingCase> sampling_cases() {
  std::vector<SamplingCase> out;
  for (const NamedBsdf& b : rough_bsdfs()) {
    const bool lambert = std::holds_alternative<LambertBsdf>(b.bsdf);
    // Lambert's sampler ignores wo but for its side, so both sides suffice.
    const std::vector<float> cosines =
        lambert ? std::vector<float>{0.5f, -0.1f} : std::vector{1.f, 0.6f, 0.1f};
    for (const float c : cosines) {
      const float cos_o = b.flip_wo ? -c : c;
      out.push_back({b.name + "_cos" + (cos_o < 0.f ? "m" : "") + format_float(std::abs(cos_o)), b.bsdf,
                     dir_with_cos(cos_o), 1000 + out.size()});
    }
  }
  return out;
}

// ---- Chi-square fits. Each case draws 1M samples into a 40 x 80 grid over
// (cos theta, phi) and compares with the integrated pdf.

constexpr long kChiSquareSamples = 1'000'000;
constexpr double kFamilySignificance = 0.01;

// The p-value routine itself, against tabulated 5% critical values.
TEST(BsdfChiSquareHelper, PValueMatchesTables) {
  EXPECT_NEAR(ts::chi_square_p_value(3.841, 1), 0.05, 1e-4);
  EXPECT_NEAR(ts::chi_square_p_value(18.307, 10), 0.05, 1e-4);
  EXPECT_NEAR(ts::chi_square_p_value(124.342, 100), 0.05, 1e-4);
  EXPECT_NEAR(ts::chi_square_p_value(1074.679, 1000), 0.05, 1e-4);
  EXPECT_NEAR(ts::chi_square_p_value(2.0, 2), std::exp(-1.0), 1e-12);  // dof 2: Q = exp(-x/2)
  EXPECT_NEAR(ts::sidak_significance(0.01, 1), 0.01, 1e-15);
}

class BsdfChiSquare : public ::testing::TestWithParam<SamplingCase> {};

// Sample attempts, checking on the way that each sample's f and pdf are those
// that eval and pdf give for its direction (so the weight is f |cos| / pdf).
// Near the critical angle the Fresnel transmittance has infinite slope, so the
// float rounding between the sampled half vector and the one eval rebuilds
// from (wo, wi) can reach ~1e-3 there: a few such samples per million are
// allowed up to 1e-2.
constexpr double kAgreement = 1e-3;
constexpr double kIllConditionedAgreement = 1e-2;
constexpr double kIllConditionedShare = 1e-5;

struct CheckedSampler {
  const SamplingCase& c;
  long mismatches = 0;  // samples beyond kAgreement
  double worst = 0.0;

  std::optional<Vec3> operator()(Pcg32& rng) {
    const float u_lobe = rng.next_float();
    const auto s = bsdf_sample(c.bsdf, c.wo, u_lobe, Vec2(rng.next_float(), rng.next_float()));
    if (!s) return std::nullopt;
    double err = s->is_delta ? 1.0 : relative_difference(s->pdf, bsdf_pdf(c.bsdf, c.wo, s->wi));
    const Color f = bsdf_eval(c.bsdf, c.wo, s->wi);
    for (int k = 0; k < 3; ++k) err = std::max(err, relative_difference(s->f[k], f[k]));
    worst = std::max(worst, err);
    if (err > kAgreement) ++mismatches;
    return s->wi;
  }
};

TEST_P(BsdfChiSquare, SamplingMatchesPdf) {
  const SamplingCase& c = GetParam();
  const ts::SphereGrid grid{40, 80};
  CheckedSampler sampler{c};
  const ts::Histogram hist = ts::sample_histogram(grid, kChiSquareSamples, c.seed, sampler);
  EXPECT_LE(sampler.mismatches, kIllConditionedShare * kChiSquareSamples);
  EXPECT_LE(sampler.worst, kIllConditionedAgreement);

  const auto expected = ts::expected_counts(grid, kChiSquareSamples,
                                            [&](const Vec3& wi) { return bsdf_pdf(c.bsdf, c.wo, wi); });
  // The pdf is of the samples that succeed, so it integrates to their share.
  const double integral = std::accumulate(expected.begin(), expected.end(), 0.0) / kChiSquareSamples;
  const double accepted = 1.0 - double(hist.rejected) / kChiSquareSamples;
  EXPECT_LE(integral, 1.001);
  EXPECT_NEAR(accepted, integral, 5.0 * std::sqrt(0.25 / kChiSquareSamples) + 1e-3);

  const ts::ChiSquareResult r = ts::chi_square(hist.counts, expected);
  const double significance = ts::sidak_significance(kFamilySignificance, int(sampling_cases().size()));
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_GE(r.p_value, significance) << "chi2 = " << r.statistic << ", dof = " << r.dof
                                     << ", pooled cells = " << r.pooled_cells;
}

INSTANTIATE_TEST_SUITE_P(Bsdf, BsdfChiSquare, ::testing::ValuesIn(sampling_cases()),
                         [](const auto& param_info) { return param_info.param.name; });

// ---- Energy: no BSDF may scatter more flux than arrives.

TEST(BsdfEnergy, MeanWeightAtMostOne) {
  for (const NamedBsdf& b : rough_bsdfs()) {
    for (int k = 0; k < 12; ++k) {
      const float c = 0.02f + 0.98f * float(k) / 11.f;
      for (const float cos_o : {c, -c}) {
        const double e = mean_energy(b.bsdf, dir_with_cos(cos_o), 40'000, 3 + k);
        EXPECT_LE(e, 1.01) << b.name << " at cos " << cos_o;
      }
    }
  }
}

// ---- White furnace.

TEST(BsdfWhiteFurnace, LambertReturnsAlbedo) {
  for (const float c : {1.f, 0.5f, 0.05f, -0.7f})
    EXPECT_NEAR(mean_energy(LambertBsdf{Color(1.f)}, dir_with_cos(c), 20'000, 5), 1.0, 0.005) << c;
}

TEST(BsdfWhiteFurnace, SmoothMirrorIsExact) {
  const Bsdf mirror = ConductorBsdf{Color(1.f), 0.f};
  for (const float c : {1.f, 0.5f, 0.01f, -0.3f}) {
    const auto s = bsdf_sample(mirror, dir_with_cos(c), 0.5f, Vec2(0.3f, 0.8f));
    ASSERT_TRUE(s);
    EXPECT_FLOAT_EQ(s->f.x * std::abs(s->wi.z) / s->pdf, 1.f) << c;
  }
}

// Asserts R + T = 1 for the smooth dielectric: every sampled weight, with the
// radiance-mode 1/eta^2 of transmission multiplied back, is 1, and the share
// of reflections is the Fresnel reflectance.
TEST(BsdfWhiteFurnace, SmoothDielectricReflectPlusTransmitIsOne) {
  constexpr int kSamples = 20'000;
  for (const float eta : {1.1f, 1.33f, 1.5f, 2.4f, 1.f / 1.5f}) {
    const Bsdf glass = DielectricBsdf{eta, 0.f, Color(1.f)};
    for (const float c : {1.f, 0.7f, 0.2f, -0.9f, -0.6f, -0.3f}) {
      const Vec3 wo = dir_with_cos(c);
      EXPECT_NEAR(mean_energy(glass, wo, kSamples, 9), 1.0, 0.005) << "eta " << eta << " cos " << c;
      int reflected = 0;
      for (int k = 0; k < kSamples; ++k)
        reflected += !bsdf_sample(glass, wo, (k + 0.5f) / kSamples, Vec2(0.5f))->is_transmission;
      EXPECT_NEAR(double(reflected) / kSamples, fresnel_dielectric(c, eta), 1.0 / kSamples + 1e-6);
    }
  }
}

// Single-scattering GGX ignores light that bounces between microfacets, so
// rough surfaces lose energy (up to ~40% at alpha 1); only "no gain" is asserted.
TEST(BsdfWhiteFurnace, RoughGgxAlbedo) {
  std::printf(
      "  GGX directional albedo (flux, white): alpha | conductor cos 1, 0.5, 0.1 | "
      "glass(out) cos 1, 0.5, 0.1 | glass(in) cos 1, 0.5, 0.1\n");
  for (const float alpha : {0.01f, 0.05f, 0.1f, 0.2f, 0.3f, 0.5f, 0.8f, 1.0f}) {
    std::printf("  %5.2f |", alpha);
    const Bsdf metal = ConductorBsdf{Color(1.f), alpha};
    const Bsdf glass = DielectricBsdf{1.5f, alpha, Color(1.f)};
    for (const auto& [bsdf, sign] : {std::pair{metal, 1.f}, std::pair{glass, 1.f}, std::pair{glass, -1.f}}) {
      for (const float c : {1.f, 0.5f, 0.1f}) {
        const double e = mean_energy(bsdf, dir_with_cos(sign * c), 100'000, 11);
        EXPECT_LE(e, 1.01) << "alpha " << alpha << " cos " << sign * c;
        std::printf(" %.4f", e);
      }
      std::printf(" |");
    }
    std::printf("\n");
  }
}

// ---- Reciprocity.

template <class Check>
void for_random_pairs(int n, Check&& check) {
  Pcg32 rng(23);
  for (int k = 0; k < n; ++k) {
    const Vec3 a = sample_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
    const Vec3 b = sample_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
    check(a, b);
  }
}

TEST(BsdfReciprocity, Lambert) {
  const Bsdf bsdf = LambertBsdf{Color(0.3f, 0.6f, 0.9f)};
  for_random_pairs(
      1000, [&](const Vec3& a, const Vec3& b) { EXPECT_EQ(bsdf_eval(bsdf, a, b), bsdf_eval(bsdf, b, a)); });
}

TEST(BsdfReciprocity, RoughConductor) {
  for (const float alpha : {0.05f, 0.3f, 1.f}) {
    const Bsdf bsdf = ConductorBsdf{Color(0.9f, 0.6f, 0.2f), alpha};
    for_random_pairs(1000, [&](const Vec3& a, const Vec3& b) {
      const Color fab = bsdf_eval(bsdf, a, b), fba = bsdf_eval(bsdf, b, a);
      for (int k = 0; k < 3; ++k) EXPECT_LE(relative_difference(fab[k], fba[k]), 1e-5) << alpha;
    });
  }
}

// Radiance-mode BTDFs are reciprocal up to the squared indices of the two
// sides (Veach 1997, sec. 5.2): f(wo, wi) / n(wo)^2 = f(wi, wo) / n(wi)^2,
// where n(w) is the index of the medium w points into. Pairs whose outside
// direction grazes their microfacet are skipped: the inside one is then at the
// critical angle, where Fresnel has infinite slope and rounding decides.
TEST(BsdfReciprocity, RoughDielectricGeneralised) {
  const float eta = 1.5f;
  const Bsdf bsdf = DielectricBsdf{eta, 0.3f, Color(1.f)};
  const auto n_of = [&](const Vec3& w) { return w.z > 0.f ? 1.f : eta; };
  int checked = 0;
  for_random_pairs(1000, [&](const Vec3& a, const Vec3& b) {
    const Vec3 outside = a.z > 0.f ? a : b;
    const Vec3 wm = glm::normalize(a * n_of(a) + b * n_of(b));
    if (a.z * b.z < 0.f && std::abs(glm::dot(outside, wm)) < 0.03f) return;
    const double lhs = bsdf_eval(bsdf, a, b).x / sqr(n_of(a));
    const double rhs = bsdf_eval(bsdf, b, a).x / sqr(n_of(b));
    EXPECT_LE(relative_difference(lhs, rhs), 1e-4);
    ++checked;
  });
  EXPECT_GT(checked, 950);
}

// ---- Delta lobes and degenerate input.

TEST(BsdfDelta, MirrorReflects) {
  const Bsdf mirror = ConductorBsdf{Color(0.9f), 0.f};
  const Vec3 wo = glm::normalize(Vec3(0.3f, -0.5f, 0.7f));
  const auto s = bsdf_sample(mirror, wo, 0.5f, Vec2(0.2f, 0.9f));
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->is_delta);
  EXPECT_FALSE(s->is_transmission);
  EXPECT_EQ(s->wi, Vec3(-wo.x, -wo.y, wo.z));
  EXPECT_FLOAT_EQ(s->pdf, 1.f);
}

TEST(BsdfDelta, SmoothDielectricObeysSnell) {
  for (const float eta : {1.5f, 1.f / 1.33f}) {
    const Bsdf glass = DielectricBsdf{eta, 0.f, Color(1.f)};
    for (const float c : {0.9f, 0.7f, -0.95f}) {  // all below the critical angle
      const Vec3 wo = dir_with_cos(c);
      const auto s = bsdf_sample(glass, wo, kOneMinusEpsilon, Vec2(0.5f));
      ASSERT_TRUE(s && s->is_transmission) << eta << " " << c;
      const float n_o = c > 0.f ? 1.f : eta, n_i = c > 0.f ? eta : 1.f;
      const float sin_o = std::hypot(wo.x, wo.y), sin_i = std::hypot(s->wi.x, s->wi.y);
      EXPECT_NEAR(n_o * sin_o, n_i * sin_i, 1e-5f);
      EXPECT_LT(s->wi.z * wo.z, 0.f);
      EXPECT_NEAR(glm::dot(Vec2(s->wi), Vec2(wo)), -sin_i * sin_o, 1e-5f);  // stays in the plane of incidence
      EXPECT_NEAR(s->eta, n_i / n_o, 1e-6f);
      EXPECT_NEAR(s->pdf, 1.f - fresnel_dielectric(c, eta), 1e-6f);
    }
  }
}

TEST(BsdfDelta, TotalInternalReflectionOnlyReflects) {
  const Bsdf glass = DielectricBsdf{1.5f, 0.f, Color(1.f)};
  const float critical_cos = std::sqrt(1.f - sqr(1.f / 1.5f));
  const Vec3 wo = dir_with_cos(-0.9f * critical_cos);  // inside, beyond the critical angle
  for (const float u : {0.f, 0.5f, kOneMinusEpsilon}) {
    const auto s = bsdf_sample(glass, wo, u, Vec2(0.5f));
    ASSERT_TRUE(s);
    EXPECT_FALSE(s->is_transmission);
    EXPECT_EQ(s->wi, Vec3(-wo.x, -wo.y, wo.z));
    EXPECT_FLOAT_EQ(s->pdf, 1.f);
  }
}

TEST(BsdfDelta, TransparentPassesStraightThrough) {
  const Bsdf clear = TransparentBsdf{Color(0.2f, 0.5f, 1.f)};
  for (const float c : {0.8f, -0.3f}) {
    const Vec3 wo = dir_with_cos(c);
    const auto s = bsdf_sample(clear, wo, 0.3f, Vec2(0.1f));
    ASSERT_TRUE(s);
    EXPECT_EQ(s->wi, -wo);
    EXPECT_TRUE(s->is_delta && s->is_transmission);
    EXPECT_EQ(s->eta, 1.f);
    const Color w = s->f * std::abs(s->wi.z) / s->pdf;
    EXPECT_NEAR(w.r, 0.2f, 1e-6f);
    EXPECT_NEAR(w.b, 1.f, 1e-6f);
  }
}

TEST(BsdfDelta, EvalAndPdfOfDeltaAreZero) {
  const Vec3 wo = dir_with_cos(0.6f);
  for (const Bsdf& b : {Bsdf{ConductorBsdf{Color(1.f), 0.f}}, Bsdf{DielectricBsdf{1.5f, 0.f, Color(1.f)}},
                        Bsdf{TransparentBsdf{}}}) {
    EXPECT_TRUE(bsdf_is_delta(b));
    const auto s = bsdf_sample(b, wo, 0.1f, Vec2(0.5f));
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->is_delta);
    EXPECT_EQ(bsdf_eval(b, wo, s->wi), Color(0.f));
    EXPECT_EQ(bsdf_pdf(b, wo, s->wi), 0.f);
  }
  EXPECT_FALSE(bsdf_is_delta(LambertBsdf{}));
  EXPECT_FALSE(bsdf_is_delta(ConductorBsdf{Color(1.f), 0.1f}));
  EXPECT_FALSE(bsdf_is_delta(DielectricBsdf{1.5f, 0.1f, Color(1.f)}));
  EXPECT_TRUE(bsdf_is_delta(DielectricBsdf{1.f, 0.5f, Color(1.f)}));  // index-matched: no bending
}

TEST(BsdfDegenerate, TangentWoGivesNoSample) {
  const Vec3 wo(1.f, 0.f, 0.f);
  for (const Bsdf& b : {Bsdf{LambertBsdf{}}, Bsdf{ConductorBsdf{Color(1.f), 0.3f}},
                        Bsdf{ConductorBsdf{Color(1.f), 0.f}}, Bsdf{DielectricBsdf{1.5f, 0.3f, Color(1.f)}},
                        Bsdf{DielectricBsdf{1.5f, 0.f, Color(1.f)}}, Bsdf{TransparentBsdf{}}})
    EXPECT_FALSE(bsdf_sample(b, wo, 0.5f, Vec2(0.3f, 0.6f)));
}

TEST(BsdfLambert, SamplesTheSideOfWo) {
  const Bsdf bsdf = LambertBsdf{};
  Pcg32 rng(5);
  for (const float c : {0.4f, -0.4f}) {
    for (int k = 0; k < 100; ++k) {
      const auto s = bsdf_sample(bsdf, dir_with_cos(c), 0.f, Vec2(rng.next_float(), rng.next_float()));
      ASSERT_TRUE(s);
      EXPECT_GT(s->wi.z * c, 0.f);
    }
  }
}

TEST(BsdfDielectric, TintMultipliesTransmissionOnly) {
  const Vec3 wo = dir_with_cos(0.8f);
  const Color tint(0.25f, 0.5f, 1.f);
  for (const float alpha : {0.f, 0.3f}) {
    const Bsdf white = DielectricBsdf{1.5f, alpha, Color(1.f)}, tinted = DielectricBsdf{1.5f, alpha, tint};
    for (const float u_lobe : {0.01f, 0.99f}) {
      const auto a = bsdf_sample(white, wo, u_lobe, Vec2(0.3f, 0.4f));
      const auto b = bsdf_sample(tinted, wo, u_lobe, Vec2(0.3f, 0.4f));
      ASSERT_TRUE(a && b);
      const Color expect = a->is_transmission ? a->f * tint : a->f;
      for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(b->f[k], expect[k]);
    }
  }
}

}  // namespace
}  // namespace inkray
