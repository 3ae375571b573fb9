#include "ui/panels/properties_panel.h"

#include "core/document/graph_edit.h"
#include "core/document/param_text.h"
#include "ui/panels/param_panel.h"
#include "ui/widgets/key_actions.h"
#include "ui/model/scene_edits.h"

#include <imgui.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace inkray {
namespace {

// A tagged variant's type combo and its alternative's widgets.
template <class Variant>
Edited edit_tagged_item(ParamPanel& panel, const Selection& sel, const char* label, Variant& value,
                        std::string_view group = {}) {
  Edited edited;
  if (edit_variant_type(label, value)) edited = {true, false, "type"};
  problem_beside(panel.state, sel, "type");
  std::visit([&](auto& alternative) { edited |= edit_item(alternative, widgets_for(panel, sel, group)); },
             value);
  return edited;
}

// A name field: typed text, its problem beside it.
bool edit_name(ParamPanel& panel, const Selection& sel, std::string& name, std::string_view doc) {
  ParamWidgets widgets = widgets_for(panel, sel);
  widgets(text("name", doc), name);
  return widgets.changed;
}

// The material's type and settings; a graph's nodes are the node editor's.
Edited edit_material_data(ParamPanel& panel, const Selection& sel, MaterialDesc& m) {
  EditorState& state = panel.state;
  const MaterialVariant before = m.data;
  Edited edited;
  if (edit_variant_type("Type###type", m.data)) edited = {true, false, "type"};
  problem_beside(state, sel, "type");
  // Turning a material into a graph keeps its look: it becomes that material's closure node.
  if (edited.changed && std::holds_alternative<GraphDesc>(m.data)) m.data = graph_from_material(before);
  std::visit(
      [&]<class T>(T& data) {
        if constexpr (std::is_same_v<T, GraphDesc>) {
          ImGui::TextDisabled("%zu nodes, %zu links", data.nodes.size(), data.links.size());
        } else {
          // A mix offers the other materials: one of itself would be a cycle.
          edited |= edit_item(data, widgets_for(panel, sel, {}, m.name));
        }
      },
      m.data);
  if (ImGui::Button("Edit nodes")) state.want_node_editor = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Open the node editor on this material (a plain one becomes a graph at the first edit)");
  return edited;
}

// Scale with a lock: locked, editing one component scales all three alike (param_text.h).
bool edit_scale(ParamPanel& panel, const Selection& sel, Vec3& scale, std::string* param) {
  static constexpr Param kScale =
      vector("scale", "Scale along the object's own axes, applied first").labelled("Scale");
  EditorState& state = panel.state;
  Vec3 edited = scale;
  ParamWidgets widgets = widgets_for(panel, sel, "transform");
  widgets(kScale, edited);
  ImGui::Checkbox("Uniform scale", &state.uniform_scale);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Locked: editing one component scales all three proportionally");
  if (!widgets.changed) return false;
  if (state.uniform_scale) edited = locked_scale(scale, edited);
  // No zero factor: the reader refuses it, and a flat object cannot be scaled back.
  if (edited.x == 0.f || edited.y == 0.f || edited.z == 0.f || edited == scale) return false;
  for (int i = 0; i < 3; ++i)
    edited[i] = std::clamp(edited[i], -float(kMaxCoordinate), float(kMaxCoordinate));
  scale = edited;
  *param = "scale";
  return true;
}

bool edit_transform(ParamPanel& panel, const Selection& sel, TransformDesc& t, std::string* param) {
  static constexpr Param kTranslate =
      vector("translate", "Moves the object, applied last").labelled("Position");
  ParamWidgets translate = widgets_for(panel, sel, "transform");
  translate(kTranslate, t.translate);
  bool changed = translate.changed;
  if (changed) *param = "translate";
  changed |= edit_scale(panel, sel, t.scale, param);
  for (size_t i = 0; i < t.rotate.size(); ++i) {
    ImGui::PushID(int(i));
    std::string rotation_param;
    if (edit_params(t.rotate[i], &rotation_param,
                    widgets_for(panel, sel, "transform.rotate." + std::to_string(i))))
      changed = true, *param = "rotate" + std::to_string(i) + rotation_param;
    if (ImGui::SmallButton("remove rotation")) {
      t.rotate.erase(t.rotate.begin() + long(i));
      changed = true, *param = "rotate-remove";
      ImGui::PopID();
      break;
    }
    ImGui::PopID();
  }
  if (ImGui::SmallButton("+ rotation")) t.rotate.push_back({}), changed = true, *param = "rotate-add";
  return changed;
}

void material_section(ParamPanel& panel, int index) {
  EditorState& state = panel.state;
  const Selection sel{ItemKind::material, index};
  MaterialDesc m = panel.shown.materials[size_t(index)];
  ImGui::PushID("material");
  Edited edited;
  if (edit_name(panel, sel, m.name, "Unique material name")) edited = {true, true, "name"};
  edited |= edit_material_data(panel, sel, m);
  if (ImGui::TreeNode("Outline overrides")) {
    edited |= edit_item(m.lines, widgets_for(panel, sel, "lines"));
    ImGui::TreePop();
  }
  ImGui::PopID();
  if (!edited.changed) return;
  std::optional<SceneDesc> scene = with_named(state, sel, &SceneDesc::materials, std::move(m), edited.param);
  if (!scene) return;
  // A new mix needs two inputs to be valid at once: it gets them (param_text.h).
  if (edited.param == "type") give_mix_inputs(*scene, size_t(index));
  commit(state, sel, std::move(*scene), edited.param, edited.typed);
}

// A struct's parameters but those `skip` picks, which the caller draws elsewhere.
template <class Skip>
struct Except {
  ParamWidgets& widgets;
  Skip skip;
  template <class F>
  void operator()(const Param& p, F& field) {
    if (!skip(p)) widgets(p, field);
  }
};

void object_section(ParamPanel& panel, int index) {
  EditorState& state = panel.state;
  const SceneDesc& scene = panel.shown;
  const Selection sel{ItemKind::object, index};
  ObjectDesc o = scene.objects[size_t(index)];
  ParamWidgets own = widgets_for(panel, sel);
  // The outline overrides come last.
  Except top{own, [](const Param& p) { return p.kind == ParamKind::group; }};
  visit_params(o, top);
  Edited edited{own.changed, own.changed_typed, own.changed_param};
  section_title("Transform");
  std::string transform_param;
  if (edit_transform(panel, sel, o.transform, &transform_param)) edited = {true, false, transform_param};
  section_title("Shape");
  edited |= edit_tagged_item(panel, sel, "Shape###shape", o.shape, "shape");
  if (ImGui::TreeNode("Outline overrides")) {
    edited |= edit_item(o.lines, widgets_for(panel, sel, "lines"));
    ImGui::TreePop();
  }
  if (edited.changed) {
    commit_named(state, sel, &SceneDesc::objects, std::move(o), edited.param, edited.typed);
    return;
  }
  // The object's material, so the look can be tuned without leaving the object.
  for (int m = 0; m < int(scene.materials.size()); ++m) {
    if (scene.materials[size_t(m)].name == scene.objects[size_t(index)].material) {
      section_title(("Material: " + scene.materials[size_t(m)].name).c_str());
      material_section(panel, m);
      break;
    }
  }
  for (int e = 0; e < int(scene.strokes.size()); ++e) {
    if (scene.strokes[size_t(e)].object != scene.objects[size_t(index)].name) continue;
    ImGui::PushID(e);
    section_title(("Strokes: " + scene.strokes[size_t(e)].name).c_str());
    const Selection emitter_sel{ItemKind::emitter, e};
    StrokeEmitterDesc emitter = scene.strokes[size_t(e)];
    ParamWidgets widgets = widgets_for(panel, emitter_sel);
    visit_params(emitter, widgets);
    if (widgets.changed) {
      commit_named(state, emitter_sel, &SceneDesc::strokes, std::move(emitter), widgets.changed_param,
                   widgets.changed_typed);
      ImGui::PopID();
      return;
    }
    ImGui::PopID();
  }
}

// Singletons (camera, render settings, outlines, environment) have no name to keep consistent.
template <class T>
void singleton_section(ParamPanel& panel, ItemKind kind, T SceneDesc::*member) {
  EditorState& state = panel.state;
  const Selection sel{kind, -1};
  T value = panel.shown.*member;
  Edited edited;
  if constexpr (requires { std::variant_size<T>::value; }) {
    edited = edit_tagged_item(panel, sel, "Type###type", value);
  } else {
    edited = edit_item(value, widgets_for(panel, sel));
  }
  if (edited.changed) {
    SceneDesc scene = state.document.scene();
    scene.*member = std::move(value);
    commit(state, sel, std::move(scene), edited.param, edited.typed);
  }
}

// Line sets have a tab of their own, with their styles' swatches and their keys.
void line_sets_link(EditorState& state, size_t count) {
  ImGui::Spacing();
  ImGui::TextDisabled("%zu line set%s", count, count == 1 ? "" : "s");
  ImGui::SameLine();
  if (ImGui::SmallButton("Edit in the Line sets tab")) state.want_line_sets = true;
}

// The outlines' settings but their line sets.
void outlines_section(ParamPanel& panel) {
  EditorState& state = panel.state;
  const Selection sel{ItemKind::outlines, -1};
  OutlineDesc outlines = panel.shown.outlines;
  ParamWidgets widgets = widgets_for(panel, sel);
  Except own{widgets, [](const Param& p) { return p.name == "sets"; }};
  visit_params(outlines, own);
  line_sets_link(state, outlines.sets.size());
  if (!widgets.changed) return;
  SceneDesc scene = state.document.scene();
  outlines.sets = scene.outlines.sets;  // the shown sets are at this frame; the document's keep their keys
  scene.outlines = std::move(outlines);
  commit(state, sel, std::move(scene), widgets.changed_param, widgets.changed_typed);
}

}  // namespace

