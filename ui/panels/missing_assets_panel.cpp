#include "ui/panels/missing_assets_panel.h"

#include "core/document/param_text.h"

#include <imgui.h>

#include <algorithm>
#include <system_error>
#include <utility>

namespace inkray {
namespace {

// The kind's extensions, and the missing file's own when it is another.
std::vector<std::string> dialog_filter(const MissingAsset& m) {
  std::vector<std::string> filter;
  for (std::string_view e : file_extensions(m.type)) filter.emplace_back(e);
  const std::string own = m.resolved.extension().string();
  if (!own.empty() && !filter.empty() && std::find(filter.begin(), filter.end(), own) == filter.end())
    filter.push_back(own);
  return filter;
}

// Where the dialog starts: the file's folder when it is still there, else the scene's.
std::filesystem::path dialog_start(const MissingAsset& m, const SceneDesc& scene) {
  std::error_code ec;
  if (std::filesystem::is_directory(m.resolved.parent_path(), ec)) return m.resolved.parent_path();
  return scene.base_dir.empty() ? std::filesystem::current_path(ec) : scene.base_dir;
}

}  // namespace

std::string MissingAssetsPanel::badge_text() const {
  if (missing_.empty()) return {};
  return std::to_string(missing_.size()) + (missing_.size() == 1 ? " file missing" : " files missing") +
         " - Locate...";
}

void MissingAssetsPanel::refresh(const EditorState& state) {
  const auto now = std::chrono::steady_clock::now();
  const bool opened = state.document.file() != document_file_;
  if (!stale_ && !opened && now - checked_at_ < std::chrono::seconds(1)) return;
  std::vector<MissingAsset> missing = missing_assets(state.document.scene());
  // A new document, or files gone missing since: show them.
  if (opened || missing.size() > missing_.size()) open_ = !missing.empty();
  missing_ = std::move(missing);
  document_file_ = state.document.file();
  checked_at_ = now;
  stale_ = false;
}

void MissingAssetsPanel::relink_to(EditorState& state, const std::filesystem::path& chosen) {
  SceneDesc after = state.document.scene();
  const size_t changed = relink(after, locating_, chosen);
  if (changed == 0) {
    state.log.warning("relinking " + locating_ + " to " + chosen.string() + " changed nothing");
    return;
  }
  state.edit(std::move(after), "Relink assets");
  state.log.info("relinked " + std::to_string(changed) + (changed == 1 ? " reference" : " references") +
                 " to files in " + chosen.parent_path().string());
  stale_ = true;
}

void MissingAssetsPanel::draw(EditorState& state) {
  refresh(state);
  std::filesystem::path chosen;
  if (dialog_.draw(&chosen)) {
    relink_to(state, chosen);
    refresh(state);
  }
  if (missing_.empty() || !open_) return;
  ImGui::SetNextWindowSize(ImVec2(37.f * ImGui::GetFontSize(), 0.f), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Missing files", &open_)) {
    ImGui::End();
    return;
  }
  ImGui::TextWrapped(
      "These files are not where the scene says. The viewport draws them as placeholders (a magenta "
      "checker, a box) until they are found; the scene keeps their paths until you relink them.");
  ImGui::Separator();
  for (size_t i = 0; i < missing_.size(); ++i) {
    const MissingAsset& m = missing_[i];
    ImGui::PushID(int(i));
    if (ImGui::Button("Locate...")) {
      locating_ = m.written;
      dialog_.open("Locate " + m.resolved.filename().string(), FileDialog::Mode::open, dialog_filter(m),
                   dialog_start(m, state.document.scene()));
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Choose the file; the other missing files of its folder are looked for beside it");
    ImGui::SameLine();
    ImGui::TextUnformatted(m.written.c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", m.resolved.string().c_str());
    ImGui::Indent();
    ImGui::TextDisabled("used by %s", users_text(m.users).c_str());
    ImGui::Unindent();
    ImGui::PopID();
  }
  ImGui::End();
}

}  // namespace inkray
