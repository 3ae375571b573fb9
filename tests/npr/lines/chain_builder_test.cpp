// Chains of synthetic line images: the count, length, order and labels of what
// build_chains traces from coverage drawn at known distances from known shapes.
#include "core/npr/lines/chain_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace inkray {
namespace {

// A line image of one type: opacity falls from 1 on the shape to 0 at `half_width`
// + 1 pixels, as a resolved line of that width does.
ChainSource line_image(int w, int h, const std::function<float(Vec2)>& distance, float half_width = 1.f,
                       LineType type = LineType::silhouette) {
  ChainSource s;
  s.width = w, s.height = h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float d = distance(Vec2(float(x) + 0.5f, float(y) + 0.5f));
      const float o = std::clamp(half_width + 0.5f - d, 0.f, 1.f);
      if (o <= 0.f) continue;
      s.pixels.push_back(uint32_t(y * w + x));
      std::array<float, kLineTypeCount> a{};
      a[size_t(type)] = o;
      s.opacity.push_back(a);
    }
  return s;
}

float segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.f, 1.f);
  return glm::length(p - (a + t * ab));
}

TEST(ChainBuilder, CircleIsOneClosedChainOfItsCircumference) {
  const Vec2 c(64.f, 64.f);
  const float r = 40.f;
  for (float half : {0.6f, 1.f, 2.f}) {
    const auto chains = build_chains(line_image(
        128, 128, [&](Vec2 p) { return std::abs(glm::length(p - c) - r); }, half));
    ASSERT_EQ(chains.size(), 1u) << "half width " << half;
    EXPECT_TRUE(chains[0].closed);
    EXPECT_NEAR(chain_length(chains[0]), 2.f * float(M_PI) * r, 0.02f * 2.f * float(M_PI) * r);
    float worst = 0.f;  // the fitted chain follows the circle
    for (const ChainPoint& q : chains[0].points) worst = std::max(worst, std::abs(glm::length(q.p - c) - r));
    EXPECT_LT(worst, 0.8f) << "half width " << half;
    // Clockwise on screen from the top.
    EXPECT_NEAR(chains[0].points[0].p.y, c.y - r, 1.f);
    EXPECT_GT(chains[0].points[5].p.x, chains[0].points[0].p.x);
    // A circle turns by 1/r everywhere, clockwise (positive with y down).
    float mean = 0.f;
    for (const ChainPoint& q : chains[0].points) mean += q.curvature;
    EXPECT_NEAR(mean / float(chains[0].points.size()), 1.f / r, 0.2f / r);
  }
}

TEST(ChainBuilder, CrossIsTwoStraightChains) {
  const Vec2 a0(10, 64), a1(118, 64), b0(64, 10), b1(64, 118);
  const auto chains = build_chains(line_image(
      128, 128, [&](Vec2 p) { return std::min(segment_distance(p, a0, a1), segment_distance(p, b0, b1)); }));
  ASSERT_EQ(chains.size(), 2u);
  for (const Chain& c : chains) {
    EXPECT_FALSE(c.closed);
    EXPECT_NEAR(chain_length(c), 108.f, 1.5f);
    const Vec2 d = c.points.back().p - c.points.front().p;
    EXPECT_LT(std::min(std::abs(d.x), std::abs(d.y)), 1.5f);  // straight through the crossing
  }
}

TEST(ChainBuilder, TIsABarAndAStem) {
  const Vec2 a0(10, 30), a1(118, 30), s0(64, 30), s1(64, 118);
  const auto chains = build_chains(line_image(
      128, 128, [&](Vec2 p) { return std::min(segment_distance(p, a0, a1), segment_distance(p, s0, s1)); }));
  ASSERT_EQ(chains.size(), 2u);
  std::vector<float> lengths{chain_length(chains[0]), chain_length(chains[1])};
  std::sort(lengths.begin(), lengths.end());
  EXPECT_NEAR(lengths[0], 88.f, 3.f);
  EXPECT_NEAR(lengths[1], 108.f, 3.f);
  // The stem stops at the bar, its top end in the crossing; the bar's ends are free.
  const Chain& stem = chain_length(chains[0]) < chain_length(chains[1]) ? chains[0] : chains[1];
  const Chain& bar = &stem == &chains[0] ? chains[1] : chains[0];
  const bool top_first = stem.points.front().p.y < stem.points.back().p.y;
  EXPECT_TRUE(stem.ends_at_crossing[top_first ? 0 : 1]);
  EXPECT_FALSE(stem.ends_at_crossing[top_first ? 1 : 0]);
  EXPECT_FALSE(bar.ends_at_crossing[0] || bar.ends_at_crossing[1]);
}

