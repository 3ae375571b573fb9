// orient_chain and measure_curvature: a chain's stable start and direction, and its
// turning per pixel, positive clockwise on screen (y down).
#include "core/npr/lines/chain_shape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace inkray {
namespace {

Chain chain_through(std::initializer_list<Vec2> points, bool closed) {
  Chain c;
  c.closed = closed;
  for (const Vec2& p : points) c.points.push_back({p});
  return c;
}

TEST(ChainShape, AnOpenChainStartsAtItsEndWithTheSmallerX) {
  Chain c = chain_through({{5.f, 1.f}, {3.f, 2.f}, {1.f, 4.f}}, false);
  c.ends_at_crossing = {true, false};
  orient_chain(c);
  EXPECT_EQ(c.points.front().p, Vec2(1.f, 4.f));
  EXPECT_EQ(c.points.back().p, Vec2(5.f, 1.f));
  EXPECT_FALSE(c.ends_at_crossing[0]);  // the ends keep what they meet
  EXPECT_TRUE(c.ends_at_crossing[1]);
  // Ends at the same x: the smaller y first.
  Chain upright = chain_through({{2.f, 9.f}, {3.f, 5.f}, {2.f, 1.f}}, false);
  orient_chain(upright);
  EXPECT_EQ(upright.points.front().p, Vec2(2.f, 1.f));
}

TEST(ChainShape, ALoopStartsAtItsTopRunningClockwiseOnScreen) {
  // Counter-clockwise on screen (y down): right, then up, then left, then down.
  Chain c = chain_through({{0.f, 10.f}, {10.f, 10.f}, {10.f, 0.f}, {0.f, 0.f}}, true);
  orient_chain(c);
  ASSERT_EQ(c.points.size(), 4u);
  EXPECT_EQ(c.points[0].p, Vec2(0.f, 0.f)) << "the topmost point, the leftmost of those";
  EXPECT_EQ(c.points[1].p, Vec2(10.f, 0.f)) << "then right along the top: clockwise";
  EXPECT_EQ(c.points[2].p, Vec2(10.f, 10.f));
}

TEST(ChainShape, ACircleTurnsByOneOverItsRadius) {
  constexpr float kRadius = 20.f;
  constexpr int kPoints = 120;
  Chain c;
  c.closed = true;
  // Clockwise on screen with y down: the angle grows from +x towards +y.
  for (int i = 0; i < kPoints; ++i) {
    const float a = 2.f * std::numbers::pi_v<float> * float(i) / kPoints;
    c.points.push_back({Vec2(kRadius * std::cos(a), kRadius * std::sin(a))});
  }
  measure_curvature(c);
  for (const ChainPoint& q : c.points) EXPECT_NEAR(q.curvature, 1.f / kRadius, 1e-3f);
  // Run the other way, it turns the other way; an open chain's ends copy their neighbours.
  Chain open = c;
  open.closed = false;
  std::reverse(open.points.begin(), open.points.end());
  measure_curvature(open);
  EXPECT_NEAR(open.points[5].curvature, -1.f / kRadius, 1e-3f);
  EXPECT_EQ(open.points.front().curvature, open.points[1].curvature);
  EXPECT_EQ(open.points.back().curvature, open.points[kPoints - 2].curvature);
}

}  // namespace
}  // namespace inkray
