// Strokes drawn into an image. A stroke's pixels are visited once per piece of the
// stroke they lie across, not once per capsule that reaches them: each segment draws
// the slab of pixels whose nearest point on its line lies within it, and each vertex
// the wedge outside its turn that neither neighbouring slab holds (the round join).
// Where slabs overlap, inside a turn, the nearest wins. A 3 px line so costs about
// one visit per pixel instead of the nine of overlapping capsules.
#include "core/npr/lines/stroke_raster.h"

#include "core/npr/lines/brush_levels.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace inkray {
namespace {

// Thinner strokes are drawn this wide, fainter: kMinLineWidthPx
// (core/npr/outlines/line_detector.h), the film's own rule for thin lines.
constexpr float kMinDrawnHalfWidth = 0.5f;
// Samples closer than this are one point: their segment has no direction.
constexpr float kSamePointPx = 1e-3f;

// The pixels one stroke covers, each with the alpha and colour of the place on the
// stroke that covers it most, the nearest among those covering it fully: where the
// stroke crosses itself a pixel is drawn once. A slot per pixel of the stroke's box
// finds a pixel's entry in the short list of covered ones. The slots are reused stroke
// after stroke (a few kilobytes for most, so they stay in cache) and are cleared
// through that list as the stroke is composited: a stroke costs what it covers.
class StrokeCoverage {
 public:
  // The box of the next stroke: pixels x0..x1, y0..y1 of `image`.
  void begin(int x0, int y0, int x1, int y1, const RgbImage& image) {
    x0_ = x0, y0_ = y0, x1_ = x1, y1_ = y1, box_width_ = x1 - x0 + 1;
    image_width_ = image.width, image_pixels_ = image.pixels.data();
    const size_t area = size_t(box_width_) * size_t(y1 - y0 + 1);
    if (slot_.size() < area) slot_.resize(area, -1);
  }
  int x0() const { return x0_; }
  int y0() const { return y0_; }
  int x1() const { return x1_; }
  int y1() const { return y1_; }

  // What covers pixel (x, y) so far: a new entry covering nothing the first time.
  struct Covered {
    uint32_t pixel, local;  // in the image, in the box
    float shape = -1.f;     // geometric coverage
    float distance = 0.f;   // from the place on the stroke it was taken from
    float alpha = 0.f;
    Color color{0.f};
    // Whether `shape` at `d` beats it: the most covering, then the nearest.
    bool beaten_by(float s, float d) const { return s > shape || (s == shape && d < distance); }
  };
  Covered& at(int x, int y) {
    const uint32_t local = uint32_t(y - y0_) * uint32_t(box_width_) + uint32_t(x - x0_);
    int32_t& slot = slot_[local];
    if (slot < 0) {
      slot = int32_t(covered_.size());
      const uint32_t pixel = uint32_t(y) * uint32_t(image_width_) + uint32_t(x);
      covered_.push_back({pixel, local});
      // The image is tens of megabytes and a stroke's rows lie far apart in it:
      // fetching the pixel now, while the stroke is still being drawn, keeps the
      // cache misses off the composite, where they were a third of its time.
      __builtin_prefetch(image_pixels_ + pixel, 1);
    }
    return covered_[size_t(slot)];
  }

  // OVER `image` in the display's space, as composite_lines does.
  void composite(const DisplayMapping& mapping, RgbImage& image) {
    for (const Covered& c : covered_) {
      slot_[c.local] = -1;
      if (!(c.alpha > 0.f)) continue;
      Color& pixel = image.pixels[c.pixel];
      pixel = mapping.from_display(glm::mix(mapping.to_display(pixel), c.color, std::min(c.alpha, 1.f)));
    }
    covered_.clear();
  }

