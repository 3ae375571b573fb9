#include "ui/panels/export_dialog.h"

#include "ui/widgets/widget_report.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace inkray {
namespace {

namespace fs = std::filesystem;

const ImVec4 kErrorColor(1.f, 0.4f, 0.35f, 1.f);

// "42 s", "3:05", "1:02:03".
std::string clock_text(double seconds) {
  const long s = std::lround(std::max(seconds, 0.0));
  char text[32];
  if (s < 60)
    std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  return text;
}

// A row of the dialog's two-column table: the label, then the cursor in the widget column.
void row(const char* label) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(label);
  ImGui::TableNextColumn();
}

}  // namespace

void ExportUi::open_dialog(const EditorState& state) {
  const SceneDesc& scene = state.document.scene();
  if (form_.output.empty() || state.document.file() != form_scene_) {
    form_scene_ = state.document.file();
    form_.output = default_export_path(form_scene_).string();
    form_.spp = std::max(scene.render.spp, 1);
    form_.time_seconds = scene.render.time_limit;
  }
  scene_width_ = form_.width = scene.render.width;
  scene_height_ = form_.height = scene.render.height;
  dialog_open_ = focus_dialog_ = true;
}

uint64_t ExportUi::start_for_test(EditorState& state, const fs::path& output) {
  open_dialog(state);
  form_.output = output.string();
  return start(state);
}

uint64_t ExportUi::start(EditorState& state) {
  check_ = check_export_form(form_, state.document.file());
  if (!check_.error.empty()) return 0;
  ExportRequest request = make_export_request(form_, check_, state.document.scene());
  const auto [width, height] = export_resolution(request);
  state.log.info("export queued: " + check_.output.string() + " at " + std::to_string(width) + " x " +
                 std::to_string(height) + ", " + std::to_string(request.spp) + " spp, " +
                 std::to_string(request.threads) + " threads");
  const uint64_t id = queue_.add(std::move(request), form_.keep_viewport);
  dialog_open_ = false;
  progress_open_ = true;
  return id;
}

void ExportUi::draw(EditorState& state) {
  state.exports = &queue_;
  for (const uint64_t id : queue_.poll()) {
    const ExportEntry& e = *queue_.find(id);
    if (e.state == ExportState::done) {
      for (const fs::path& f : e.written) state.log.info("wrote " + f.string());
      image_view_.open(e.written);
    } else if (e.state == ExportState::cancelled) {
      state.log.info("export cancelled: " + e.request.output.string());
    } else {
      state.log.error("export " + e.request.output.string() + ": " + e.error);
    }
  }
  draw_dialog(state);
  draw_progress();
  image_view_.draw();
}

