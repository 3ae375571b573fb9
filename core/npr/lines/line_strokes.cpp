// Chains styled into strokes.
#include "core/npr/lines/line_strokes.h"

#include "core/math/hash.h"
#include "core/npr/lines/chain_corners.h"
#include "core/npr/lines/stroke_dashes.h"
#include "core/npr/lines/stroke_jitter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace inkray {
namespace {

// Samples about this far apart (at most one and a half times), pixels: width and
// colour then change smoothly however long the chain's own segments are.
constexpr float kSampleSpacingPx = 1.f;
// Curvature (radians per pixel at 1080 lines) that reads as 1: a turn of a radian
// over ten pixels, a radius of ten pixels. A radian per pixel would leave all but
// the tightest curls near 0.
constexpr float kFullCurvaturePer1080Px = 0.1f;

struct DepthRange {
  float nearest = 0.f, farthest = 0.f;
};

// Over every point of every chain, the background (depth 0) left out.
DepthRange depth_range(const std::vector<Chain>& chains) {
  DepthRange r{std::numeric_limits<float>::max(), 0.f};
  for (const Chain& c : chains)
    for (const ChainPoint& q : c.points)
      if (q.depth > 0.f) r.nearest = std::min(r.nearest, q.depth), r.farthest = std::max(r.farthest, q.depth);
  if (r.farthest <= 0.f) r.nearest = 0.f;
  return r;
}

ChainPoint lerp(const ChainPoint& a, const ChainPoint& b, float t) {
  return {glm::mix(a.p, b.p, t), glm::mix(a.opacity, b.opacity, t), glm::mix(a.depth, b.depth, t),
          glm::mix(a.curvature, b.curvature, t), glm::mix(a.light, b.light, t)};
}

// The piece's points with every segment over one and a half spacings subdivided (a
// loop's closing segment too, so its points still end short of the first).
std::vector<ChainPoint> resampled(const Chain& piece) {
  std::vector<ChainPoint> out;
  const size_t n = piece.points.size();
  const size_t segments = piece.closed ? n : n - 1;
  out.reserve(n);
  for (size_t i = 0; i < segments; ++i) {
    const ChainPoint& a = piece.points[i];
    const ChainPoint& b = piece.points[(i + 1) % n];
    // Rounded, so a traced chain's diagonal steps (1.4 px) are kept as they are.
    const int steps = std::max(1, int(std::lround(glm::length(b.p - a.p) / kSampleSpacingPx)));
    for (int k = 0; k < steps; ++k) out.push_back(lerp(a, b, float(k) / float(steps)));
  }
  if (!piece.closed) out.push_back(piece.points.back());
  return out;
}

// The direction an open line leaves `points` through its first point, measured
// over the corner reach so a stair step at the very end does not set it.
Vec2 end_direction(const std::vector<ChainPoint>& points) {
  const Vec2 end = points.front().p;
  Vec2 inner = end;
  for (const ChainPoint& q : points) {
    inner = q.p;
    if (glm::length(q.p - end) >= kCornerReachPx) break;
  }
  const Vec2 d = end - inner;
  const float len = glm::length(d);
  return len > 0.f ? d / len : Vec2(0.f);
}

// Extends both ends of an open line straight on by `length`, at the sample spacing,
// the end points' attributes carried out (curvature 0: the extension is straight).
void overshoot(std::vector<ChainPoint>& points, float length) {
  if (!(length > 0.f) || points.size() < 2) return;
  const int steps = std::max(1, int(std::ceil(length / kSampleSpacingPx)));
  auto extension = [&](const std::vector<ChainPoint>& from) {
    std::vector<ChainPoint> ext;
    const Vec2 dir = end_direction(from);
    ChainPoint q = from.front();
    q.curvature = 0.f;
    for (int k = steps; k >= 1; --k)
      ext.push_back(q), ext.back().p = q.p + dir * (length * float(k) / float(steps));
    return ext;  // outermost first
  };
  std::vector<ChainPoint> before = extension(points);
  std::vector<ChainPoint> reversed(points.rbegin(), points.rend());
  std::vector<ChainPoint> after = extension(reversed);
  std::reverse(after.begin(), after.end());
  before.insert(before.end(), points.begin(), points.end());
  before.insert(before.end(), after.begin(), after.end());
  points = std::move(before);
}

// Grows from 0 at x = 0 to 1 at x = 1, level there so the full width joins on
// smoothly; steep at 0 for a pointed, not a needle-thin, tip.
float taper_ease(float x) {
  x = std::clamp(x, 0.f, 1.f);
  return x * (2.f - x);
}

// An end at a crossing is not a tip (Chain::ends_at_crossing): which lines are joined
// through a crossing may change from frame to frame, and the line goes on there anyway.
float taper(const LineStyle& style, const std::array<bool, 2>& ends_at_crossing, float s, float length) {
  float f = 1.f;
  if (style.taper_start > 0.f && !ends_at_crossing[0]) f *= taper_ease(s / (style.taper_start * length));
  if (style.taper_end > 0.f && !ends_at_crossing[1])
    f *= taper_ease((length - s) / (style.taper_end * length));
  return f;
}

// The pressure curve's width multiplier at `along` (0 at the start, 1 at the end).
float pressure(const std::vector<PressurePoint>& curve, float along) {
  if (curve.empty()) return 1.f;
  const PressurePoint* below = nullptr;
  const PressurePoint* above = nullptr;
  for (const PressurePoint& p : curve) {
    if (p.at <= along && (!below || p.at >= below->at)) below = &p;
    if (p.at >= along && (!above || p.at < above->at)) above = &p;
  }
  if (!below) return above->width;
  if (!above || above->at <= below->at) return below->width;
  return glm::mix(below->width, above->width, (along - below->at) / (above->at - below->at));
}

struct ValueContext {
  DepthRange depth;
  float full_curvature_per_px;  // at this image's scale
};

float modulation_value(LineModulation by, const ChainPoint& q, float along, const ValueContext& c) {
  switch (by) {
    case LineModulation::none:
      return 0.f;
    case LineModulation::along:
      return along;
    case LineModulation::depth: {
      const float span = c.depth.farthest - c.depth.nearest;
      if (!(q.depth > 0.f)) return 1.f;
      return span > 0.f ? std::clamp((q.depth - c.depth.nearest) / span, 0.f, 1.f) : 0.f;
    }
    case LineModulation::curvature:
      return std::clamp(std::abs(q.curvature) / c.full_curvature_per_px, 0.f, 1.f);
    case LineModulation::light:
      return std::clamp(q.light, 0.f, 1.f);
    case LineModulation::coverage:
      break;
  }
  return std::clamp(q.opacity, 0.f, 1.f);
}

// One pass over one piece: shape it, then give each point its width, colour and opacity.
LineStroke styled_stroke(const Chain& piece, const LineStyle& style, float scale, const ValueContext& values,
                         uint32_t seed) {
  std::vector<ChainPoint> points = resampled(piece);
  if (!piece.closed) overshoot(points, style.overshoot * scale);
  jitter_points(points, piece.closed, seed, style.jitter * scale, style.jitter_scale * scale);

  LineStroke stroke;
  stroke.closed = piece.closed;
  stroke.samples.reserve(points.size());
  float s = 0.f;
  for (size_t i = 0; i < points.size(); ++i) {
    if (i > 0) s += glm::length(points[i].p - points[i - 1].p);
    stroke.samples.push_back({points[i].p, 0.f, Color(0.f), 0.f, s});
  }
  const float length = stroke_length(stroke);
  for (size_t i = 0; i < points.size(); ++i) {
    StrokeSample& sample = stroke.samples[i];
    const ChainPoint& q = points[i];
    const float along = length > 0.f ? sample.v / length : 0.f;
    const float width_factor =
        glm::mix(1.f, style.width_min, modulation_value(style.width_by, q, along, values));
    const float tapered = piece.closed ? 1.f : taper(style, piece.ends_at_crossing, sample.v, length);
    sample.half_width =
        std::max(0.f, 0.5f * style.width * scale * width_factor * tapered * pressure(style.pressure, along));
    sample.color =
        style.color_by == LineModulation::none
            ? style.color
            : glm::mix(style.color, style.color_end, modulation_value(style.color_by, q, along, values));
    const float opacity_factor =
        glm::mix(1.f, style.opacity_min, modulation_value(style.opacity_by, q, along, values));
    sample.opacity = std::clamp(style.opacity * opacity_factor * q.opacity, 0.f, 1.f);
  }
  return stroke;
}

}  // namespace

