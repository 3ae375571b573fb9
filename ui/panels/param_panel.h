// What the panels that edit the document through the generated widgets share (the
// properties panel, the Line sets panel): the widgets' context for one item, and the
// one way their edits reach the document. An edit is refused when it would make the
// scene unrenderable, with the reason beside its field; it lands through
// EditorState::edit with a merge key naming the item and parameter, so one slider drag
// is one undo step, and the edit's stage (a line style's is the resolve's) follows
// from what it changed.
#pragma once

#include "ui/model/editor_state.h"
#include "ui/model/scene_edits.h"
#include "ui/widgets/param_widgets.h"

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace inkray {

// What a panel's widgets share while it is drawn: the editor's state, the document
// at the current frame (the values shown), and the keys the fields ask for.
struct ParamPanel {
  EditorState& state;
  const SceneDesc& shown;
  KeyTargets keys;

  explicit ParamPanel(EditorState& editor) : state(editor), shown(editor.shown()) {
    keys.document = &state.document.scene();
    keys.report = state.report_params;
  }
};

// ImGui 1.86 has no SeparatorText.
void section_title(const char* title);

// The widgets' context for one item: the scene's names and folder, that item's last
// problem, shown beside its field, and the item's keys (`group` sits between the
// item's path and its parameters': "transform", "lines").
ParamWidgets widgets_for(ParamPanel& panel, const Selection& item, std::string_view group = {},
                         std::string_view self_name = {});

// The problem of a field drawn by the panel rather than by the generated widgets.
void problem_beside(const EditorState& state, const Selection& item, std::string_view param);
void set_problem(EditorState& state, const Selection& item, const std::string& param, std::string message);

// What the generated widgets of one struct changed.
struct Edited {
  bool changed = false;
  bool typed = false;  // typed text: a name or a path
  std::string param;
  Edited& operator|=(const Edited& later) {
    if (later.changed) *this = later;
    return *this;
  }
};

template <class Desc>
Edited edit_item(Desc& desc, ParamWidgets widgets) {
  visit_params(desc, widgets);
  return {widgets.changed, widgets.changed_typed, widgets.changed_param};
}

// Every edit of a panel ends here. One that would make the scene unrenderable is
// refused, with the reason beside its field; typed text (a name, a path) is kept,
// since typing passes through such states, and the reason shows until it is mended.
void commit(EditorState& state, const Selection& item, SceneDesc after, const std::string& param, bool typed);

// Says beside the name field why `name` was refused: empty or taken.
void refuse_name(EditorState& state, const Selection& item, const std::string& param,
                 const std::string& name);

// The document with an edited copy of a named item, in the list `list_of` gives
// (a member pointer such as &SceneDesc::objects, or a function of the scene). A changed
// name is applied with rename_item (scene_edits.h) so references and tracks follow; an
// empty or taken name keeps the old one, and the reason shows beside the field.
template <class T, class ListOf>
std::optional<SceneDesc> with_named(EditorState& state, const Selection& sel, ListOf list_of, T edited,
                                    const std::string& param) {
  SceneDesc scene = state.document.scene();
  const std::string old_name = std::invoke(list_of, scene)[size_t(sel.index)].name;
  if (edited.name != old_name) {
    if (!rename_item(scene, sel, edited.name)) {
      refuse_name(state, sel, param, edited.name);
      return std::nullopt;
    }
    // Renaming rewrites references inside the edited item too (a material's own mix inputs).
    edited.name = std::invoke(list_of, scene)[size_t(sel.index)].name;
  }
  std::invoke(list_of, scene)[size_t(sel.index)] = std::move(edited);
  return scene;
}

template <class T, class ListOf>
void commit_named(EditorState& state, const Selection& sel, ListOf list_of, T edited,
                  const std::string& param, bool typed) {
  if (auto scene = with_named(state, sel, list_of, std::move(edited), param))
    commit(state, sel, std::move(*scene), param, typed);
}

}  // namespace inkray
