// Chains styled into strokes: selection, corners, short pieces, scale, taper,
// overshoot, jitter (and its stability), passes, modulation and dashes.
#include "core/npr/lines/line_strokes.h"

#include "core/npr/lines/chain_corners.h"
#include "tests/npr/lines/line_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace inkray {
namespace {

using namespace test;

LineStyle plain_style(float width = 2.f) {
  LineStyle s;
  s.color = Color(0.f);
  s.width = width;
  return s;
}

std::vector<LineStroke> stroke_one(const Chain& chain, const LineStyle& style, int height = 1080) {
  return stroke_chains({chain}, {line_set("lines", style)}, height);
}

// An L: right along the top, then down, turning 90 degrees at its corner.
Chain l_chain() {
  Chain c = straight_chain(Vec2(10.f, 10.f), Vec2(60.f, 10.f));
  const Chain down = straight_chain(Vec2(60.f, 10.f), Vec2(60.f, 60.f));
  c.points.insert(c.points.end(), down.points.begin() + 1, down.points.end());
  return c;
}

TEST(LineStrokes, WidthsArePixelsAt1080Lines) {
  const Chain c = straight_chain(Vec2(10.f, 10.f), Vec2(50.f, 10.f));
  const std::vector<LineStroke> at_1080 = stroke_one(c, plain_style(2.f), 1080);
  const std::vector<LineStroke> at_2160 = stroke_one(c, plain_style(2.f), 2160);
  ASSERT_EQ(at_1080.size(), 1u);
  ASSERT_EQ(at_2160.size(), 1u);
  EXPECT_FLOAT_EQ(at_1080[0].samples[5].half_width, 1.f);
  EXPECT_FLOAT_EQ(at_2160[0].samples[5].half_width, 2.f);
  EXPECT_FALSE(at_1080[0].closed);
  EXPECT_EQ(at_1080[0].set, 0);
  EXPECT_NEAR(stroke_length(at_1080[0]), 40.f, 1e-3f);
}

TEST(LineStrokes, SelectsByTypePathObjectAndMaterial) {
  Chain crease = straight_chain(Vec2(0.f), Vec2(20.f, 0.f), LineType::crease);
  crease.object = 1, crease.material = 0;
  Chain mirrored = straight_chain(Vec2(0.f, 5.f), Vec2(20.f, 5.f), LineType::silhouette);
  mirrored.path = LinePath::reflected;
  mirrored.object = 0, mirrored.material = 2;
  const Chain unowned = straight_chain(Vec2(0.f, 9.f), Vec2(20.f, 9.f), LineType::silhouette);

  LineSelection all;
  EXPECT_TRUE(selects(all, crease) && selects(all, mirrored) && selects(all, unowned));
  LineSelection creases;
  creases.types = 1u << int(LineType::crease);
  EXPECT_TRUE(selects(creases, crease));
  EXPECT_FALSE(selects(creases, mirrored));
  LineSelection direct;
  direct.paths = 1u << int(LinePath::direct);
  EXPECT_TRUE(selects(direct, crease));
  EXPECT_FALSE(selects(direct, mirrored));
  LineSelection object1;
  object1.objects = {false, true};
  EXPECT_TRUE(selects(object1, crease));
  EXPECT_FALSE(selects(object1, mirrored));
  EXPECT_FALSE(selects(object1, unowned));  // object -1
  LineSelection material2;
  material2.materials = {false, false, true};
  EXPECT_TRUE(selects(material2, mirrored));
  EXPECT_FALSE(selects(material2, crease));

  // Each set strokes what it selects, sets in order.
  LineSet first = line_set("creases", plain_style());
  first.select = creases;
  LineSet second = line_set("reflections", plain_style());
  second.select.paths = 1u << int(LinePath::reflected);
  const std::vector<LineStroke> strokes = stroke_chains({crease, mirrored, unowned}, {first, second}, 1080);
  ASSERT_EQ(strokes.size(), 2u);
  EXPECT_EQ(strokes[0].set, 0);
  EXPECT_NEAR(strokes[0].samples[0].p.y, 0.f, 1e-4f);
  EXPECT_EQ(strokes[1].set, 1);
  EXPECT_NEAR(strokes[1].samples[0].p.y, 5.f, 1e-4f);
}

TEST(LineStrokes, MinLengthDropsShortChains) {
  const Chain short_chain = straight_chain(Vec2(0.f), Vec2(8.f, 0.f));
  const Chain long_chain = straight_chain(Vec2(0.f, 20.f), Vec2(30.f, 20.f));
  LineStyle style = plain_style();
  style.min_length = 10.f;
  std::vector<LineStroke> strokes = stroke_chains({short_chain, long_chain}, {line_set("s", style)}, 1080);
  ASSERT_EQ(strokes.size(), 1u);
  EXPECT_NEAR(strokes[0].samples[0].p.y, 20.f, 1e-4f);
  // At twice the resolution 10 px reads 20: the 30 px chain stays, a 15 px one goes.
  const Chain middling = straight_chain(Vec2(0.f, 40.f), Vec2(15.f, 40.f));
  strokes = stroke_chains({middling, long_chain}, {line_set("s", style)}, 2160);
  ASSERT_EQ(strokes.size(), 1u);
  EXPECT_NEAR(strokes[0].samples[0].p.y, 20.f, 1e-4f);
}

TEST(LineStrokes, CornersSharperThanTheAngleSplitChains) {
  const Chain l = l_chain();
  const std::vector<float> turns = chain_turns(l);
  EXPECT_NEAR(*std::max_element(turns.begin(), turns.end()), 90.f, 1.f);
  // A 90 degree turn is sharper than 180 - 100 = 80 degrees, not than 180 - 80.
  EXPECT_EQ(split_at_corners(l, 100.f).size(), 2u);
  EXPECT_EQ(split_at_corners(l, 80.f).size(), 1u);
  EXPECT_EQ(split_at_corners(l, 0.f).size(), 1u);
  const std::vector<Chain> pieces = split_at_corners(l, 100.f);
  EXPECT_EQ(pieces[0].points.back().p, Vec2(60.f, 10.f));  // cut exactly at the corner
  EXPECT_EQ(pieces[1].points.front().p, Vec2(60.f, 10.f));

  // A closed square opens into its four sides; a circle stays one loop.
  Chain square;
  square.closed = true;
  const Vec2 corners[4] = {{0.f, 0.f}, {40.f, 0.f}, {40.f, 40.f}, {0.f, 40.f}};
  for (int side = 0; side < 4; ++side) {
    const Chain edge = straight_chain(corners[side], corners[(side + 1) % 4]);
    square.points.insert(square.points.end(), edge.points.begin(), edge.points.end() - 1);
  }
  const std::vector<Chain> sides = split_at_corners(square, 100.f);
  ASSERT_EQ(sides.size(), 4u);
  for (const Chain& side : sides) {
    EXPECT_FALSE(side.closed);
    EXPECT_NEAR(chain_length(side), 40.f, 1e-3f);
  }
  const std::vector<Chain> circle = split_at_corners(circle_chain(Vec2(50.f), 20.f), 100.f);
  ASSERT_EQ(circle.size(), 1u);
  EXPECT_TRUE(circle[0].closed);

  // Styled: each piece its own stroke, tapering into the corner.
  LineStyle style = plain_style(4.f);
  style.corner_angle = 100.f;
  style.taper_end = 0.3f;
  const std::vector<LineStroke> strokes = stroke_one(l, style);
  ASSERT_EQ(strokes.size(), 2u);
  EXPECT_NEAR(strokes[0].samples.back().half_width, 0.f, 1e-4f);
}

TEST(LineStrokes, TaperGrowsFromAndShrinksToNothing) {
  LineStyle style = plain_style(4.f);
  style.taper_start = 0.25f;
  style.taper_end = 0.25f;
  const std::vector<LineStroke> strokes = stroke_one(straight_chain(Vec2(0.f), Vec2(100.f, 0.f)), style);
  ASSERT_EQ(strokes.size(), 1u);
  const std::vector<StrokeSample>& s = strokes[0].samples;
  ASSERT_EQ(s.size(), 101u);
  EXPECT_FLOAT_EQ(s.front().half_width, 0.f);
  EXPECT_FLOAT_EQ(s.back().half_width, 0.f);
  EXPECT_FLOAT_EQ(s[50].half_width, 2.f);
  EXPECT_FLOAT_EQ(s[25].half_width, 2.f);
  for (size_t i = 1; i <= 25; ++i) EXPECT_GT(s[i].half_width, s[i - 1].half_width);
  for (size_t i = 76; i <= 100; ++i) EXPECT_LT(s[i].half_width, s[i - 1].half_width);
  // A loop has no ends to taper.
  const std::vector<LineStroke> loop = stroke_one(circle_chain(Vec2(50.f), 20.f), style);
  ASSERT_EQ(loop.size(), 1u);
  EXPECT_TRUE(loop[0].closed);
  for (const StrokeSample& q : loop[0].samples) EXPECT_FLOAT_EQ(q.half_width, 2.f);
}

// The pressure curve, given out of order: flat before its first point and after its
// last, straight between, on top of the width.
TEST(LineStrokes, PressureCurveScalesTheWidthAlongTheLine) {
  LineStyle style = plain_style(4.f);
  style.pressure = {{0.8f, 0.5f}, {0.2f, 1.f}, {0.5f, 2.f}};
  const std::vector<LineStroke> strokes = stroke_one(straight_chain(Vec2(0.f), Vec2(100.f, 0.f)), style);
  ASSERT_EQ(strokes.size(), 1u);
  const std::vector<StrokeSample>& s = strokes[0].samples;
  ASSERT_EQ(s.size(), 101u);
  EXPECT_FLOAT_EQ(s[0].half_width, 2.f);
  EXPECT_FLOAT_EQ(s[20].half_width, 2.f);
  EXPECT_NEAR(s[35].half_width, 3.f, 1e-4f);
  EXPECT_FLOAT_EQ(s[50].half_width, 4.f);
  EXPECT_NEAR(s[65].half_width, 2.5f, 1e-4f);
  EXPECT_FLOAT_EQ(s[80].half_width, 1.f);
  EXPECT_FLOAT_EQ(s[100].half_width, 1.f);
  // One point: the whole line at its multiplier.
  style.pressure = {{0.4f, 0.25f}};
  const std::vector<LineStroke> flat = stroke_one(straight_chain(Vec2(0.f), Vec2(100.f, 0.f)), style);
  ASSERT_EQ(flat.size(), 1u);
  for (const StrokeSample& sample : flat[0].samples) EXPECT_FLOAT_EQ(sample.half_width, 0.5f);
}

// Which lines are joined through a crossing may change from frame to frame: a line
// drawn as one chain through it, or as two chains stopping there, must not grow tips
// there, and stays as wide there as the joined line is.
TEST(LineStrokes, NoTaperWhereAChainStopsAtACrossing) {
  LineStyle style = plain_style(4.f);
  style.taper_start = style.taper_end = 0.3f;
  Chain left = straight_chain(Vec2(0.f), Vec2(100.f, 0.f)),
        right = straight_chain(Vec2(100.f, 0.f), Vec2(200.f, 0.f));
  left.ends_at_crossing = {false, true};
  right.ends_at_crossing = {true, false};
  const std::vector<LineStroke> joined = stroke_one(straight_chain(Vec2(0.f), Vec2(200.f, 0.f)), style);
  const std::vector<LineStroke> split = stroke_chains({left, right}, {line_set("lines", style)}, 1080);
  ASSERT_EQ(joined.size(), 1u);
  ASSERT_EQ(split.size(), 2u);
  EXPECT_FLOAT_EQ(split[0].samples.front().half_width, 0.f);  // the free ends are tips
  EXPECT_FLOAT_EQ(split[1].samples.back().half_width, 0.f);
  const auto width_at = [](const LineStroke& stroke, float x) {
    for (const StrokeSample& q : stroke.samples)
      if (std::abs(q.p.x - x) < 0.5f) return q.half_width;
    return -1.f;
  };
  for (float x : {90.f, 100.f, 110.f}) {
    EXPECT_FLOAT_EQ(width_at(joined[0], x), 2.f) << x;
    EXPECT_FLOAT_EQ(width_at(x <= 100.f ? split[0] : split[1], x), 2.f) << x;
  }
  // Split at a corner, the cut ends are corners, not crossings: they taper.
  Chain bent = left;
  bent.ends_at_crossing = {true, true};
  const Chain down = straight_chain(Vec2(100.f, 0.f), Vec2(100.f, 100.f));
  bent.points.insert(bent.points.end(), down.points.begin() + 1, down.points.end());
  style.corner_angle = 120.f;
  const std::vector<LineStroke> pieces = stroke_one(bent, style);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_FLOAT_EQ(pieces[0].samples.front().half_width, 2.f);
  EXPECT_FLOAT_EQ(pieces[0].samples.back().half_width, 0.f);
  EXPECT_FLOAT_EQ(pieces[1].samples.front().half_width, 0.f);
  EXPECT_FLOAT_EQ(pieces[1].samples.back().half_width, 2.f);
}

TEST(LineStrokes, OvershootExtendsAlongTheEndTangents) {
  LineStyle style = plain_style();
  style.overshoot = 6.f;
  const std::vector<LineStroke> strokes = stroke_one(straight_chain(Vec2(10.f, 5.f), Vec2(50.f, 5.f)), style);
  ASSERT_EQ(strokes.size(), 1u);
  EXPECT_NEAR(strokes[0].samples.front().p.x, 4.f, 1e-4f);
  EXPECT_NEAR(strokes[0].samples.back().p.x, 56.f, 1e-4f);
  EXPECT_NEAR(strokes[0].samples.back().p.y, 5.f, 1e-4f);
  EXPECT_NEAR(stroke_length(strokes[0]), 52.f, 1e-3f);
}

// The sample positions of the strokes of the chain whose first point is `start`.
std::vector<Vec2> positions_of(const std::vector<LineStroke>& strokes, size_t index) {
  std::vector<Vec2> p;
  for (const StrokeSample& s : strokes[index].samples) p.push_back(s.p);
  return p;
}

TEST(LineStrokes, JitterDisplacesTheSameWayWhateverTheOrder) {
  LineStyle style = plain_style();
  style.jitter = 2.f;
  style.jitter_scale = 15.f;
  style.seed = 7;
  const Chain a = straight_chain(Vec2(10.f, 20.f), Vec2(110.f, 20.f));
  const Chain b = circle_chain(Vec2(60.f, 80.f), 30.f);
  const std::vector<LineStroke> ab = stroke_chains({a, b}, {line_set("s", style)}, 1080);
  ASSERT_EQ(ab.size(), 2u);
  float most = 0.f;
  for (const StrokeSample& s : ab[0].samples) most = std::max(most, std::abs(s.p.y - 20.f));
  EXPECT_GT(most, 0.5f);
  EXPECT_LE(most, 2.f + 1e-4f);

  // Listed the other way round, and each traced backwards from another start.
  Chain a_reversed = a, b_reversed = b;
  std::reverse(a_reversed.points.begin(), a_reversed.points.end());
  std::reverse(b_reversed.points.begin(), b_reversed.points.end());
  std::rotate(b_reversed.points.begin(), b_reversed.points.begin() + 40, b_reversed.points.end());
  const std::vector<LineStroke> ba = stroke_chains({b_reversed, a_reversed}, {line_set("s", style)}, 1080);
  ASSERT_EQ(ba.size(), 2u);
  std::vector<Vec2> line = positions_of(ba, 1);
  std::reverse(line.begin(), line.end());
  const std::vector<Vec2> expected_line = positions_of(ab, 0);
  ASSERT_EQ(line.size(), expected_line.size());
  for (size_t i = 0; i < line.size(); ++i)
    EXPECT_NEAR(glm::length(line[i] - expected_line[i]), 0.f, 1e-3f) << i;
  // The loop: the same displaced points, in another order.
  const std::vector<Vec2> loop = positions_of(ba, 0), expected_loop = positions_of(ab, 1);
  ASSERT_EQ(loop.size(), expected_loop.size());
  for (const Vec2& p : expected_loop) {
    float nearest = 1e9f;
    for (const Vec2& q : loop) nearest = std::min(nearest, glm::length(p - q));
    EXPECT_LT(nearest, 1e-3f);
  }

  // Another seed, another wobble.
  style.seed = 8;
  const std::vector<LineStroke> reseeded = stroke_chains({a}, {line_set("s", style)}, 1080);
  float moved = 0.f;
  for (size_t i = 0; i < reseeded[0].samples.size(); ++i)
    moved = std::max(moved, glm::length(reseeded[0].samples[i].p - ab[0].samples[i].p));
  EXPECT_GT(moved, 0.2f);
}

TEST(LineStrokes, EachPassHasItsOwnNoise) {
  LineStyle style = plain_style();
  style.jitter = 1.5f;
  style.passes = 3;
  const std::vector<LineStroke> strokes = stroke_one(straight_chain(Vec2(0.f), Vec2(80.f, 0.f)), style);
  ASSERT_EQ(strokes.size(), 3u);
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b) {
      float apart = 0.f;
      for (size_t i = 0; i < strokes[size_t(a)].samples.size(); ++i)
        apart =
            std::max(apart, glm::length(strokes[size_t(a)].samples[i].p - strokes[size_t(b)].samples[i].p));
      EXPECT_GT(apart, 0.2f) << a << " " << b;
    }
}