 private:
  int x0_ = 0, y0_ = 0, x1_ = -1, y1_ = -1, box_width_ = 0, image_width_ = 0;
  const Color* image_pixels_ = nullptr;
  std::vector<int32_t> slot_;
  std::vector<Covered> covered_;
};

struct Brush {
  const BrushLevels* levels = nullptr;
  int variant = 0;
  float v_start = 0.f;
  float v_scale = 1.f;  // brush v per pixel of stroke
  bool repeat = false;
  float v_of(float v) const {
    const float b = (v - v_start) * v_scale;
    return repeat ? b - std::floor(b) : b;
  }
};

// What the place at t between samples a and b gives a pixel centre `distance` from
// it, `across` to the right of travel, `flat` the fade of a flat end.
void cover_pixel(int x, int y, float distance, float across, float flat, const StrokeSample& a,
                 const StrokeSample& b, float t, float vb, const Brush& brush, const AlphaTexture* texture,
                 StrokeCoverage& coverage) {
  const float half_width = a.half_width + (b.half_width - a.half_width) * t;
  const float drawn = std::max(half_width, kMinDrawnHalfWidth);
  const float shape = std::min(drawn - distance + 0.5f, 1.f) * flat;
  if (shape <= 0.f) return;
  StrokeCoverage::Covered& covered = coverage.at(x, y);
  if (!covered.beaten_by(shape, distance)) return;
  float alpha = shape * std::min(half_width / kMinDrawnHalfWidth, 1.f);
  if (texture) {  // u = 0 on the left of travel (y points down the image)
    const float v = a.v + (vb - a.v) * t;
    alpha *= texture->coverage_in(brush.variant, Vec2(0.5f + across / (2.f * drawn), brush.v_of(v)));
  }
  covered.shape = shape, covered.distance = distance;
  covered.alpha = alpha * (a.opacity + (b.opacity - a.opacity) * t);
  covered.color = glm::mix(a.color, b.color, t);
}

const AlphaTexture* texture_for(const Brush& brush, float widest) {
  return brush.levels ? &brush.levels->for_width(2.f * std::max(widest, kMinDrawnHalfWidth)) : nullptr;
}

// The rows of a convex quad: where each line y = yc crosses it, from its edges' slopes
// worked out once.
class QuadRows {
 public:
  explicit QuadRows(const Vec2 (&corners)[4]) {
    for (int e = 0; e < 4; ++e) {
      const Vec2 p = corners[e], q = corners[(e + 1) % 4];
      Edge& edge = edges_[e];
      edge.y_lo = std::min(p.y, q.y), edge.y_hi = std::max(p.y, q.y);
      edge.x_at_lo = p.y <= q.y ? p.x : q.x;
      edge.slope = p.y == q.y ? 0.f : (q.x - p.x) / (q.y - p.y);
      edge.flat_hi = std::max(p.x, q.x);
      edge.flat = p.y == q.y;
    }
  }
  // x from *lo to *hi on row yc; false when the row misses the quad.
  bool span(float yc, float* lo, float* hi) const {
    *lo = std::numeric_limits<float>::max(), *hi = -std::numeric_limits<float>::max();
    for (const Edge& e : edges_) {
      if (yc < e.y_lo || yc > e.y_hi) continue;
      const float x = e.x_at_lo + (yc - e.y_lo) * e.slope;
      *lo = std::min(*lo, e.flat ? std::min(x, e.flat_hi) : x);
      *hi = std::max(*hi, e.flat ? e.flat_hi : x);
    }
    return *lo <= *hi;
  }

