#include "ui/panels/render_panel.h"

#include "core/document/param_text.h"
#include "ui/model/export_queue.h"
#include "ui/widgets/key_actions.h"
#include "ui/widgets/param_widgets.h"
#include "ui/widgets/widget_report.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace inkray {
namespace {

struct WidestLabel {
  float width = 0.f;
  template <class T>
  void operator()(const Param& p, T&) {
    width = std::max(width, ImGui::CalcTextSize(param_label(p).c_str()).x);
  }
};

// The widest label of the render settings, measured so their column never clips one.
float document_label_width() {
  WidestLabel widest;
  RenderSettings settings;
  visit_params(settings, widest);
  return widest.width;
}

// A column of labelled widgets: the widgets get what its labels leave.
void push_item_width(float label_width) {
  const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
  ImGui::PushItemWidth(std::clamp(ImGui::GetContentRegionAvail().x - label_width - spacing,
                                  ImGui::GetFontSize() * 5.f, ImGui::GetFontSize() * 14.f));
}

// The settings at the current frame, keyable like the properties panel's; editing an
// animated one keys it (ui/model/document.cpp).
void document_settings(EditorState& state, float label_width) {
  RenderSettings settings = state.shown().render;
  KeyTargets keys;
  keys.document = &state.document.scene();
  keys.report = state.report_params;
  ParamWidgets widgets;
  widgets.keys = &keys;
  widgets.key_item = Selection{ItemKind::render, -1};
  std::string param;
  push_item_width(label_width);
  if (edit_params(settings, &param, widgets)) {
    SceneDesc scene = state.document.scene();
    scene.render = settings;
    state.edit(std::move(scene), "Edit " + param, "render:" + param);
  }
  ImGui::PopItemWidth();
  apply_key_actions(state, keys);
}

constexpr const char* kViewportLabels[] = {"Samples per pixel", "Time limit", "Noise target"};

void viewport_limits(EditorState& state, const ProgressiveRenderer& renderer, float label_width) {
  push_item_width(label_width);
  ImGui::DragInt("Samples per pixel##viewport", &state.limits.spp, 1.f, 0, 1 << 20,
                 state.limits.spp == 0 ? "as the document" : "%d");
  float seconds = float(state.limits.time_seconds);
  if (ImGui::DragFloat("Time limit##viewport", &seconds, 0.5f, 0.f, 1e6f,
                       seconds == 0.f ? "as the document" : "%.1f s"))
    state.limits.time_seconds = std::max(seconds, 0.f);
  float percent = float(state.limits.noise_target * 100.0);
  if (ImGui::DragFloat("Noise target##viewport", &percent, 0.02f, 0.f, 50.f,
                       percent == 0.f ? "none" : "%.2f %% error"))
    state.limits.noise_target = std::clamp(percent, 0.f, 50.f) / 100.0;
  ImGui::PopItemWidth();
  ImGui::TextDisabled("%d render thread%s", renderer.threads(), renderer.threads() == 1 ? "" : "s");
}

void export_section(EditorState& state) {
  if (ImGui::Button("Export...")) state.want_export = true;
  widget_report::item("render.export");
  ExportQueue* queue = state.exports;
  if (!queue) return;
  ImGui::PushTextWrapPos(0.f);
  if (const ExportEntry* e = queue->running()) {
    const ExportProgress& p = e->progress;
    ImGui::Text("Exporting %s: %u / %u spp", e->request.output.filename().string().c_str(), p.spp,
                p.spp_target);
    char overlay[32];
    std::snprintf(overlay, sizeof overlay, "%.0f %%", double(p.fraction) * 100.0);
    ImGui::ProgressBar(p.fraction, ImVec2(-1.f, 0.f), overlay);
    if (ImGui::Button("Cancel export")) queue->cancel(e->id);
    widget_report::item("render.export_cancel");
    if (const int waiting = queue->queued(); waiting > 0) {
      ImGui::SameLine();
      ImGui::TextDisabled("%d more queued", waiting);
    }
  } else if (!queue->entries().empty()) {
    const ExportEntry& last = queue->entries().back();
    const char* how = last.state == ExportState::done     ? "wrote"
                      : last.state == ExportState::failed ? "failed:"
                                                          : "cancelled:";
    ImGui::TextDisabled("Last export %s %s", how, last.request.output.filename().string().c_str());
  }
  ImGui::PopTextWrapPos();
}

}  // namespace

void draw_render_panel(EditorState& state, const ProgressiveRenderer& renderer) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float document_labels = document_label_width();
  float viewport_labels = 0.f;
  for (const char* l : kViewportLabels) viewport_labels = std::max(viewport_labels, ImGui::CalcTextSize(l).x);
  // A column fits its labels and a widget of at least 8 characters; when the panel is
  // too narrow for three, Viewport and Export share one, then everything stacks.
  const float widget = ImGui::GetFontSize() * 8.f + style.ItemInnerSpacing.x + style.CellPadding.x * 2.f;
  const float document_w = document_labels + widget, viewport_w = viewport_labels + widget;
  const float export_w = ImGui::GetFontSize() * 16.f;
  const float avail = ImGui::GetContentRegionAvail().x;
  const int columns = avail >= document_w + viewport_w + export_w ? 3
                      : avail >= document_w + viewport_w          ? 2
                                                                  : 1;
  if (!ImGui::BeginTable("render_columns", columns, ImGuiTableFlags_BordersInnerV)) return;
  // Widths in proportion to what each column needs, so the spare width is shared fairly.
  const float weights[3] = {document_w, columns == 2 ? std::max(viewport_w, export_w) : viewport_w, export_w};
  for (int c = 0; c < columns; ++c)
    ImGui::TableSetupColumn(nullptr, ImGuiTableColumnFlags_WidthStretch, weights[c]);
  ImGui::TableNextColumn();
  ImGui::TextDisabled("Document");
  document_settings(state, document_labels);
  if (columns > 1)
    ImGui::TableNextColumn();
  else
    ImGui::Separator();
  ImGui::TextDisabled("Viewport");
  viewport_limits(state, renderer, viewport_labels);
  if (columns > 2)
    ImGui::TableNextColumn();
  else
    ImGui::Separator();
  ImGui::TextDisabled("Export");
  export_section(state);
  ImGui::EndTable();
}

}  // namespace inkray
