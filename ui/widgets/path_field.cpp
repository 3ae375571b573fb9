#include "ui/widgets/path_field.h"

#include "core/document/param_text.h"
#include "ui/widgets/file_dialog.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <string_view>
#include <vector>

namespace inkray {
namespace {

// One dialog serves every path field: ImGui shows one modal at a time, and the
// field that opened it (by ImGui id) is the one that takes the chosen file.
struct Browser {
  FileDialog dialog;
  ImGuiID field = 0;
};
Browser& browser() {
  static Browser instance;
  return instance;
}

}  // namespace

bool path_field(const char* label, const Param& p, std::string* value,
                const std::filesystem::path& scene_dir) {
  ImGui::PushID(label);
  const ImGuiID id = ImGui::GetID("browse");
  const float button = ImGui::GetFrameHeight() * 1.4f;
  const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
  ImGui::SetNextItemWidth(std::max(ImGui::CalcItemWidth() - button - spacing, 40.f));
  std::string edited = *value;
  bool changed = ImGui::InputText("##path", &edited) && edited != *value;
  if (ImGui::IsItemHovered() && ImGui::GetIO().MouseDownDuration[0] < 0.f) {
    ImGui::SetTooltip("%s", param_tooltip(p, false).c_str());
  }
  ImGui::SameLine(0.f, spacing);
  Browser& b = browser();
  if (ImGui::Button("...", ImVec2(button, 0.f))) {
    std::vector<std::string> extensions;
    for (std::string_view e : file_extensions(p.file_type)) extensions.emplace_back(e);
    const std::filesystem::path start = value->empty() ? scene_dir : scene_dir / *value;
    b.dialog.open("Choose " + param_label(p), FileDialog::Mode::open, std::move(extensions),
                  start.empty() ? std::filesystem::current_path() : start);
    b.field = id;
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Browse for a file");
  ImGui::SameLine(0.f, spacing);
  const std::string_view shown(label);
  ImGui::TextUnformatted(label, label + std::min(shown.find("##"), shown.size()));
  if (b.field == id) {
    std::filesystem::path chosen;
    if (b.dialog.draw(&chosen)) {
      const std::string stored = path_in_scene(chosen, scene_dir);
      if (stored != *value) edited = stored, changed = true;
    }
    if (!b.dialog.is_open()) b.field = 0;
  }
  ImGui::PopID();
  if (changed) *value = edited;
  return changed;
}

}  // namespace inkray
