#include "ui/panels/param_panel.h"

#include "core/document/edit_checks.h"
#include "core/document/error_log.h"

#include <imgui.h>

#include <vector>

namespace inkray {
namespace {

std::string merge_key(const Selection& s, const std::string& param) {
  return std::to_string(int(s.kind)) + ":" + std::to_string(s.index) + ":" + param;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += (text.empty() ? "" : "\n") + line;
  return text;
}

}  // namespace

void section_title(const char* title) {
  ImGui::Spacing();
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.f, 1.f), "%s", title);
  ImGui::Separator();
}

ParamWidgets widgets_for(ParamPanel& panel, const Selection& item, std::string_view group,
                         std::string_view self_name) {
  const EditorState& state = panel.state;
  ParamWidgets widgets;
  widgets.scene = &state.document.scene();
  widgets.self_name = self_name;
  if (state.problem_item == item) {
    widgets.problem_param = state.problem_param;
    widgets.problem_message = state.problem_message;
  }
  widgets.keys = &panel.keys;
  widgets.key_item = item;
  widgets.key_group = group;
  return widgets;
}

void problem_beside(const EditorState& state, const Selection& item, std::string_view param) {
  if (state.problem_item != item || state.problem_param != param || state.problem_message.empty()) return;
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.35f, 0.3f, 1.f));
  ImGui::PushTextWrapPos(0.f);
  ImGui::TextUnformatted(state.problem_message.c_str());
  ImGui::PopTextWrapPos();
  ImGui::PopStyleColor();
}

void set_problem(EditorState& state, const Selection& item, const std::string& param, std::string message) {
  state.problem_item = item;
  state.problem_param = param;
  state.problem_message = std::move(message);
}

void commit(EditorState& state, const Selection& item, SceneDesc after, const std::string& param,
            bool typed) {
  const std::vector<std::string> added = problems_added(state.document.scene(), after);
  if (!added.empty() && !typed) {
    set_problem(state, item, param, "Not applied: " + joined(added));
    return;
  }
  if (added.empty()) {
    if (state.problem_item == item) set_problem(state, {}, {}, {});
  } else {
    set_problem(state, item, param, joined(added));
  }
  state.edit(std::move(after), "Edit " + param, merge_key(item, param));
}

void refuse_name(EditorState& state, const Selection& item, const std::string& param,
                 const std::string& name) {
  set_problem(state, item, param,
              name.empty() ? "Not applied: a name cannot be empty"
                           : "Not applied: the name " + in_quotes(name) + " is taken");
}

}  // namespace inkray
