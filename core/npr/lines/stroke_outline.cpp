// Strokes as filled outlines.
#include "core/npr/lines/stroke_outline.h"

#include "core/image/image_io.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

// Samples closer than this are one point: their segment has no direction.
constexpr float kSamePointPx = 1e-3f;
// Turns sharper than this between two segments break the outline: the mitred
// offset of a sharper turn would stand out past the round join it stands for.
constexpr float kMaxMitreTurnDegrees = 25.f;
constexpr float kPi = 3.14159265358979f;

std::vector<StrokeSample> distinct_samples(const LineStroke& stroke) {
  std::vector<StrokeSample> out;
  for (const StrokeSample& s : stroke.samples)
    if (out.empty() || glm::length(s.p - out.back().p) > kSamePointPx) out.push_back(s);
  if (stroke.closed)
    while (out.size() > 1 && glm::length(out.front().p - out.back().p) <= kSamePointPx) out.pop_back();
  return out;
}

bool near_colour(const StrokeSample& a, const StrokeSample& b) {
  if (std::abs(a.opacity - b.opacity) > kRunOpacityTolerance) return false;
  if (a.color == b.color) return true;  // the usual case, without encoding
  for (int c = 0; c < 3; ++c) {
    const float ea = linear_to_srgb(std::clamp(a.color[c], 0.f, 1.f));
    const float eb = linear_to_srgb(std::clamp(b.color[c], 0.f, 1.f));
    if (std::abs(ea - eb) > kRunColorTolerance) return false;
  }
  return true;
}

std::vector<Vec2> disc(Vec2 centre, float radius) {
  const int sides = std::clamp(int(std::ceil(2.f * kPi * radius)), 8, 48);
  std::vector<Vec2> ring;
  for (int k = 0; k < sides; ++k) {
    const float a = 2.f * kPi * float(k) / float(sides);
    ring.push_back(centre + radius * Vec2(std::cos(a), std::sin(a)));
  }
  return ring;
}

class Outliner {
 public:
  Outliner(std::vector<StrokeSample> samples, bool closed) : s_(std::move(samples)), closed_(closed) {
    const size_t n = s_.size(), segments = closed_ ? n : n - 1;
    for (size_t i = 0; i < segments; ++i) {
      const Vec2 d = s_[(i + 1) % n].p - s_[i].p;
      length_.push_back(glm::length(d));
      normal_.push_back(Vec2(-d.y, d.x) / length_.back());
    }
  }

  size_t size() const { return s_.size(); }
  const StrokeSample& sample(size_t i) const { return s_[i % s_.size()]; }

  // Whether the outline must break at sample i, between segments i - 1 and i.
  bool too_sharp(size_t i) const {
    const size_t n = s_.size();
    if (!closed_ && (i == 0 || i + 1 >= n)) return false;
    const size_t before = (i + normal_.size() - 1) % normal_.size(), after = i % normal_.size();
    static const float kMaxMitreTurnCosine = std::cos(kMaxMitreTurnDegrees * kPi / 180.f);
    const float cosine = std::clamp(glm::dot(normal_[before], normal_[after]), -1.f, 1.f);
    if (cosine < kMaxMitreTurnCosine) return true;
    // The inner offset would pass the middle of a neighbouring segment: it folds.
    const float tan_half_turn = std::sqrt((1.f - cosine) / (1.f + cosine));
    return s_[i].half_width * tan_half_turn > 0.5f * std::min(length_[before], length_[after]);
  }

  // Samples first..last (indices may run past the end of a loop) as one polygon,
  // flat across where it meets a disc; where only the colour changes, runs meet
  // along the same mitred edge.
  std::vector<Vec2> run_ring(size_t first, size_t last, bool flat_first, bool flat_last) const {
    std::vector<Vec2> left, right;
    for (size_t k = first; k <= last; ++k) {
      const Vec2 offset = offset_at(k, flat_first && k == first, flat_last && k == last);
      left.push_back(sample(k).p + offset);
      right.push_back(sample(k).p - offset);
    }
    left.insert(left.end(), right.rbegin(), right.rend());
    return left;
  }