 private:
  struct Edge {
    float y_lo, y_hi, x_at_lo, slope, flat_hi;
    bool flat;
  };
  Edge edges_[4];
};

// The pixels whose nearest point on the line through a and b lies between them (from
// half a pixel before a open start, to half a pixel past b at an open end, where the
// stroke ends flat), within reach of the widest half width there.
void draw_slab(const StrokeSample& a, const StrokeSample& b, float vb, bool open_start, bool open_end,
               const Brush& brush, StrokeCoverage& coverage) {
  const Vec2 d = b.p - a.p;
  const float length = glm::length(d);
  if (!(length > kSamePointPx)) return;
  const Vec2 dir = d / length, normal(-dir.y, dir.x);
  const float widest = std::max({a.half_width, b.half_width, kMinDrawnHalfWidth});
  const float reach = widest + 0.5f;
  const float s0 = open_start ? -0.5f : 0.f, s1 = open_end ? length + 0.5f : length;
  const Vec2 corners[4] = {a.p + dir * s0 - normal * reach, a.p + dir * s1 - normal * reach,
                           a.p + dir * s1 + normal * reach, a.p + dir * s0 + normal * reach};
  float y_lo = corners[0].y, y_hi = corners[0].y;
  for (const Vec2& c : corners) y_lo = std::min(y_lo, c.y), y_hi = std::max(y_hi, c.y);
  const int y0 = std::max(int(std::ceil(y_lo - 0.5f)), coverage.y0());
  const int y1 = std::min(int(std::floor(y_hi - 0.5f)), coverage.y1());
  const AlphaTexture* texture = texture_for(brush, widest);
  const QuadRows rows(corners);
  for (int y = y0; y <= y1; ++y) {
    const float yc = float(y) + 0.5f;
    float x_lo, x_hi;
    if (!rows.span(yc, &x_lo, &x_hi)) continue;
    const int x0 = std::max(int(std::ceil(x_lo - 0.5f)), coverage.x0());
    const int x1 = std::min(int(std::floor(x_hi - 0.5f)), coverage.x1());
    for (int x = x0; x <= x1; ++x) {
      const Vec2 w = Vec2(float(x) + 0.5f, yc) - a.p;
      const float along = glm::dot(w, dir);
      // Half open, so a pixel on the line between two slabs is drawn by one.
      if (along < s0 || along > s1 || (!open_end && along == s1)) continue;
      const float across = glm::dot(w, normal);
      const float distance = std::abs(across);
      if (distance >= reach) continue;
      float flat = 1.f;
      if (open_start) flat *= std::clamp(along + 0.5f, 0.f, 1.f);
      if (open_end) flat *= std::clamp(length - along + 0.5f, 0.f, 1.f);
      cover_pixel(x, y, distance, across, flat, a, b, std::clamp(along / length, 0.f, 1.f), vb, brush,
                  texture, coverage);
    }
  }
}

// The round join at sample s, between the segments arriving along `in` and leaving
// along `out` (unit): the pixels past the end of the one and before the start of the
// other, on the outside of the turn. `whole`: a disc (a stroke of one point).
void draw_join(const StrokeSample& s, Vec2 in, Vec2 out, bool whole, const Brush& brush,
               StrokeCoverage& coverage) {
  const float reach = std::max(s.half_width, kMinDrawnHalfWidth) + 0.5f;
  const float turn_cosine = glm::dot(in, out);
  if (!whole && turn_cosine > 1.f - 1e-7f) return;  // straight on: the slabs meet
  Vec2 lo = s.p - reach, hi = s.p + reach;
  if (!whole && turn_cosine > 0.f) {
    // A turn under 90 degrees: the wedge lies within the quad of the vertex, the two
    // outer normals and where the tangents there meet.
    Vec2 n_in(-in.y, in.x), n_out(-out.y, out.x);
    if (glm::dot(n_in, out) > 0.f) n_in = -n_in;
    if (glm::dot(n_out, in) < 0.f) n_out = -n_out;
    const Vec2 mid = glm::normalize(n_in + n_out);
    const Vec2 tip = s.p + mid * (reach / std::max(glm::dot(mid, n_in), 0.5f));
    lo = glm::min(glm::min(s.p, tip), glm::min(s.p + n_in * reach, s.p + n_out * reach));
    hi = glm::max(glm::max(s.p, tip), glm::max(s.p + n_in * reach, s.p + n_out * reach));
  }
  const int x0 = std::max(int(std::ceil(lo.x - 0.5f)), coverage.x0());
  const int x1 = std::min(int(std::floor(hi.x - 0.5f)), coverage.x1());
  const int y0 = std::max(int(std::ceil(lo.y - 0.5f)), coverage.y0());
  const int y1 = std::min(int(std::floor(hi.y - 0.5f)), coverage.y1());
  const AlphaTexture* texture = texture_for(brush, s.half_width);
  const Vec2 right(-in.y, in.x);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const Vec2 w = Vec2(float(x) + 0.5f, float(y) + 0.5f) - s.p;
      if (!whole && (glm::dot(w, in) < 0.f || glm::dot(w, out) >= 0.f)) continue;
      const float distance = glm::length(w);
      if (distance >= reach) continue;
      const float across = glm::dot(w, right) < 0.f ? -distance : distance;
      cover_pixel(x, y, distance, across, 1.f, s, s, 0.f, s.v, brush, texture, coverage);
    }
  }
}

// Samples merge into one drawn segment while they stray from it by no more than
// these (pixels; opacity and colour), over at most kMaxMergedPx.
constexpr float kMergeTolerancePx = 0.05f;
constexpr float kMergeToleranceValue = 0.004f;
constexpr float kMaxMergedPx = 16.f;

// Whether `k` lies where the segment from a to b puts it, by its v: on the line, with
// the width, opacity and colour that segment interpolates there.
bool on_segment(const StrokeSample& a, const StrokeSample& b, const StrokeSample& k) {
  const float span = b.v - a.v;
  const float t = span > 0.f ? (k.v - a.v) / span : 0.f;
  const Vec2 off = k.p - glm::mix(a.p, b.p, t);
  const Color dc = glm::abs(k.color - glm::mix(a.color, b.color, t));
  return glm::dot(off, off) <= kMergeTolerancePx * kMergeTolerancePx &&
         std::abs(k.half_width - glm::mix(a.half_width, b.half_width, t)) <= kMergeTolerancePx &&
         std::abs(k.opacity - glm::mix(a.opacity, b.opacity, t)) <= kMergeToleranceValue &&
         std::max({dc.r, dc.g, dc.b}) <= kMergeToleranceValue;
}