float stroke_length(const LineStroke& stroke) {
  if (stroke.samples.empty()) return 0.f;
  float length = stroke.samples.back().v - stroke.samples.front().v;
  if (stroke.closed) length += glm::length(stroke.samples.front().p - stroke.samples.back().p);
  return length;
}

bool selects(const LineSelection& select, const Chain& chain) {
  auto bit = [](uint32_t bits, int index) { return index >= 0 && index < 32 && ((bits >> index) & 1u) != 0; };
  auto in = [](const std::vector<bool>& chosen, int index) {
    return chosen.empty() || (index >= 0 && size_t(index) < chosen.size() && chosen[size_t(index)]);
  };
  const bool seen = chain.covers == 0;
  return bit(select.types, int(chain.type)) && bit(select.paths, int(chain.path)) &&
         (seen ? select.visible : select.hidden) && in(select.objects, chain.object) &&
         in(select.materials, chain.material);
}

std::vector<LineStroke> stroke_chains(const std::vector<Chain>& chains, const std::vector<LineSet>& sets,
                                      int image_height) {
  std::vector<LineStroke> strokes;
  const float scale = float(std::max(image_height, 1)) / 1080.f;
  const ValueContext values{depth_range(chains), kFullCurvaturePer1080Px / scale};
  for (size_t set_index = 0; set_index < sets.size(); ++set_index) {
    const LineStyle& style = sets[set_index].style;
    for (const Chain& chain : chains) {
      if (chain.points.size() < 2 || !selects(sets[set_index].select, chain)) continue;
      for (const Chain& piece : split_at_corners(chain, style.corner_angle)) {
        const float length = chain_length(piece);
        if (!(length > 0.f) || length < style.min_length * scale) continue;
        const uint32_t key = chain_key(piece);
        for (int pass = 0; pass < std::max(style.passes, 1); ++pass) {
          LineStroke stroke =
              styled_stroke(piece, style, scale, values, hash_combine(style.seed, uint32_t(pass), key));
          stroke.set = int(set_index);
          stroke.brush = style.brush;
          stroke.brush_repeat_px = style.brush_repeat * scale;
          if (style.brush && style.brush->variants > 1)
            stroke.brush_variant =
                int(hash_combine(key, uint32_t(pass), 0x62727368u) % uint32_t(style.brush->variants));
          if (style.dash > 0.f && style.gap > 0.f) {
            for (LineStroke& dash : cut_dashes(stroke, style.dash * scale, style.gap * scale))
              strokes.push_back(std::move(dash));
          } else {
            strokes.push_back(std::move(stroke));
          }
        }
      }
    }
  }
  return strokes;
}

}  // namespace inkray
