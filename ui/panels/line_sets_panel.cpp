#include "ui/panels/line_sets_panel.h"

#include "ui/model/line_set_edits.h"
#include "ui/model/line_set_summary.h"
#include "ui/panels/param_panel.h"
#include "ui/widgets/key_actions.h"
#include "ui/widgets/line_style_swatch.h"
#include "ui/widgets/toolbar_flow.h"
#include "ui/widgets/widget_report.h"

#include <imgui.h>
#include <imgui_internal.h>  // RenderTextEllipsis

#include <algorithm>
#include <string>
#include <utility>

namespace inkray {
namespace {

constexpr std::string_view kNewSetPreset = "ink";
constexpr int kVisibleRows = 6;  // the list scrolls beyond these

std::vector<LineSetDesc>& sets_of(SceneDesc& scene) { return scene.outlines.sets; }

Selection set_item(int index) { return {ItemKind::line_set, index}; }

// What the toolbar and the rows' switches asked for; done once the panel is drawn, so
// the whole panel shows one document ("decide, then do").
enum class SetAction { none, add, duplicate, remove, up, down };
struct Requests {
  SetAction action = SetAction::none;
  int toggled = -1;  // the set whose switch was clicked
  bool enabled = false;
};

bool toolbar_button(ToolbarFlow& flow, const char* label, const char* report, const char* tooltip,
                    bool enabled) {
  flow.next(button_width(label));
  ImGui::BeginDisabled(!enabled);
  const bool pressed = ImGui::Button(label);
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", tooltip);
  widget_report::item(report);
  return pressed;
}

SetAction toolbar(int count, int chosen) {
  ToolbarFlow flow;
  SetAction action = SetAction::none;
  const bool any = count > 0;
  if (toolbar_button(flow, "Add", "line_sets.add",
                     "A new set taking every line, in the ink style, drawn last", true))
    action = SetAction::add;
  if (toolbar_button(flow, "Duplicate", "line_sets.duplicate", "A copy of the chosen set, with its keys",
                     any))
    action = SetAction::duplicate;
  if (toolbar_button(flow, "Delete", "line_sets.delete", "Delete the chosen set and its keys", any))
    action = SetAction::remove;
  if (toolbar_button(flow, "Up", "line_sets.up", "Draw the chosen set earlier (under the sets after it)",
                     any && chosen > 0))
    action = SetAction::up;
  if (toolbar_button(flow, "Down", "line_sets.down", "Draw the chosen set later (over the sets before it)",
                     any && chosen + 1 < count))
    action = SetAction::down;
  return action;
}

// Does what the toolbar asked, as one undoable step, and chooses the set it leaves.
void apply(EditorState& state, SetAction action) {
  SceneDesc scene = state.document.scene();
  const Selection chosen = set_item(state.line_set.index);
  Selection after = chosen;
  const char* label = "";
  bool done = false;
  switch (action) {
    case SetAction::none:
      return;
    case SetAction::add:
      after = add_line_set(scene, kNewSetPreset), label = "Add line set", done = true;
      break;
    case SetAction::duplicate:
      after = duplicate_item(scene, chosen), label = "Duplicate line set",
      done = after.kind != ItemKind::none;
      break;
    case SetAction::remove:
      done = delete_item(scene, chosen), label = "Delete line set";
      after = set_item(std::min(chosen.index, int(sets_of(scene).size()) - 1));
      break;
    case SetAction::up:
    case SetAction::down:
      done = move_line_set(scene, chosen, action == SetAction::up ? -1 : 1, &after);
      label = action == SetAction::up ? "Move line set up" : "Move line set down";
      break;
  }
  if (!done || !state.edit_checked(std::move(scene), label)) return;
  state.line_set.index = std::max(after.index, 0);
  state.line_set.reveal = true;
}

// One row: the enabled switch, the style's swatch, the name and what the set selects.
void set_row(ParamPanel& panel, int index, Requests* requests) {
  EditorState& state = panel.state;
  const LineSetDesc& set = panel.shown.outlines.sets[size_t(index)];
  const ImGuiStyle& style = ImGui::GetStyle();
  const float line = ImGui::GetTextLineHeight();
  const float row_height = 2.f * line + style.ItemSpacing.y;
  ImGui::PushID(index);
  const ImVec2 start = ImGui::GetCursorScreenPos();
  if (ImGui::Selectable("##row", index == state.line_set.index, ImGuiSelectableFlags_AllowItemOverlap,
                        ImVec2(0.f, row_height)))
    state.line_set.index = index;
  widget_report::item("line_sets.row:" + set.name);
  const std::string summary = line_set_summary(set);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s: %s", set.name.c_str(), summary.c_str());
  if (state.line_set.reveal && index == state.line_set.index) {
    ImGui::SetScrollHereY(0.5f);
    state.line_set.reveal = false;
  }
  const ImVec2 row_max = ImGui::GetItemRectMax();
  const ImVec2 below = ImGui::GetCursorScreenPos();

  // The switch over the row, centred in its height.
  ImGui::SetCursorScreenPos(ImVec2(start.x, start.y + 0.5f * (row_height - ImGui::GetFrameHeight())));
  bool enabled = set.enabled;
  if (ImGui::Checkbox("##enabled", &enabled)) requests->toggled = index, requests->enabled = enabled;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Draw this set");
  widget_report::item("line_sets.enabled:" + set.name);

  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float swatch_x = ImGui::GetItemRectMax().x + style.ItemInnerSpacing.x;
  const ImVec2 swatch_lo(swatch_x, start.y + 1.f),
      swatch_hi(swatch_x + 5.f * line, start.y + row_height - 1.f);
  draw_line_style_swatch(draw, swatch_lo, swatch_hi, set.style, !set.enabled);

  // The name and the summary, cut short with "..." where the row ends (the tooltip has all).
  const float text_x = swatch_hi.x + style.ItemInnerSpacing.x;
  const auto text_line = [&](float y, ImGuiCol colour, const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(colour));
    ImGui::RenderTextEllipsis(draw, ImVec2(text_x, y), ImVec2(row_max.x, y + line), row_max.x, row_max.x,
                              text.c_str(), nullptr, nullptr);
    ImGui::PopStyleColor();
  };
  text_line(start.y, set.enabled ? ImGuiCol_Text : ImGuiCol_TextDisabled, set.name);
  text_line(start.y + line + 0.5f * style.ItemSpacing.y, ImGuiCol_TextDisabled, summary);

