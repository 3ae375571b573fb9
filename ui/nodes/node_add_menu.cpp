// The searchable add-node menu; see node_add_menu.h.
#include "ui/nodes/node_add_menu.h"

#include "core/document/graph_edit.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <string_view>
#include <vector>

namespace inkray {
namespace {

bool contains_text(std::string_view haystack, std::string_view needle) {
  const auto it = std::search(haystack.begin(), haystack.end(), needle.begin(), needle.end(),
                              [](char a, char b) { return std::tolower(a) == std::tolower(b); });
  return it != haystack.end();
}

NodeCategory category_of(std::string_view type_name) { return node_category(*make_node(type_name)); }

}  // namespace

std::string node_add_menu(std::string* filter, bool graph_has_output) {
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  ImGui::SetNextItemWidth(13.f * ImGui::GetFontSize());
  ImGui::InputTextWithHint("##search", "search node types", filter);
  const bool enter = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false);
  const auto allowed = [&](std::string_view name) {
    return !(graph_has_output && name == OutputNode::type_name);
  };
  const std::vector<std::string_view> names = node_type_names();
  std::string chosen;
  if (filter->empty()) {
    for (size_t c = 0; c < kNodeCategoryNames.size(); ++c) {
      if (!ImGui::BeginMenu(std::string(kNodeCategoryNames[c]).c_str())) continue;
      for (std::string_view name : names) {
        if (category_of(name) != NodeCategory(c)) continue;
        if (ImGui::MenuItem(std::string(name).c_str(), nullptr, false, allowed(name))) chosen = name;
      }
      ImGui::EndMenu();
    }
    return chosen;
  }
  bool first = true;
  for (std::string_view name : names) {
    if (!contains_text(name, *filter) || !allowed(name)) continue;
    // Enter takes the first match, which is shown highlighted.
    if (ImGui::Selectable(std::string(name).c_str(), first) || (first && enter)) chosen = name;
    ImGui::SameLine(200.f);
    ImGui::TextDisabled("%s", std::string(kNodeCategoryNames[size_t(category_of(name))]).c_str());
    first = false;
  }
  if (first) ImGui::TextDisabled("no node type matches");
  return chosen;
}

}  // namespace inkray
