// The editor's widgets, generated from the parameter lists (docs/architecture.md,
// "Parameter tables"): a visitor over a parameter table that draws one ImGui widget per Param
// with its label, slider range and plain-text tooltip (core/document/param_text.h),
// and records which parameter changed. References are combos of the scene's names,
// paths a field with a browse button (path_field.h). Given a KeyTargets, keyable
// fields show their keys and take I, Alt+I and a right-click menu.
#pragma once

#include "core/document/desc.h"
#include "ui/model/selection.h"

#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

struct ImDrawList;

namespace inkray {

// Keys from the widgets (docs/architecture.md, "Timeline and keys"), shared by the
// widgets of one panel: the document whose tracks mark the fields (at its current
// frame), and what the user asked this frame, which the panel turns into edits.
struct KeyTargets {
  const SceneDesc* document = nullptr;
  bool report = false;           // each keyable field reports itself as "param:PATH" (widget_report.h)
  std::string hovered, focused;  // the keyable parameters under the mouse and with the focus, this frame
  enum class Action { none, insert, remove, clear } action = Action::none;
  std::string action_path;  // the parameter of a right-click menu's choice
};

// A key mark: filled when a key is on this frame, outlined when the parameter is
// animated without one here (the timeline draws its keys with it too).
void draw_key_diamond(ImDrawList* draw, float x, float y, float radius, unsigned fill, unsigned outline);
inline constexpr unsigned kKeyFill = 0xFF28C8FFu;       // yellow (ImGui colours are ABGR)
inline constexpr unsigned kAnimatedMark = 0xFF5AC86Eu;  // green

struct ParamWidgets {
  // Context, set by the caller: where reference names and the scene's folder come
  // from (null: references are typed, paths resolve against the working directory),
  // the name a material reference must not take (a mix's own), and a problem to show
  // in red beside the parameter it names (a path like changed_param).
  const SceneDesc* scene = nullptr;
  std::string_view self_name;
  std::string problem_param, problem_message;

  bool changed = false;
  // The last changed parameter, with the groups it is in ("silhouette.width"): the
  // undo merge key.
  std::string changed_param;
  bool changed_typed = false;  // it was typed text (a name or a path), kept while typing

  // Keying, when `keys` is set: the item these are parameters of, and the groups
  // between its path and theirs ("transform", "lines"), for key_path (scene_edits.h).
  KeyTargets* keys = nullptr;
  Selection key_item;
  std::string key_group;

  void operator()(const Param& p, float& v);
  void operator()(const Param& p, int& v);
  void operator()(const Param& p, bool& v);
  void operator()(const Param& p, Vec3& v);  // point, direction, vector or color by p.kind
  void operator()(const Param& p, std::string& v);
  void operator()(const Param& p, ColorInput& v);
  void operator()(const Param& p, std::vector<Color>& v);
  template <class E>
  requires std::is_enum_v<E>
  void operator()(const Param& p, E& v) {
    int index = int(v);
    if (choice_widget(p, &index)) v = E(index), note(p);
  }
  // A graph's nodes are drawn by the node editor (node_editor_panel.h), not as a list.
  void operator()(const Param&, std::vector<GraphNodeDesc>&) {}
  // A list of structs (ramp stops, links): each entry's widgets, buttons to remove it
  // and to move it up or down (where order matters), an add button. Line sets have a
  // panel of their own (ui/panels/line_sets_panel.h).
  template <ParamGroup T>
  void operator()(const Param& p, std::vector<T>& items) {
    if (!begin_group(p)) return;
    for (size_t i = 0; i < items.size(); ++i) {
      push_item(p, int(i));
      visit_params(items[i], *this);
      const ItemAction action = item_buttons(i > 0, i + 1 < items.size());
      if (action != ItemAction::none) {
        if (action == ItemAction::remove) items.erase(items.begin() + long(i));
        if (action == ItemAction::up) std::swap(items[i], items[i - 1]);
        if (action == ItemAction::down) std::swap(items[i], items[i + 1]);
        note(p);
        pop_item();
        break;
      }
      pop_item();
    }
    if (add_button()) {
      items.push_back(items.empty() ? T{} : items.back());
      note(p);
    }
    end_group();
  }
  template <ParamGroup T>
  void operator()(const Param& p, T& group) {
    if (begin_group(p)) {
      if constexpr (HasPresets<T>) {
        int chosen = -1;
        if (preset_combo(ParamPresets<T>::names, &chosen)) {
          ParamPresets<T>::apply(ParamPresets<T>::names[size_t(chosen)], group);
          note(p);
        }
      }
      visit_params(group, *this);
      end_group();
    }
  }

