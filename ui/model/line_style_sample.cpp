#include "ui/model/line_style_sample.h"

#include "core/compiler/compile_line_sets.h"
#include "core/npr/strokes/brush.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

constexpr float kPi = 3.14159265f;

// One wave of a sine: a line that bends both ways, as most drawn lines do somewhere.
Chain sample_chain(float width, float height, float margin_x, float margin_y) {
  Chain chain;
  const float x0 = margin_x, x1 = std::max(width - margin_x, x0 + 1.f);
  const float amplitude = std::max(0.5f * height - margin_y, 0.f);
  const int count = std::max(int(x1 - x0), 2);
  for (int i = 0; i <= count; ++i) {
    const float t = float(i) / float(count);
    ChainPoint point;
    point.p = Vec2(x0 + t * (x1 - x0), 0.5f * height - amplitude * std::sin(2.f * kPi * t));
    point.depth = 1.f + t;  // near at the left, far at the right
    point.light = t;
    chain.points.push_back(point);
  }
  // Turning per pixel, from each point's neighbours.
  for (size_t i = 1; i + 1 < chain.points.size(); ++i) {
    const Vec2 a = chain.points[i].p - chain.points[i - 1].p, b = chain.points[i + 1].p - chain.points[i].p;
    const float turn = std::atan2(a.x * b.y - a.y * b.x, glm::dot(a, b));
    chain.points[i].curvature = turn / std::max(0.5f * (glm::length(a) + glm::length(b)), 1e-3f);
  }
  return chain;
}

}  // namespace

std::vector<LineStroke> sample_strokes(const LineSetStyleDesc& style, float width, float height,
                                       float scale) {
  // Room for the overshoot at the ends and for the widest line and its wobble across.
  const float half_width = 0.5f * style.width * scale * std::max(1.f, style.width_min);
  const float margin_x =
      std::min(style.overshoot * scale, 0.25f * width) + std::min(half_width, 0.2f * width) + 2.f;
  const float margin_y = std::min(half_width + style.jitter * scale, 0.35f * height) + 0.1f * height;
  LineSet set;
  static_cast<LineStyleParams&>(set.style) = style;
  const int image_height = std::max(int(std::lround(1080.f * scale)), 1);
  return stroke_chains({sample_chain(width, height, margin_x, margin_y)}, {set}, image_height);
}

float sample_brush_alpha(const LineSetStyleDesc& style, const LineStroke& stroke, float u, float v) {
  if (style.brush != LineBrush::bristle && style.brush != LineBrush::flat) return 1.f;
  // Stretched over the stroke, or repeated every brush_repeat pixels (as scaled).
  const float repeat =
      stroke.brush_repeat_px > 0.f ? stroke.brush_repeat_px : std::max(stroke_length(stroke), 1e-3f);
  const float along = std::fmod(std::max(v, 0.f), repeat) / repeat;
  if (style.brush == LineBrush::flat) return flat_alpha(u, along, kLineBrushPressure);
  const StrokeEmitterDesc defaults;  // a line set's bristle brush has the strokes' default bristles
  return bristle_alpha(u, along, defaults.bristles, kLineBrushPressure, uint32_t(stroke.brush_variant));
}

}  // namespace inkray