TEST(LineStrokes, ModulationAndOpacity) {
  Chain near_chain = straight_chain(Vec2(0.f), Vec2(50.f, 0.f));
  Chain far_chain = straight_chain(Vec2(0.f, 10.f), Vec2(50.f, 10.f));
  for (ChainPoint& q : near_chain.points) q.depth = 2.f, q.opacity = 0.5f;
  for (ChainPoint& q : far_chain.points) q.depth = 8.f;
  far_chain.points[3].depth = 0.f;  // the background: as far as the farthest

  LineStyle style = plain_style(4.f);
  style.opacity = 0.8f;
  style.color = Color(1.f, 0.f, 0.f);
  style.color_end = Color(0.f, 0.f, 1.f);
  style.color_by = LineModulation::depth;
  style.width_by = LineModulation::along;
  style.width_min = 0.5f;
  style.opacity_by = LineModulation::depth;
  style.opacity_min = 0.25f;
  const std::vector<LineStroke> strokes =
      stroke_chains({near_chain, far_chain}, {line_set("s", style)}, 1080);
  ASSERT_EQ(strokes.size(), 2u);
  const LineStroke &near_stroke = strokes[0], &far_stroke = strokes[1];
  EXPECT_FLOAT_EQ(near_stroke.samples.front().half_width, 2.f);
  EXPECT_FLOAT_EQ(near_stroke.samples.back().half_width, 1.f);
  EXPECT_NEAR(near_stroke.samples[25].half_width, 1.5f, 1e-5f);
  EXPECT_EQ(near_stroke.samples[5].color, Color(1.f, 0.f, 0.f));
  EXPECT_EQ(far_stroke.samples[5].color, Color(0.f, 0.f, 1.f));
  EXPECT_EQ(far_stroke.samples[3].color, Color(0.f, 0.f, 1.f));
  // style opacity * modulation * the chain's own opacity
  EXPECT_FLOAT_EQ(near_stroke.samples[5].opacity, 0.8f * 1.f * 0.5f);
  EXPECT_FLOAT_EQ(far_stroke.samples[5].opacity, 0.8f * 0.25f * 1.f);

  // Curvature reads 1 at a radian per 10 pixels at 1080 lines, 20 at 2160.
  LineStyle curl = plain_style(4.f);
  curl.width_by = LineModulation::curvature;
  curl.width_min = 0.f;
  const Chain tight = circle_chain(Vec2(50.f), 10.f), loose = circle_chain(Vec2(50.f), 40.f);
  EXPECT_NEAR(stroke_one(tight, curl)[0].samples[0].half_width, 0.f, 1e-4f);
  EXPECT_NEAR(stroke_one(loose, curl)[0].samples[0].half_width, 2.f * 0.75f, 1e-4f);
  EXPECT_NEAR(stroke_one(loose, curl, 2160)[0].samples[0].half_width, 4.f * 0.5f, 1e-4f);
}

