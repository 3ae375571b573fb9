#include "ui/render_panel.h"

#include "ui/param_widgets.h"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace inkray {
namespace {

void document_settings(EditorState& state) {
  RenderSettings settings = state.document.scene().render;
  std::string param;
  ImGui::PushItemWidth(160.f);
  if (edit_params(settings, &param)) {
    SceneDesc scene = state.document.scene();
    scene.render = settings;
    state.edit(std::move(scene), "Edit " + param, "render:" + param);
  }
  ImGui::PopItemWidth();
}

void viewport_limits(EditorState& state, const ProgressiveRenderer& renderer) {
  ImGui::PushItemWidth(160.f);
  ImGui::DragInt("viewport spp", &state.limits.spp, 1.f, 0, 1 << 20, state.limits.spp == 0 ? "document" : "%d");
  float seconds = float(state.limits.time_seconds);
  if (ImGui::DragFloat("time limit (s)", &seconds, 0.5f, 0.f, 1e6f, seconds == 0.f ? "document" : "%.1f")) state.limits.time_seconds = seconds;
  float noise = float(state.limits.noise_target);
  if (ImGui::DragFloat("noise target", &noise, 0.001f, 0.f, 1.f, "%.4f")) state.limits.noise_target = noise;
  ImGui::PopItemWidth();
  ImGui::TextDisabled("viewport threads: %d", renderer.threads());
}

void export_section(EditorState& state) {
  ExportSettings& e = state.export_settings;
  ImGui::PushItemWidth(220.f);
  ImGui::InputText("output (.png/.exr/.pfm)", &e.output);
  ImGui::PopItemWidth();
  ImGui::PushItemWidth(120.f);
  ImGui::DragInt("export spp", &e.spp, 1.f, 1, 1 << 20);
  ImGui::SameLine();
  ImGui::DragFloat("export time (s)", &e.time_limit, 0.5f, 0.f, 1e6f, "%.1f");
  ImGui::PopItemWidth();
  ImGui::TextUnformatted("AOVs:");
  for (size_t i = 0; i < kAovNames.size(); ++i) {
    ImGui::SameLine();
    bool on = e.aovs[i];
    if (ImGui::Checkbox(std::string(kAovNames[i]).c_str(), &on)) e.aovs[i] = on;
  }
  const bool running = state.export_job && !state.export_job->done();
  if (running) {
    ImGui::ProgressBar(state.export_job->progress(), ImVec2(240.f, 0.f));
    ImGui::SameLine();
    if (ImGui::Button("Cancel export")) state.export_job->cancel();
  } else if (ImGui::Button("Export render...")) {
    state.want_export = true;
  }
}

}  // namespace

void draw_render_panel(EditorState& state, const ProgressiveRenderer& renderer) {
  if (ImGui::BeginTable("render_columns", 3, ImGuiTableFlags_BordersInnerV)) {
    ImGui::TableNextColumn();
    ImGui::TextDisabled("Document");
    document_settings(state);
    ImGui::TableNextColumn();
    ImGui::TextDisabled("Viewport");
    viewport_limits(state, renderer);
    ImGui::TableNextColumn();
    ImGui::TextDisabled("Export");
    export_section(state);
    ImGui::EndTable();
  }
}

}  // namespace inkray
