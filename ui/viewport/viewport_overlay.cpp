#include "ui/viewport/viewport_overlay.h"

#include "ui/widgets/fonts.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace inkray {
namespace {

// log10 of the relative error against seconds, with labelled axes: straight lines for
// 1/sqrt(n) convergence at a steady rate. `at` is the top left of the plot's box, which
// is kErrorPlotHeight + two text lines tall, kept small to leave the image visible.
constexpr float kErrorPlotHeight = 44.f;  // at UI scale 1

void error_plot(ImDrawList* draw, const std::vector<ErrorSample>& curve, ImVec2 at, float width) {
  const float ui = ui_scale_of_font();
  const float kLeft = 30.f * ui;  // room for the error's tick labels
  const ImU32 axis_colour = IM_COL32(160, 160, 160, 255), label_colour = IM_COL32(210, 210, 210, 255);
  const float line_h = ImGui::GetTextLineHeight();
  const ImVec2 p0(at.x + kLeft, at.y + 0.5f * line_h),
      p1(at.x + width, at.y + 0.5f * line_h + kErrorPlotHeight * ui);
  double t_max = 0.0, lo = 1e9, hi = -1e9;
  for (const ErrorSample& e : curve) {
    t_max = std::max(t_max, e.seconds);
    if (!(e.relative_error > 0.0)) continue;  // no estimate yet
    const double v = std::log10(e.relative_error);
    lo = std::min(lo, v), hi = std::max(hi, v);
  }
  if (lo > hi) lo = -2.0, hi = -1.0;
  lo = std::floor(lo), hi = std::max(std::ceil(hi), lo + 1.0);
  t_max = std::max(t_max, 1e-3);
  const auto px = [&](double t) { return p0.x + float(t / t_max) * (p1.x - p0.x); };
  const auto py = [&](double v) { return p1.y - float((v - lo) / (hi - lo)) * (p1.y - p0.y); };
  draw->AddLine(ImVec2(p0.x, p0.y), ImVec2(p0.x, p1.y), axis_colour);
  draw->AddLine(ImVec2(p0.x, p1.y), ImVec2(p1.x, p1.y), axis_colour);
  // The error falls from the top left, so its title sits top right, clear of the curve.
  const char* y_title = "log10 relative error";
  draw->AddText(ImVec2(p1.x - ImGui::CalcTextSize(y_title).x, p0.y), label_colour, y_title);
  char text[32];
  const int decade_step = hi - lo > 3.0 ? 2 : 1;
  for (int d = int(lo); d <= int(hi); d += decade_step) {
    const float y = py(d);
    draw->AddLine(ImVec2(p0.x - 3.f, y), ImVec2(p0.x, y), axis_colour);
    std::snprintf(text, sizeof text, "%d", d);
    draw->AddText(ImVec2(p0.x - 5.f - ImGui::CalcTextSize(text).x, y - 0.5f * line_h), label_colour, text);
  }
  // Seconds at both ends, the axis title between them.
  for (const double t : {0.0, t_max}) {
    const float x = px(t);
    draw->AddLine(ImVec2(x, p1.y), ImVec2(x, p1.y + 3.f), axis_colour);
    std::snprintf(text, sizeof text, t_max >= 10.0 ? "%.0f" : "%.1f", t);
    const float w = ImGui::CalcTextSize(text).x;
    draw->AddText(ImVec2(std::clamp(x - 0.5f * w, p0.x, p1.x - w), p1.y + 3.f), label_colour, text);
  }
  const char* x_title = "time (s)";
  draw->AddText(ImVec2(0.5f * (p0.x + p1.x) - 0.5f * ImGui::CalcTextSize(x_title).x, p1.y + 3.f),
                label_colour, x_title);
  std::vector<ImVec2> points;
  points.reserve(curve.size());
  for (const ErrorSample& e : curve) {
    if (e.relative_error > 0.0) points.emplace_back(px(e.seconds), py(std::log10(e.relative_error)));
  }
  draw->AddPolyline(points.data(), int(points.size()), IM_COL32(120, 200, 255, 255), 0, 1.5f);
}

}  // namespace

void draw_problems_overlay(const std::vector<std::string>& problems, float x, float y, float w) {
  std::string text = "This scene cannot render until this is mended:";
  constexpr size_t kShown = 6;
  for (size_t i = 0; i < problems.size() && i < kShown; ++i) text += "\n" + problems[i];
  if (problems.size() > kShown)
    text += "\n... and " + std::to_string(problems.size() - kShown) + " more (see the log)";
  const float wrap = std::max(w - 28.f, 200.f);
  const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(ImVec2(x + 6, y + 6), ImVec2(x + 18 + size.x, y + 16 + size.y),
                      IM_COL32(90, 20, 20, 220), 4.f);
  draw->AddText(nullptr, 0.f, ImVec2(x + 12, y + 11), IM_COL32(255, 230, 220, 255), text.c_str(), nullptr,
                wrap);
}

void draw_stats_overlay(const ViewportSnapshot& s, float x, float y) {
  const RenderStats& st = s.stats;
  const double rays_per_s = st.elapsed_seconds > 0 ? double(st.rays) / st.elapsed_seconds : 0.0;
  char text[320];
  std::snprintf(text, sizeof text, "%s%u spp  %u passes  %.1f s\n%.2f Mrays/s  error %.2f%% raw%s",
                s.divisor > 1 ? "preview 1/" : "", st.spp, st.passes, st.elapsed_seconds, rays_per_s * 1e-6,
                st.relative_error * 100.0, s.finished ? "  (done)" : "");
  if (s.denoised)
    std::snprintf(text + std::strlen(text), sizeof text - std::strlen(text),
                  "\ndenoised at %u spp: error %.2f%%", s.denoised_spp, s.denoised_error * 100.0);
  if (st.tiles > 0 && st.active_tiles < st.tiles)
    std::snprintf(text + std::strlen(text), sizeof text - std::strlen(text),
                  "\nadaptive: %u of %u tiles sampling", st.active_tiles, st.tiles);
  if (s.divisor > 1) {
    std::snprintf(text, sizeof text, "preview 1/%d  %.1f s", s.divisor, st.elapsed_seconds);
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 size = ImGui::CalcTextSize(text);
  const float width = std::max(size.x, 180.f * ui_scale_of_font());  // narrow: the image matters more
  const bool plot = s.error_curve.size() >= 2;
  const float plot_h =
      plot ? kErrorPlotHeight * ui_scale_of_font() + 6.f + 2.f * ImGui::GetTextLineHeight() : 0.f;
  draw->AddRectFilled(ImVec2(x + 6, y + 6), ImVec2(x + 14 + width, y + 16 + size.y + plot_h),
                      IM_COL32(0, 0, 0, 150), 4.f);
  draw->AddText(ImVec2(x + 10, y + 10), IM_COL32(235, 235, 235, 255), text);
  if (plot) error_plot(draw, s.error_curve, ImVec2(x + 10, y + 14 + size.y), width - 6.f);
}

}  // namespace inkray