void draw_properties_panel(EditorState& state) {
  ParamPanel panel(state);
  const SceneDesc& scene = panel.shown;
  const Selection sel = validated(scene, state.selection);
  if (sel.kind == ItemKind::none) {
    ImGui::TextDisabled("Select an item in the scene graph or click the viewport.");
    return;
  }
  ImGui::Text("%s", item_name(scene, sel).c_str());
  if (!scene.animation.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("at frame %g", double(scene.render.frame));
  }
  ImGui::Separator();
  // Room for the longest labels ("Specular colour") at any interface size.
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 9.f);
  switch (sel.kind) {
    case ItemKind::camera:
      singleton_section(panel, sel.kind, &SceneDesc::camera);
      break;
    case ItemKind::render:
      singleton_section(panel, sel.kind, &SceneDesc::render);
      break;
    case ItemKind::outlines:
      outlines_section(panel);
      break;
    case ItemKind::line_set:
      line_sets_link(state, scene.outlines.sets.size());
      break;
    case ItemKind::environment:
      singleton_section(panel, sel.kind, &SceneDesc::environment);
      break;
    case ItemKind::object:
      object_section(panel, sel.index);
      break;
    case ItemKind::material:
      material_section(panel, sel.index);
      break;
    case ItemKind::light: {
      LightDesc light = scene.lights[size_t(sel.index)];
      Edited edited;
      if (edit_name(panel, sel, light.name, "Light name")) edited = {true, true, "name"};
      edited |= edit_tagged_item(panel, sel, "Type###type", light.data);
      if (edited.changed)
        commit_named(state, sel, &SceneDesc::lights, std::move(light), edited.param, edited.typed);
      break;
    }
    case ItemKind::emitter: {
      StrokeEmitterDesc emitter = scene.strokes[size_t(sel.index)];
      ParamWidgets widgets = widgets_for(panel, sel);
      visit_params(emitter, widgets);
      if (widgets.changed)
        commit_named(state, sel, &SceneDesc::strokes, std::move(emitter), widgets.changed_param,
                     widgets.changed_typed);
      break;
    }
    case ItemKind::none:
      break;
  }
  ImGui::PopItemWidth();
  apply_key_actions(state, panel.keys);
}

}  // namespace inkray