void ExportUi::draw_dialog(EditorState& state) {
  if (!dialog_open_) return;
  if (focus_dialog_) ImGui::SetNextWindowFocus(), focus_dialog_ = false;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(viewport->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::Begin("Export render", &dialog_open_,
                    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  check_ = check_export_form(form_, state.document.file());
  // Fixed columns: the window fits its content, which a stretching column would chase.
  if (ImGui::BeginTable("export_form", 2, ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupColumn("label", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn(
        "value", ImGuiTableColumnFlags_WidthFixed,
        std::min(ImGui::GetFontSize() * 30.f, ImGui::GetMainViewport()->WorkSize.x * 0.6f));
    output_row();
    limits_rows();
    resolution_row();
    ImGui::EndTable();
  }
  ImGui::Checkbox("Keep the viewport rendering (one thread)", &form_.keep_viewport);
  ImGui::TextDisabled(form_.keep_viewport
                          ? "The export renders on %d of %d threads; the viewport keeps going."
                          : "The export renders on all %d of %d threads; the viewport pauses until it ends.",
                      export_threads(form_.keep_viewport), export_threads(false));
  ImGui::Separator();
  ImGui::BeginDisabled(!check_.error.empty());
  if (ImGui::Button("Start", ImVec2(ImGui::GetFontSize() * 6.f, 0.f))) {
    if (check_.existing.empty())
      start(state);
    else
      ask_overwrite_ = true;
  }
  widget_report::item("export.start");
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Close", ImVec2(ImGui::GetFontSize() * 6.f, 0.f))) dialog_open_ = false;
  if (queue_.running()) {
    const int ahead = queue_.queued() + 1;
    ImGui::SameLine();
    ImGui::TextDisabled("queued behind %d export%s", ahead, ahead > 1 ? "s" : "");
  }
  draw_overwrite_popup(state);
  fs::path chosen;
  if (file_dialog_.draw(&chosen)) form_.output = chosen.string();
  ImGui::End();
}

void ExportUi::output_row() {
  row("Output");
  const float browse = ImGui::CalcTextSize("...").x + ImGui::GetStyle().FramePadding.x * 2.f;
  ImGui::SetNextItemWidth(-(browse + ImGui::GetStyle().ItemSpacing.x));
  ImGui::InputText("##output", &form_.output);
  widget_report::item("export.output");
  ImGui::SameLine();
  if (ImGui::Button("...")) {
    const fs::path start = check_.output.empty() ? default_export_path(form_scene_) : check_.output;
    file_dialog_.open("Export to", FileDialog::Mode::save, {".png", ".exr", ".pfm"}, start);
  }
  widget_report::item("export.browse");
  row("Format");
  if (!check_.error.empty()) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + ImGui::GetContentRegionAvail().x);
    ImGui::TextColored(kErrorColor, "%s", check_.error.c_str());
    ImGui::PopTextWrapPos();
  } else {
    ImGui::TextUnformatted(check_.format.c_str());
  }
  row("AOVs");
  ImGui::TextDisabled("written beside the image as <name>_<aov>");
  // As many columns as fit, so the names never clip.
  float widest = 0.f;
  for (std::string_view n : kAovNames)
    widest = std::max(widest, ImGui::CalcTextSize(n.data(), n.data() + n.size()).x);
  const float cell = widest + ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x * 2.f + 8.f;
  const int columns = std::max(1, int(ImGui::GetContentRegionAvail().x / cell));
  if (ImGui::BeginTable("aovs", columns)) {
    for (size_t i = 0; i < kAovNames.size(); ++i) {
      ImGui::TableNextColumn();
      bool on = form_.aovs[i];
      if (ImGui::Checkbox(std::string(kAovNames[i]).c_str(), &on)) form_.aovs[i] = on;
    }
    ImGui::EndTable();
  }
}

void ExportUi::limits_rows() {
  row("Samples per pixel");
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.f);
  ImGui::DragInt("##spp", &form_.spp, 1.f, 1, 1 << 20);
  form_.spp = std::max(form_.spp, 1);
  row("Time limit");
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.f);
  ImGui::DragFloat("##time", &form_.time_seconds, 0.5f, 0.f, 1e7f,
                   form_.time_seconds > 0.f ? "%.1f s" : "none");
  form_.time_seconds = std::max(form_.time_seconds, 0.f);
  row("Noise target");
  float percent = form_.noise_target * 100.f;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.f);
  if (ImGui::DragFloat("##noise", &percent, 0.02f, 0.f, 50.f, percent > 0.f ? "%.2f %% error" : "none"))
    form_.noise_target = std::clamp(percent, 0.f, 50.f) / 100.f;
  ImGui::SameLine();
  ImGui::TextDisabled("stops at the first limit met; tiles below it stop early");
  row("Denoise");
  ImGui::Checkbox("##denoise", &form_.denoise);
  widget_report::item("export.denoise");
  ImGui::SameLine();
  ImGui::TextDisabled(form_.denoise ? "lines and bands stay crisp; also writes <name>_raw"
                                    : "off: the image as rendered");
  row("Lines as vectors");
  ImGui::Checkbox("SVG##lines_svg", &form_.lines_svg);
  widget_report::item("export.lines_svg");
  ImGui::SameLine();
  ImGui::Checkbox("PDF##lines_pdf", &form_.lines_pdf);
  widget_report::item("export.lines_pdf");
  ImGui::SameLine();
  ImGui::TextDisabled("<name>.svg / .pdf: a layer per line set, mirrors and glass included");
}

void ExportUi::resolution_row() {
  row("Resolution");
  const double aspect = double(scene_width_) / double(std::max(scene_height_, 1));
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.f);
  if (ImGui::DragInt("##width", &form_.width, 1.f, 1, 16384) && keep_aspect_)
    form_.height = std::clamp(int(std::lround(form_.width / aspect)), 1, 16384);
  ImGui::SameLine();
  ImGui::TextUnformatted("x");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.f);
  if (ImGui::DragInt("##height", &form_.height, 1.f, 1, 16384) && keep_aspect_)
    form_.width = std::clamp(int(std::lround(form_.height * aspect)), 1, 16384);
  form_.width = std::clamp(form_.width, 1, 16384);
  form_.height = std::clamp(form_.height, 1, 16384);
  ImGui::SameLine();
  ImGui::Checkbox("Keep aspect", &keep_aspect_);
  if (form_.width != scene_width_ || form_.height != scene_height_) {
    ImGui::SameLine();
    if (ImGui::Button("Scene's")) form_.width = scene_width_, form_.height = scene_height_;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back to the scene's %d x %d", scene_width_, scene_height_);
  }
}

