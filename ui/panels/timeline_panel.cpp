// The timeline's transport, frame fields and scrub bar; see timeline_panel.h.
#include "ui/panels/timeline_panel.h"

#include "core/document/animation_edit.h"
#include "ui/widgets/param_widgets.h"
#include "ui/model/scene_edits.h"
#include "ui/widgets/widget_report.h"

#include <imgui.h>

#include <cstdio>
#include <string>
#include <vector>

namespace inkray {
namespace {

enum class Icon { jump_start, step_back, play, pause, step_forward, jump_end };

// A button with a drawn icon (the font has no media symbols).
bool icon_button(const char* id, Icon icon, const char* tooltip) {
  const float h = ImGui::GetFrameHeight();
  const bool pressed = ImGui::Button(id, ImVec2(std::round(h * 1.3f), h));
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  const float cx = 0.5f * (lo.x + hi.x), cy = 0.5f * (lo.y + hi.y), s = h * 0.22f;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImU32 colour = ImGui::GetColorU32(ImGuiCol_Text);
  // Clockwise on screen, as ImGui's anti-aliasing expects.
  const auto right = [&](float x) {
    draw->AddTriangleFilled(ImVec2(x - 0.8f * s, cy - s), ImVec2(x + 0.8f * s, cy),
                            ImVec2(x - 0.8f * s, cy + s), colour);
  };
  const auto left = [&](float x) {
    draw->AddTriangleFilled(ImVec2(x + 0.8f * s, cy - s), ImVec2(x + 0.8f * s, cy + s),
                            ImVec2(x - 0.8f * s, cy), colour);
  };
  const auto bar = [&](float x, float half_width) {
    draw->AddRectFilled(ImVec2(x - half_width, cy - s), ImVec2(x + half_width, cy + s), colour);
  };
  const float thin = 0.18f * s;
  if (icon == Icon::jump_start) bar(cx - 1.1f * s, thin), left(cx + 0.2f * s);
  if (icon == Icon::step_back) left(cx - 0.3f * s), bar(cx + 0.8f * s, thin);
  if (icon == Icon::play) right(cx + 0.1f * s);
  if (icon == Icon::pause) bar(cx - 0.45f * s, 0.25f * s), bar(cx + 0.45f * s, 0.25f * s);
  if (icon == Icon::step_forward) bar(cx - 0.8f * s, thin), right(cx + 0.3f * s);
  if (icon == Icon::jump_end) right(cx - 0.2f * s), bar(cx + 1.1f * s, thin);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
  return pressed;
}

std::string frame_text(double frame) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", frame);
  return text;
}

// Frames between numbered ticks: 1, 2, 5, 10, 20, 50, ..., at least `min_px` apart.
double tick_step(double px_per_frame, double min_px) {
  for (double decade = 1.0; decade < 1e9; decade *= 10.0)
    for (double m : {1.0, 2.0, 5.0})
      if (decade * m * px_per_frame >= min_px) return decade * m;
  return 1e9;
}

void edit_range(EditorState& state, int start, int end, float fps, const char* label, const char* key) {
  SceneDesc scene = state.document.scene();
  scene.render.frame_start = start;
  scene.render.frame_end = end;
  scene.render.fps = fps;
  if (scene.render == state.document.scene().render) return;
  state.edit(std::move(scene), label, key);
}

void toolbar(EditorState& state) {
  const RenderSettings& r = state.document.scene().render;
  const float em = ImGui::GetFontSize();
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(0.2f * em, ImGui::GetStyle().ItemSpacing.y));
  if (icon_button("##jump_start", Icon::jump_start, "First frame of the shot (Shift+Left)"))
    jump_to_end(state, false);
  widget_report::item("timeline.jump_start");
  ImGui::SameLine();
  if (icon_button("##step_back", Icon::step_back, "Previous frame (Left)")) step_frame(state, -1);
  widget_report::item("timeline.step_back");
  ImGui::SameLine();
  if (icon_button("##play", state.playing ? Icon::pause : Icon::play,
                  state.playing ? "Pause (Space)" : "Play (Space)"))
    toggle_playback(state);
  widget_report::item("timeline.play");
  ImGui::SameLine();
  if (icon_button("##step_forward", Icon::step_forward, "Next frame (Right)")) step_frame(state, 1);
  widget_report::item("timeline.step_forward");
  ImGui::SameLine();
  if (icon_button("##jump_end", Icon::jump_end, "Last frame of the shot (Shift+Right)"))
    jump_to_end(state, true);
  widget_report::item("timeline.jump_end");
  ImGui::PopStyleVar();