  // An unbroken loop: its outer and inner edges, wound against each other.
  std::vector<std::vector<Vec2>> loop_rings() const {
    std::vector<Vec2> left, right;
    for (size_t k = 0; k < s_.size(); ++k) {
      const Vec2 offset = offset_at(k, false, false);
      left.push_back(s_[k].p + offset);
      right.push_back(s_[k].p - offset);
    }
    std::reverse(right.begin(), right.end());
    return {left, right};
  }

 private:
  // Across sample k: along its segment's normal at a run's ends (flat ends, as
  // draw_strokes' are), else mitred between its two segments.
  Vec2 offset_at(size_t k, bool run_start, bool run_end) const {
    const size_t segments = normal_.size();
    const size_t at = k % s_.size();
    const float hw = s_[at].half_width;
    const bool has_before = closed_ || at > 0, has_after = closed_ || at + 1 < s_.size();
    const Vec2 before = normal_[(at + segments - 1) % segments], after = normal_[at % segments];
    if (run_start || !has_before) return after * hw;
    if (run_end || !has_after) return before * hw;
    const Vec2 sum = before + after;
    const float len = glm::length(sum);
    if (!(len > 1e-6f)) return after * hw;
    const Vec2 mitre = sum / len;
    return mitre * (hw / std::max(glm::dot(mitre, after), 0.5f));
  }

  std::vector<StrokeSample> s_;
  bool closed_;
  std::vector<float> length_;
  std::vector<Vec2> normal_;  // per segment, unit
};

OutlineShape run_shape(const Outliner& o, size_t first, size_t last, bool flat_first, bool flat_last) {
  OutlineShape shape{{o.run_ring(first, last, flat_first, flat_last)}, Color(0.f), 0.f};
  for (size_t k = first; k <= last; ++k)
    shape.color += o.sample(k).color, shape.opacity += o.sample(k).opacity;
  const float count = float(last - first + 1);
  shape.color /= count, shape.opacity /= count;
  return shape;
}

}  // namespace

std::vector<OutlineShape> stroke_outline(const LineStroke& stroke) {
  std::vector<StrokeSample> samples = distinct_samples(stroke);
  std::vector<OutlineShape> shapes;
  if (samples.empty()) return shapes;
  if (samples.size() == 1) {
    const StrokeSample& s = samples.front();
    if (s.half_width > 0.f) shapes.push_back({{disc(s.p, s.half_width)}, s.color, s.opacity});
    return shapes;
  }
  const bool closed = stroke.closed && samples.size() > 2;
  const Outliner o(std::move(samples), closed);
  const size_t n = o.size();

  // Where runs break: at sharp turns (with a disc for the join) and colour changes.
  std::vector<bool> sharp(n, false);
  for (size_t i = 0; i < n; ++i) sharp[i] = o.too_sharp(i);
  size_t first = 0;
  if (closed) {
    while (first < n && !sharp[first]) ++first;
    if (first == n) {  // no sharp turn: a loop, unless its colour drifts
      first = 0;
      bool drifts = false;
      for (size_t i = 1; i < n && !drifts; ++i) drifts = !near_colour(o.sample(0), o.sample(i));
      if (!drifts) {
        OutlineShape loop{o.loop_rings(), Color(0.f), 0.f};
        for (size_t i = 0; i < n; ++i) loop.color += o.sample(i).color, loop.opacity += o.sample(i).opacity;
        loop.color /= float(n), loop.opacity /= float(n);
        shapes.push_back(std::move(loop));
        return shapes;
      }
    }
  }
  // Sample indices run from `first` to `end` (a loop comes back round to `first`).
  const size_t end = closed ? first + n : n - 1;
  size_t run_start = first;
  for (size_t k = first + 1; k <= end; ++k) {
    const bool breaks = sharp[k % n] || !near_colour(o.sample(run_start), o.sample(k));
    if (k < end && !breaks) continue;
    shapes.push_back(run_shape(o, run_start, k, sharp[run_start % n], sharp[k % n]));
    run_start = k;
  }
  for (size_t i = 0; i < n; ++i) {
    const StrokeSample& s = o.sample(i);
    if (sharp[i] && s.half_width > 0.f) shapes.push_back({{disc(s.p, s.half_width)}, s.color, s.opacity});
  }
  return shapes;
}

}  // namespace inkray