void ExportUi::draw_overwrite_popup(EditorState& state) {
  if (ask_overwrite_) ImGui::OpenPopup("Replace files?"), ask_overwrite_ = false;
  if (!ImGui::BeginPopupModal("Replace files?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::TextUnformatted("These files exist and will be replaced:");
  for (const fs::path& f : check_.existing) ImGui::BulletText("%s", f.string().c_str());
  if (ImGui::Button("Replace", ImVec2(ImGui::GetFontSize() * 6.f, 0.f))) {
    start(state);
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel", ImVec2(ImGui::GetFontSize() * 6.f, 0.f))) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

void ExportUi::draw_progress() {
  if (!progress_open_ || queue_.entries().empty()) return;
  // Top right, clear of the dialog and the image view, which open in the middle.
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(
      ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 20.f, viewport->WorkPos.y + 40.f),
      ImGuiCond_FirstUseEver, ImVec2(1.f, 0.f));
  ImGui::SetNextWindowSize(ImVec2(std::min(ImGui::GetFontSize() * 30.f, viewport->WorkSize.x - 40.f), 0.f),
                           ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Exports", &progress_open_)) {
    ImGui::End();
    return;
  }
  if (const ExportEntry* e = queue_.running()) {
    const ExportProgress& p = e->progress;
    ImGui::Text("Exporting %s", e->request.output.filename().string().c_str());
    if (p.width > 0) {
      ImGui::SameLine();
      ImGui::TextDisabled("%d x %d on %d threads", p.width, p.height, p.threads);
    }
    if (ImGui::BeginTable("figures", 2, ImGuiTableFlags_SizingFixedFit)) {
      const auto figure = [](const char* label, const std::string& value) {
        ImGui::TableNextColumn();
        ImGui::TextDisabled("%s", label);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(value.c_str());
      };
      figure("Samples", std::to_string(p.spp) + " / " + std::to_string(p.spp_target));
      figure("Elapsed", clock_text(p.elapsed_seconds));
      const char* phase = p.phase == ExportPhase::compiling ? "building the scene"
                          : p.phase == ExportPhase::writing ? "writing files"
                                                            : nullptr;
      figure("Remaining", phase ? phase : p.eta_seconds < 0.0 ? "estimating" : clock_text(p.eta_seconds));
      char error[64];
      if (p.relative_error > 0.0)
        std::snprintf(error, sizeof error, "%.2f %%", p.relative_error * 100.0);
      else
        std::snprintf(error, sizeof error, "after two samples");
      std::string error_text = error;
      if (e->request.noise_target > 0.0) {
        std::snprintf(error, sizeof error, " (target %.2f %%)", e->request.noise_target * 100.0);
        error_text += error;
      }
      figure("Noise", error_text + " raw");
      if (p.denoised_error > 0.0) {
        std::snprintf(error, sizeof error, "%.2f %% denoised", p.denoised_error * 100.0);
        figure("", error);
      }
      ImGui::EndTable();
    }
    ImGui::ProgressBar(p.fraction, ImVec2(-1.f, 0.f));
    if (ImGui::Button("Cancel")) queue_.cancel(e->id);
    widget_report::item("export.cancel");
    ImGui::Separator();
  }
  if (ImGui::BeginTable("queue", 3, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) {
    for (const ExportEntry& e : queue_.entries()) {
      if (e.state == ExportState::running) continue;  // shown above
      ImGui::PushID(int(e.id));
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(e.request.output.filename().string().c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.request.output.string().c_str());
      ImGui::TableNextColumn();
      if (e.state == ExportState::failed) {
        ImGui::PushTextWrapPos(0.f);
        ImGui::TextColored(kErrorColor, "failed: %s", e.error.c_str());
        ImGui::PopTextWrapPos();
      } else if (e.state == ExportState::done) {
        ImGui::Text("done, %u spp in %s", e.progress.spp, clock_text(e.progress.elapsed_seconds).c_str());
      } else {
        ImGui::TextUnformatted(kExportStateNames[size_t(e.state)]);
      }
      ImGui::TableNextColumn();
      if (e.state == ExportState::queued && ImGui::SmallButton("Cancel")) queue_.cancel(e.id);
      if (e.state == ExportState::done && ImGui::SmallButton("View")) image_view_.open(e.written);
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
  if (!queue_.running() && ImGui::Button("Clear finished")) queue_.clear_finished();
  ImGui::End();
}

}  // namespace inkray