TEST(ChainBuilder, DashedLineIsOneChainPerDashInOrder) {
  // Eight dashes of 10 pixels with gaps of 6, along a slanted line.
  const Vec2 dir = glm::normalize(Vec2(1.f, 0.3f));
  const auto chains = build_chains(line_image(160, 80, [&](Vec2 p) {
    float d = 1e9f;
    for (int i = 0; i < 8; ++i) {
      const Vec2 a = Vec2(8, 10) + dir * float(16 * i);
      d = std::min(d, segment_distance(p, a, a + dir * 10.f));
    }
    return d;
  }));
  ASSERT_EQ(chains.size(), 8u);
  for (const Chain& c : chains) {
    EXPECT_NEAR(chain_length(c), 10.f, 1.f) << c.points.front().p.x << "," << c.points.front().p.y << " "
                                            << c.points.back().p.x << "," << c.points.back().p.y;
    EXPECT_LT(c.points.front().p.x, c.points.back().p.x);  // each starts at its left end
  }
}

TEST(ChainBuilder, StartsAtTheSameEndWhateverTheScan) {
  const Vec2 a(100, 20), b(20, 100);
  const auto chains = build_chains(line_image(128, 128, [&](Vec2 p) { return segment_distance(p, a, b); }));
  ASSERT_EQ(chains.size(), 1u);
  EXPECT_NEAR(chains[0].points.front().p.x, 20.f, 1.5f);
  EXPECT_NEAR(chains[0].points.back().p.x, 100.f, 1.5f);
}

TEST(ChainBuilder, TypesStayApartAndPointsCarryTheSurface) {
  ChainSource s = line_image(
      64, 64, [](Vec2 p) { return std::abs(p.y - 20.f); }, 1.f, LineType::crease);
  const ChainSource other = line_image(
      64, 64, [](Vec2 p) { return std::abs(p.y - 44.f); }, 1.f, LineType::depth);
  s.pixels.insert(s.pixels.end(), other.pixels.begin(), other.pixels.end());
  s.opacity.insert(s.opacity.end(), other.opacity.begin(), other.opacity.end());
  s.depth.assign(64 * 64, 0.f);
  s.object.assign(64 * 64, -1);
  s.material.assign(64 * 64, -1);
  s.path.assign(64 * 64, uint8_t(LinePath::direct));
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const size_t i = size_t(y * 64 + x);
      // The upper line lies on object 3 seen in a mirror, 5 units away; below the
      // lower one object 7 is nearer than the background above it.
      if (y < 32)
        s.depth[i] = 5.f, s.object[i] = 3, s.material[i] = 1, s.path[i] = uint8_t(LinePath::reflected);
      if (y >= 45) s.depth[i] = 2.f, s.object[i] = 7, s.material[i] = 2;
    }
  const auto chains = build_chains(s);
  ASSERT_EQ(chains.size(), 2u);
  EXPECT_EQ(chains[0].type, LineType::depth);  // LineType order
  EXPECT_EQ(chains[0].object, 7);
  EXPECT_EQ(chains[0].material, 2);
  EXPECT_FLOAT_EQ(chains[0].points[10].depth, 2.f);
  EXPECT_EQ(chains[0].path, LinePath::direct);
  EXPECT_EQ(chains[1].type, LineType::crease);
  EXPECT_EQ(chains[1].object, 3);
  EXPECT_EQ(chains[1].path, LinePath::reflected);
  EXPECT_NEAR(chains[1].points[10].opacity, 1.f, 1e-6f);
}

TEST(ChainBuilder, SpecksAndEmptyImagesGiveNothing) {
  EXPECT_TRUE(build_chains(ChainSource{}).empty());
  const auto specks = build_chains(line_image(
      32, 32, [](Vec2 p) { return glm::length(p - Vec2(16.f)); }, 0.6f));
  EXPECT_TRUE(specks.empty());
  // Faint coverage below the threshold is no line.
  ChainSource faint = line_image(64, 64, [](Vec2 p) { return std::abs(p.y - 20.f); });
  for (auto& o : faint.opacity) o[size_t(LineType::silhouette)] *= 0.1f;
  EXPECT_TRUE(build_chains(faint).empty());
}

}  // namespace
}  // namespace inkray