  // The key mark beside a keyable field, its menu, and I / Alt+I while it is hovered:
  // called by every widget here, and after a field drawn by other code (the node
  // editor's colour bars), with that field as ImGui's last item. `mark_x` places the
  // mark's centre elsewhere than after the item (inside a colour bar that fills its row).
  void key_marks(const Param& p, float mark_x = -1.f);

 private:
  bool choice_widget(const Param& p, int* index);
  bool reference_widget(const Param& p, std::string* value);
  bool begin_group(const Param& p);
  void end_group();
  void push_item(const Param& p, int index);
  void pop_item();
  enum class ItemAction { none, remove, up, down };
  ItemAction item_buttons(bool can_go_up, bool can_go_down);
  bool add_button();
  // The animation path of the field `name` drawn now, or of the group being drawn for
  // an empty name (key_path, scene_edits.h); needs keys->document.
  std::string field_path(std::string_view name) const;
  // A "Preset" combo over `names`; true with *chosen set when one was picked.
  bool preset_combo(std::span<const std::string_view> names, int* chosen);
  // The tooltip and, when it names this parameter, the problem in red.
  void finish(const Param& p, bool typed_value);
  void note(const Param& p) {
    changed = true;
    changed_param = path_ + std::string(p.name);
    changed_typed = p.kind == ParamKind::text || p.kind == ParamKind::path;
  }

  std::string path_;         // "group." prefixes of the parameters being drawn
  bool unlabelled_ = false;  // a colour input's constant, named by its type row
  std::vector<size_t> path_lengths_;
};

// Widgets for a struct's parameter list, in the context `widgets` carries.
template <class Desc>
bool edit_params(Desc& desc, std::string* changed_param = nullptr, ParamWidgets widgets = {}) {
  visit_params(desc, widgets);
  if (changed_param && widgets.changed) *changed_param = widgets.changed_param;
  return widgets.changed;
}

// A variant alternative's name in the type combo: its JSON tag, or "constant" for a plain colour.
template <class T>
constexpr std::string_view alternative_name() {
  if constexpr (requires { T::type_name; }) {
    return T::type_name;
  } else {
    return "constant";
  }
}

bool variant_type_combo_impl(const char* label, const std::vector<std::string_view>& names, int* index);

// A combo over a tagged variant's alternatives (by their "type" names); switching
// type starts the new alternative from its defaults.
template <class Variant>
bool edit_variant_type(const char* label, Variant& value) {
  std::vector<std::string_view> names;
  [&]<size_t... I>(std::index_sequence<I...>) {
    (names.push_back(alternative_name<std::variant_alternative_t<I, Variant>>()), ...);
  }
  (std::make_index_sequence<std::variant_size_v<Variant>>());
  int index = int(value.index());
  if (!variant_type_combo_impl(label, names, &index)) return false;
  [&]<size_t... I>(std::index_sequence<I...>) {
    ((index == int(I) ? (value = std::variant_alternative_t<I, Variant>{}, 0) : 0), ...);
  }
  (std::make_index_sequence<std::variant_size_v<Variant>>());
  return true;
}

// Type combo plus the alternative's parameters.
template <class Variant>
bool edit_tagged(const char* label, Variant& value, std::string* changed_param,
                 const ParamWidgets& widgets = {}) {
  bool changed = edit_variant_type(label, value);
  if (changed && changed_param) *changed_param = "type";
  std::visit([&](auto& alternative) { changed |= edit_params(alternative, changed_param, widgets); }, value);
  return changed;
}

}  // namespace inkray
