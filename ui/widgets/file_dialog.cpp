#include "ui/widgets/file_dialog.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>

namespace inkray {

void FileDialog::open(std::string title, Mode mode, std::vector<std::string> extensions,
                      const std::filesystem::path& start) {
  title_ = std::move(title);
  mode_ = mode;
  extensions_ = std::move(extensions);
  std::error_code ec;
  directory_ = std::filesystem::is_directory(start, ec) ? start : start.parent_path();
  if (directory_.empty()) directory_ = std::filesystem::current_path(ec);
  directory_ = std::filesystem::absolute(directory_, ec);
  name_ = std::filesystem::is_directory(start, ec) ? std::string() : start.filename().string();
  open_ = popup_requested_ = true;
}

bool FileDialog::matches(const std::filesystem::path& file) const {
  if (extensions_.empty()) return true;
  // Cameras and other systems write TILES.PNG as readily as tiles.png.
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return std::find(extensions_.begin(), extensions_.end(), ext) != extensions_.end();
}

bool FileDialog::draw(std::filesystem::path* chosen) {
  if (!open_) return false;
  if (popup_requested_) {
    ImGui::OpenPopup(title_.c_str());
    popup_requested_ = false;
  }
  bool confirmed = false;
  const float em = ImGui::GetFontSize();
  ImGui::SetNextWindowSize(ImVec2(42 * em, 30 * em), ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal(title_.c_str(), nullptr)) {
    open_ = false;
    return false;
  }
  std::string dir = directory_.string();
  ImGui::SetNextItemWidth(-1.f);
  if (ImGui::InputText("##dir", &dir, ImGuiInputTextFlags_EnterReturnsTrue)) {
    std::error_code ec;
    if (std::filesystem::is_directory(dir, ec)) directory_ = dir;
  }
  if (ImGui::Button("Up")) directory_ = directory_.parent_path();
  ImGui::SameLine();
  std::string filter = "Filter:";
  for (const auto& e : extensions_) filter += " *" + e;
  ImGui::TextDisabled("%s", extensions_.empty() ? "All files" : filter.c_str());

  std::vector<std::filesystem::directory_entry> folders, files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(directory_, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    if (entry.is_directory(ec)) {
      folders.push_back(entry);
    } else if (matches(entry.path())) {
      files.push_back(entry);
    }
  }
  const auto by_name = [](const auto& a, const auto& b) { return a.path().filename() < b.path().filename(); };
  std::sort(folders.begin(), folders.end(), by_name);
  std::sort(files.begin(), files.end(), by_name);

  ImGui::BeginChild("listing", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * 2), true);
  std::filesystem::path enter;
  for (const auto& f : folders) {
    if (ImGui::Selectable((f.path().filename().string() + "/").c_str(), false,
                          ImGuiSelectableFlags_AllowDoubleClick)) {
      enter = f.path();
    }
  }
  for (const auto& f : files) {
    const std::string name = f.path().filename().string();
    if (ImGui::Selectable(name.c_str(), name == name_, ImGuiSelectableFlags_AllowDoubleClick)) {
      name_ = name;
      if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) confirmed = true;
    }
  }
  ImGui::EndChild();
  if (!enter.empty()) directory_ = enter;

  ImGui::SetNextItemWidth(-11.f * em);
  if (ImGui::InputText("##name", &name_, ImGuiInputTextFlags_EnterReturnsTrue)) confirmed = true;
  ImGui::SameLine();
  if (ImGui::Button(mode_ == Mode::open ? "Open" : "Save", ImVec2(5 * em, 0))) confirmed = true;
  ImGui::SameLine();
  if (ImGui::Button("Cancel", ImVec2(5 * em, 0))) {
    open_ = false;
    ImGui::CloseCurrentPopup();
  }
  if (confirmed && !name_.empty()) {
    std::filesystem::path file =
        std::filesystem::path(name_).is_absolute() ? std::filesystem::path(name_) : directory_ / name_;
    if (mode_ == Mode::save && file.extension().empty() && !extensions_.empty()) file += extensions_.front();
    *chosen = file;
    open_ = false;
    ImGui::CloseCurrentPopup();
  } else {
    confirmed = false;
  }
  ImGui::EndPopup();
  return confirmed;
}

}  // namespace inkray