  ImGui::SameLine(0.f, em);
  int frame = int(std::lround(r.frame));
  ImGui::SetNextItemWidth(3.5f * em);
  if (ImGui::DragInt("Frame", &frame, 0.2f, -1000000, 1000000)) state.document.set_frame(frame);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The current frame: what the viewport shows and keys are set at");
  widget_report::item("timeline.frame");

  ImGui::SameLine(0.f, em);
  int start = r.frame_start, end = r.frame_end;
  ImGui::SetNextItemWidth(3.5f * em);
  if (ImGui::DragInt("Start", &start, 0.2f, -1000000, 1000000))
    edit_range(state, start, std::max(end, start), r.fps, "Edit frame range", "timeline:start");
  widget_report::item("timeline.start");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(3.5f * em);
  if (ImGui::DragInt("End", &end, 0.2f, -1000000, 1000000))
    edit_range(state, std::min(start, end), end, r.fps, "Edit frame range", "timeline:end");
  widget_report::item("timeline.end");
  ImGui::SameLine();
  float fps = r.fps;
  ImGui::SetNextItemWidth(3.f * em);
  if (ImGui::DragFloat("FPS", &fps, 0.1f, 1.f, 240.f, "%.3g") && std::isfinite(fps))
    edit_range(state, start, end, std::clamp(fps, 0.001f, 1000.f), "Edit frame rate", "timeline:fps");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Frames per second of playback");
  widget_report::item("timeline.fps");
}

// The keys near x in one row, for the tooltip: "frame 12: objects/ball/transform/translate".
std::string keys_at(const SceneDesc& scene, std::string_view prefix, double frame) {
  std::string text = "Frame " + frame_text(frame) + ":";
  for (const TrackDesc& track : scene.animation) {
    if (track.target.compare(0, prefix.size(), prefix) != 0) continue;
    for (const KeyDesc& key : track.keys)
      if (key.frame == frame) text += "\n  " + track.target;
  }
  return text;
}

