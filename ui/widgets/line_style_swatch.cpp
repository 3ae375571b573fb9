#include "ui/widgets/line_style_swatch.h"

#include "ui/model/line_style_sample.h"
#include "ui/widgets/fonts.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace inkray {
namespace {

// Swatch pixels per pixel of a 1080-line image at UI scale 1: a little larger than
// life, so a pencil's wobble and a dash's gap read at this size.
constexpr float kSwatchScale = 1.5f;
// Columns across a brushed stroke, where the brush's coverage is read.
constexpr int kBrushColumns = 10;

ImU32 colour_of(const Color& c, float alpha) {
  const auto channel = [](float v) { return std::clamp(v, 0.f, 1.f); };
  return ImGui::ColorConvertFloat4ToU32(ImVec4(channel(c.r), channel(c.g), channel(c.b), channel(alpha)));
}

// The paper under the strokes: light under dark lines, dark under light ones.
Color paper_for(const Color& line) {
  const float luminance = 0.2126f * line.r + 0.7152f * line.g + 0.0722f * line.b;
  return luminance > 0.6f ? Color(0.16f, 0.16f, 0.18f) : Color(0.96f, 0.95f, 0.9f);
}

// One stroke as a strip across its samples. Its columns run across it at `across` (-1
// its left side, 1 its right; a solid line has its two sides only), and one more each
// side fades to nothing over a pixel, for edges without steps.
void draw_stroke(ImDrawList* draw, const ImVec2& origin, const LineSetStyleDesc& style,
                 const LineStroke& stroke, float fade) {
  const std::vector<StrokeSample>& samples = stroke.samples;
  if (samples.size() < 2) return;
  const bool brushed = style.brush == LineBrush::bristle || style.brush == LineBrush::flat;
  std::vector<float> across;
  if (brushed) {
    for (int c = 0; c <= kBrushColumns; ++c) across.push_back(2.f * float(c) / kBrushColumns - 1.f);
  } else {
    across = {-1.f, 1.f};
  }
  const int columns = int(across.size()) + 2;  // and the two soft edges
  const int rows = int(samples.size());
  const ImVec2 white = ImGui::GetFontTexUvWhitePixel();
  draw->PrimReserve((rows - 1) * (columns - 1) * 6, rows * columns);
  const unsigned first = draw->_VtxCurrentIdx;
  for (int i = 0; i < rows; ++i) {
    const StrokeSample& s = samples[size_t(i)];
    const Vec2 ahead = samples[size_t(std::min(i + 1, rows - 1))].p - samples[size_t(std::max(i - 1, 0))].p;
    const float length = glm::length(ahead);
    // The left of the way the stroke runs, in y-down pixels.
    const Vec2 left = length > 0.f ? Vec2(ahead.y, -ahead.x) / length : Vec2(0.f, -1.f);
    // A line thinner than a pixel is drawn a pixel wide, fainter.
    const float half = std::max(s.half_width - 0.5f, 0.f);
    const float thin = std::min(2.f * s.half_width, 1.f);
    const auto vertex = [&](float offset, float alpha) {
      const Vec2 p = s.p - left * offset;
      draw->PrimWriteVtx(ImVec2(origin.x + p.x, origin.y + p.y), white, colour_of(s.color, alpha));
    };
    const float opacity = s.opacity * thin * fade;
    vertex(-(half + 1.f), 0.f);
    for (float a : across) {
      const float u = 0.5f * (a + 1.f);
      vertex(a * half, opacity * (brushed ? sample_brush_alpha(style, stroke, u, s.v) : 1.f));
    }
    vertex(half + 1.f, 0.f);
  }
  for (int i = 0; i + 1 < rows; ++i) {
    for (int c = 0; c + 1 < columns; ++c) {
      const unsigned a = first + unsigned(i * columns + c), b = a + 1, d = a + unsigned(columns), e = d + 1;
      for (unsigned index : {a, b, e, a, e, d}) draw->PrimWriteIdx(ImDrawIdx(index));
    }
  }
}

}  // namespace

void draw_line_style_swatch(ImDrawList* draw, const ImVec2& lo, const ImVec2& hi,
                            const LineSetStyleDesc& style, bool dimmed) {
  const float rounding = 0.15f * (hi.y - lo.y);
  const Color paper = paper_for(style.color);
  draw->AddRectFilled(lo, hi, colour_of(paper, dimmed ? 0.35f : 1.f), rounding);
  draw->PushClipRect(lo, hi, true);
  const float scale = kSwatchScale * ui_scale_of_font();
  for (const LineStroke& stroke : sample_strokes(style, hi.x - lo.x, hi.y - lo.y, scale))
    draw_stroke(draw, lo, style, stroke, dimmed ? 0.35f : 1.f);
  draw->PopClipRect();
}

}  // namespace inkray