TEST(LineStrokes, DashesCutTheLineAfterItsTaper) {
  LineStyle style = plain_style(4.f);
  style.dash = 6.f;
  style.gap = 4.f;
  style.taper_start = style.taper_end = 0.5f;
  const std::vector<LineStroke> dashes = stroke_one(straight_chain(Vec2(0.f), Vec2(100.f, 0.f)), style);
  ASSERT_EQ(dashes.size(), 10u);
  for (size_t i = 0; i < dashes.size(); ++i) {
    const LineStroke& d = dashes[i];
    EXPECT_FALSE(d.closed);
    EXPECT_NEAR(d.samples.front().p.x, 10.f * float(i), 1e-4f);
    EXPECT_NEAR(d.samples.back().p.x, 10.f * float(i) + 6.f, 1e-4f);
    EXPECT_NEAR(d.samples.front().v, 10.f * float(i), 1e-4f);  // v runs on over the gaps
  }
  // The taper spans the whole line: thin at the ends, full in the middle.
  EXPECT_FLOAT_EQ(dashes[0].samples.front().half_width, 0.f);
  EXPECT_NEAR(dashes[5].samples.front().half_width, 2.f, 1e-5f);
  EXPECT_LT(dashes[9].samples.back().half_width, 0.5f);
  // A loop is dashed all the way round.
  const std::vector<LineStroke> ring = stroke_one(circle_chain(Vec2(50.f), 20.f), style);
  float dashed = 0.f;
  for (const LineStroke& d : ring) dashed += stroke_length(d);
  EXPECT_NEAR(dashed / (2.f * 3.14159265f * 20.f), 0.6f, 0.05f);
}

}  // namespace
}  // namespace inkray