// The samples the raster draws between: repeated points dropped, and runs of samples
// that one longer segment reproduces (on_segment) merged into it, up to kMaxMergedPx:
// fewer slabs and joins for straight stretches.
void merged_samples(const std::vector<StrokeSample>& samples, bool closed, std::vector<StrokeSample>& out) {
  std::vector<StrokeSample> in;
  in.reserve(samples.size());
  for (const StrokeSample& s : samples)
    if (in.empty() || glm::length(s.p - in.back().p) > kSamePointPx) in.push_back(s);
  if (closed)
    while (in.size() > 1 && glm::length(in.front().p - in.back().p) <= kSamePointPx) in.pop_back();
  out.clear();
  const size_t n = in.size();
  if (n == 0) return;
  out.push_back(in[0]);
  size_t i = 0;
  while (i + 1 < n) {
    size_t j = i + 1;
    while (j + 1 < n && in[j + 1].v - in[i].v <= kMaxMergedPx) {
      bool fits = true;
      for (size_t k = i + 1; k <= j && fits; ++k) fits = on_segment(in[i], in[j + 1], in[k]);
      if (!fits) break;
      ++j;
    }
    out.push_back(in[j]);
    i = j;
  }
}

void draw_stroke(const LineStroke& stroke, const RgbImage& image, BrushLevelCache& brushes,
                 std::vector<StrokeSample>& merged, StrokeCoverage& coverage) {
  const int width = image.width, height = image.height;
  merged_samples(stroke.samples, stroke.closed, merged);
  const std::vector<StrokeSample>& s = merged;
  const size_t n = s.size();
  if (n == 0) return;
  Vec2 lo = s.front().p, hi = lo;
  float widest = kMinDrawnHalfWidth;
  for (const StrokeSample& q : s)
    lo = glm::min(lo, q.p), hi = glm::max(hi, q.p), widest = std::max(widest, q.half_width);
  const float reach = widest + 1.f;
  const int x0 = std::max(int(std::floor(lo.x - reach)), 0),
            x1 = std::min(int(std::ceil(hi.x + reach)), width - 1);
  const int y0 = std::max(int(std::floor(lo.y - reach)), 0),
            y1 = std::min(int(std::ceil(hi.y + reach)), height - 1);
  if (x0 > x1 || y0 > y1) return;
  coverage.begin(x0, y0, x1, y1, image);

  const float length = stroke_length(stroke);
  Brush brush;
  if (stroke.brush && stroke.brush->width > 0 && stroke.brush->height > 0) {
    brush.levels = &brushes.levels_of(*stroke.brush);
    brush.variant = std::clamp(stroke.brush_variant, 0, stroke.brush->variants - 1);
    brush.v_start = s.front().v;
    brush.repeat = stroke.brush_repeat_px > 0.f;
    brush.v_scale = brush.repeat ? 1.f / stroke.brush_repeat_px : (length > 0.f ? 1.f / length : 0.f);
  }
  if (n == 1) {
    draw_join(s[0], Vec2(1.f, 0.f), Vec2(1.f, 0.f), true, brush, coverage);
    return;
  }
  const bool closed = stroke.closed && n > 2;
  const size_t segments = closed ? n : n - 1;
  auto direction = [&](size_t i) { return glm::normalize(s[(i + 1) % n].p - s[i].p); };
  for (size_t i = 0; i < segments; ++i) {
    const float vb = i + 1 < n ? s[i + 1].v : s.front().v + length;
    draw_slab(s[i], s[(i + 1) % n], vb, !closed && i == 0, !closed && i + 1 == segments, brush, coverage);
  }
  for (size_t i = closed ? 0 : 1; i < (closed ? n : n - 1); ++i)
    draw_join(s[i], direction((i + n - 1) % n), direction(i), false, brush, coverage);
}

}  // namespace

void draw_strokes(const std::vector<LineStroke>& strokes, const DisplayEncoding& display, RgbImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != size_t(image.width) * size_t(image.height))
    return;
  const DisplayMapping mapping(display);
  StrokeCoverage coverage;
  BrushLevelCache brushes;
  std::vector<StrokeSample> merged;
  for (const LineStroke& stroke : strokes) {
    draw_stroke(stroke, image, brushes, merged, coverage);
    coverage.composite(mapping, image);
  }
}

}  // namespace inkray