  ImGui::SetCursorScreenPos(below);
  ImGui::PopID();
}

// The sets in drawing order, in a box of their own that scrolls past kVisibleRows.
void set_list(ParamPanel& panel, Requests* requests) {
  const int count = int(panel.shown.outlines.sets.size());
  const ImGuiStyle& style = ImGui::GetStyle();
  const float row_height = 2.f * ImGui::GetTextLineHeight() + style.ItemSpacing.y;
  const int rows = std::clamp(count, 1, kVisibleRows);
  const float height = float(rows) * (row_height + style.ItemSpacing.y) + 2.f * style.WindowPadding.y;
  ImGui::BeginChild("sets", ImVec2(0.f, height), true);
  if (count == 0)
    ImGui::TextWrapped(
        "No line sets: each line type is drawn pixel by pixel in its own colour. Add a set "
        "to draw lines as strokes in a style.");
  for (int i = 0; i < count; ++i) set_row(panel, i, requests);
  ImGui::EndChild();
}

// The chosen set's parameters; its style's group starts open.
struct StyleOpen {
  ParamWidgets& widgets;
  template <class F>
  void operator()(const Param& p, F& field) {
    if (p.name == "style") ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    widgets(p, field);
  }
};

void set_editor(ParamPanel& panel, int index) {
  const Selection item = set_item(index);
  LineSetDesc set = panel.shown.outlines.sets[size_t(index)];
  section_title(("Line set: " + set.name).c_str());
  ImGui::PushID(index);
  ParamWidgets widgets = widgets_for(panel, item);
  StyleOpen visitor{widgets};
  visit_params(set, visitor);
  ImGui::PopID();
  if (widgets.changed)
    commit_named(panel.state, item, sets_of, std::move(set), widgets.changed_param, widgets.changed_typed);
}

}  // namespace

void draw_line_sets_panel(EditorState& state) {
  ParamPanel panel(state);
  const int count = int(panel.shown.outlines.sets.size());
  state.line_set.index = std::clamp(state.line_set.index, 0, std::max(count - 1, 0));
  Requests requests;
  requests.action = toolbar(count, state.line_set.index);
  set_list(panel, &requests);
  // Room for the longest labels ("Least opacity") at any interface size, as in the properties panel.
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 9.f);
  if (count > 0) set_editor(panel, state.line_set.index);
  ImGui::PopItemWidth();
  if (requests.toggled >= 0) {
    SceneDesc scene = state.document.scene();
    sets_of(scene)[size_t(requests.toggled)].enabled = requests.enabled;
    commit(state, set_item(requests.toggled), std::move(scene), "enabled", false);
  }
  apply_key_actions(state, panel.keys);
  apply(state, requests.action);
}

}  // namespace inkray