void scrub_bar(EditorState& state) {
  const SceneDesc& scene = state.document.scene();
  const RenderSettings& r = scene.render;
  const float em = ImGui::GetFontSize();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float w = std::max(avail.x, 8.f * em), h = std::max(avail.y, 2.5f * em);
  ImGui::InvisibleButton("scrub", ImVec2(w, h));
  widget_report::item("timeline.scrub");
  const bool hovered = ImGui::IsItemHovered(), active = ImGui::IsItemActive();

  // The frames in view: the shot, the current frame and every key, ten frames at least.
  const std::vector<double> all = key_frames(scene);
  const std::string prefix = key_path(scene, state.selection);
  const std::vector<double> selected = prefix.empty() ? std::vector<double>{} : key_frames(scene, prefix);
  double lo = std::min(double(r.frame_start), std::floor(double(r.frame)));
  double hi = std::max(double(r.frame_end), std::ceil(double(r.frame)));
  if (!all.empty()) lo = std::min(lo, all.front()), hi = std::max(hi, all.back());
  if (hi - lo < 10.0) hi = lo + 10.0;
  // The rows' names in a column of their own, left of the frames.
  const std::string item = item_name(scene, state.selection);
  const float names_w = std::min(
      std::max(ImGui::CalcTextSize("All").x, ImGui::CalcTextSize(item.c_str()).x) + 0.8f * em, 7.f * em);
  const float x0 = origin.x + names_w + em, x1 = origin.x + w - em;
  const double px_per_frame = (x1 - x0) / (hi - lo);
  const auto x_of = [&](double f) { return x0 + float((f - lo) * px_per_frame); };
  const ImVec2 mouse = ImGui::GetIO().MousePos;

  state.scrubbing = active;
  if (active) {
    const double f = std::clamp(std::round(lo + (mouse.x - x0) / px_per_frame), lo, hi);
    state.document.set_frame(f);
  }

  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float ruler_h = std::round(1.25f * em), top = origin.y + ruler_h;
  const float row_h = (h - ruler_h) * 0.5f;
  draw->AddRectFilled(origin, ImVec2(origin.x + w, origin.y + h), IM_COL32(28, 28, 31, 255));
  draw->AddRectFilled(ImVec2(x_of(r.frame_start), top),
                      ImVec2(x_of(std::max(r.frame_end, r.frame_start)), origin.y + h),
                      IM_COL32(44, 44, 50, 255));
  draw->AddRectFilled(origin, ImVec2(origin.x + w, top), IM_COL32(36, 36, 40, 255));
  draw->AddLine(ImVec2(origin.x, top + row_h), ImVec2(origin.x + w, top + row_h), IM_COL32(55, 55, 60, 255));

  // Ticks: numbered ones far enough apart for their numbers, unnumbered ones between.
  const double major = tick_step(px_per_frame, 3.0 * em);
  const double minor = major >= 5.0 ? major / 5.0 : major >= 2.0 ? major / 2.0 : major;
  const ImU32 text_colour = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  for (double f = std::ceil(lo / minor) * minor; f <= hi + 1e-9; f += minor) {
    const float x = std::round(x_of(f));
    const bool numbered = std::fmod(std::fabs(f), major) < 1e-6;
    draw->AddLine(ImVec2(x, top - (numbered ? 0.4f : 0.2f) * em), ImVec2(x, top), text_colour);
    if (!numbered) continue;
    draw->AddLine(ImVec2(x, top), ImVec2(x, origin.y + h), IM_COL32(50, 50, 56, 255));
    const std::string label = frame_text(f);
    const float tw = ImGui::CalcTextSize(label.c_str()).x;
    draw->AddText(ImVec2(x - 0.5f * tw, origin.y + 0.05f * em), text_colour, label.c_str());
  }

  // The rows' names, then their keys: every key, and the selected item's.
  draw->AddRectFilled(ImVec2(origin.x, top), ImVec2(origin.x + names_w, origin.y + h),
                      IM_COL32(34, 34, 38, 255));
  draw->PushClipRect(ImVec2(origin.x, top), ImVec2(origin.x + names_w - 0.2f * em, origin.y + h), true);
  const ImU32 name_colour = IM_COL32(150, 150, 158, 255);
  draw->AddText(ImVec2(origin.x + 0.4f * em, top + 0.5f * (row_h - em)), name_colour, "All");
  if (!item.empty())
    draw->AddText(ImVec2(origin.x + 0.4f * em, top + row_h + 0.5f * (row_h - em)), name_colour, item.c_str());
  draw->PopClipRect();
  const float radius = std::min(0.35f * em, 0.32f * row_h);
  const float all_y = top + 0.5f * row_h, selected_y = top + 1.5f * row_h;
  for (double f : all)
    draw_key_diamond(draw, x_of(f), all_y, radius, IM_COL32(190, 190, 196, 255), IM_COL32(20, 20, 20, 255));
  for (double f : selected)
    draw_key_diamond(draw, x_of(f), selected_y, radius, kKeyFill, IM_COL32(20, 20, 20, 255));
  if (all.empty())
    draw->AddText(ImVec2(x_of(lo) + 2.5f * em, top + 0.5f * (row_h - em)), IM_COL32(110, 110, 118, 255),
                  "No keys yet: I over a field keys it at this frame");

  // The current frame, over everything.
  const float fx = std::round(x_of(r.frame));
  const ImU32 blue = IM_COL32(70, 130, 230, 255);
  draw->AddLine(ImVec2(fx, top), ImVec2(fx, origin.y + h), blue, 2.f);
  const std::string label = frame_text(r.frame);
  const float tw = ImGui::CalcTextSize(label.c_str()).x;
  draw->AddRectFilled(ImVec2(fx - 0.5f * tw - 0.3f * em, origin.y), ImVec2(fx + 0.5f * tw + 0.3f * em, top),
                      blue, 3.f);
  draw->AddText(ImVec2(fx - 0.5f * tw, origin.y + 0.05f * em), IM_COL32(255, 255, 255, 255), label.c_str());

  if (hovered && !active && mouse.y > top) {
    const bool lower = mouse.y > top + row_h;
    for (double f : lower ? selected : all) {
      if (std::fabs(x_of(f) - mouse.x) > radius + 2.f) continue;
      ImGui::SetTooltip("%s", keys_at(scene, lower ? prefix : std::string_view(), f).c_str());
      break;
    }
  }
}

}  // namespace

void toggle_playback(EditorState& state) { state.playing = !state.playing; }

void step_frame(EditorState& state, int frames) {
  state.document.set_frame(std::round(double(state.document.scene().render.frame)) + frames);
}

void jump_to_end(EditorState& state, bool last) {
  const RenderSettings& r = state.document.scene().render;
  state.document.set_frame(last ? r.frame_end : r.frame_start);
}

void jump_to_key(EditorState& state, int direction) {
  const double frame = state.document.scene().render.frame;
  const std::vector<double> frames = key_frames(state.document.scene());
  if (direction > 0) {
    const auto next = std::upper_bound(frames.begin(), frames.end(), frame);
    if (next != frames.end()) state.document.set_frame(*next);
  } else {
    const auto at = std::lower_bound(frames.begin(), frames.end(), frame);
    if (at != frames.begin()) state.document.set_frame(*std::prev(at));
  }
}

void draw_timeline_panel(EditorState& state) {
  toolbar(state);
  scrub_bar(state);
}

}  // namespace inkray
