// Dashed lines.
#include "core/npr/lines/stroke_dashes.h"

#include <algorithm>

namespace inkray {
namespace {

StrokeSample lerp(const StrokeSample& a, const StrokeSample& b, float t) {
  return {glm::mix(a.p, b.p, t), glm::mix(a.half_width, b.half_width, t), glm::mix(a.color, b.color, t),
          glm::mix(a.opacity, b.opacity, t), glm::mix(a.v, b.v, t)};
}

// The sample at distance v along `samples` (v increasing), from segment `i` on.
StrokeSample sample_at(const std::vector<StrokeSample>& samples, size_t& i, float v) {
  while (i + 2 < samples.size() && samples[i + 1].v < v) ++i;
  const StrokeSample &a = samples[i], &b = samples[i + 1];
  const float span = b.v - a.v;
  return lerp(a, b, span > 0.f ? std::clamp((v - a.v) / span, 0.f, 1.f) : 0.f);
}

}  // namespace

std::vector<LineStroke> cut_dashes(const LineStroke& stroke, float dash, float gap) {
  if (!(dash > 0.f) || !(gap > 0.f) || stroke.samples.size() < 2) return {stroke};
  std::vector<StrokeSample> samples = stroke.samples;
  if (stroke.closed) {
    samples.push_back(samples.front());
    samples.back().v = samples.front().v + stroke_length(stroke);
  }
  const float start = samples.front().v, end = samples.back().v;
  std::vector<LineStroke> dashes;
  size_t segment = 0, next = 0;  // first segment a dash can start in; first sample past its start
  for (float from = start; from < end; from += dash + gap) {
    const float to = std::min(from + dash, end);
    LineStroke piece{{}, false, stroke.set, stroke.brush, stroke.brush_repeat_px, stroke.brush_variant};
    piece.samples.push_back(sample_at(samples, segment, from));
    while (next < samples.size() && samples[next].v <= from) ++next;
    for (; next < samples.size() && samples[next].v < to; ++next) piece.samples.push_back(samples[next]);
    piece.samples.push_back(sample_at(samples, segment, to));
    dashes.push_back(std::move(piece));
  }
  return dashes;
}

}  // namespace inkray
