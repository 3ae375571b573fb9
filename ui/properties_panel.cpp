#include "core/document/graph_edit.h"
#include "ui/properties_panel.h"

#include "ui/param_widgets.h"
#include "ui/scene_edits.h"

#include <imgui.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace inkray {
namespace {

// ImGui 1.86 has no SeparatorText.
void section_title(const char* title) {
  ImGui::Spacing();
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.f, 1.f), "%s", title);
  ImGui::Separator();
}

std::string merge_key(const Selection& s, const std::string& param) {
  return std::to_string(int(s.kind)) + ":" + std::to_string(s.index) + ":" + param;
}

// Commits an edited copy of a named item. A changed name is applied with
// rename_item so references to it follow; a taken name is refused.
template <class T>
void commit_named(EditorState& state, const Selection& sel, std::vector<T> SceneDesc::*list, T edited,
                  const std::string& param) {
  SceneDesc scene = state.document.scene();
  const std::string old_name = (scene.*list)[size_t(sel.index)].name;
  if (edited.name != old_name) {
    if (!rename_item(scene, sel, edited.name)) return;  // empty or taken: keep the old name
    // Renaming rewrites references inside the edited item too (a material's own mix inputs).
    edited.name = (scene.*list)[size_t(sel.index)].name;
  }
  if constexpr (std::is_same_v<T, ObjectDesc>) {
    edited.name = (scene.*list)[size_t(sel.index)].name;
  }
  (scene.*list)[size_t(sel.index)] = std::move(edited);
  state.edit(std::move(scene), "Edit " + param, merge_key(sel, param));
}

// Generated widgets, except that names referring to other items (a mix's materials,
// an emitter's object) are combos of the names that exist rather than typed text.
using References = std::vector<std::pair<std::string_view, std::vector<std::string>>>;  // parameter -> names

struct ReferenceWidgets {
  References references;
  ParamWidgets widgets;

  template <class F>
  void operator()(const Param& p, F& value) {
    widgets(p, value);
  }
  void operator()(const Param& p, std::string& value) {
    const auto it =
        std::find_if(references.begin(), references.end(), [&](const auto& r) { return r.first == p.name; });
    if (it == references.end()) return widgets(p, value);
    const std::string label(p.name);
    if (ImGui::BeginCombo(label.c_str(), value.empty() ? "(none)" : value.c_str())) {
      for (const std::string& name : it->second) {
        if (ImGui::Selectable(name.c_str(), name == value) && name != value) {
          value = name;
          widgets.changed = true;
          widgets.changed_param = label;
        }
      }
      ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered() && !p.doc.empty()) ImGui::SetTooltip("%.*s", int(p.doc.size()), p.doc.data());
  }
};

template <class Desc>
bool edit_with_references(Desc& desc, References references, std::string* param) {
  ReferenceWidgets widgets;
  widgets.references = std::move(references);
  visit_params(desc, widgets);
  if (widgets.widgets.changed) *param = widgets.widgets.changed_param;
  return widgets.widgets.changed;
}

template <class T>
std::vector<std::string> names_of(const std::vector<T>& items, std::string_view except = {}) {
  std::vector<std::string> names;
  for (const T& item : items)
    if (item.name != except) names.push_back(item.name);
  return names;
}

bool edit_emitter(const SceneDesc& scene, StrokeEmitterDesc& emitter, std::string* param) {
  return edit_with_references(emitter, {{"object", names_of(scene.objects)}}, param);
}

// The material's type and settings; a graph's nodes are the node editor's.
bool edit_material_data(EditorState& state, MaterialDesc& m, std::string* param) {
  const MaterialVariant before = m.data;
  bool changed = edit_variant_type("type", m.data);
  if (changed) *param = "type";
  // Turning a material into a graph keeps its look: it becomes that material's closure node.
  if (changed && std::holds_alternative<GraphDesc>(m.data)) m.data = graph_from_material(before);
  const SceneDesc& scene = state.document.scene();
  std::visit(
      [&]<class T>(T& data) {
        if constexpr (std::is_same_v<T, GraphDesc>) {
          ImGui::TextDisabled("%zu nodes, %zu links", data.nodes.size(), data.links.size());
        } else if constexpr (std::is_same_v<T, MixDesc>) {
          // A mix of itself would be a cycle.
          const std::vector<std::string> others = names_of(scene.materials, m.name);
          changed |= edit_with_references(data, {{"a", others}, {"b", others}}, param);
        } else {
          changed |= edit_params(data, param);
        }
      },
      m.data);
  if (ImGui::Button("Edit nodes")) state.want_node_editor = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Open the node editor on this material (a plain one becomes a graph at the first edit)");
  return changed;
}

bool edit_transform(TransformDesc& t, std::string* param) {
  bool changed = false;
  // Within what the reader accepts: positions in +-kMaxCoordinate, no zero scale factor.
  const float reach = float(kMaxCoordinate);
  if (ImGui::DragFloat3("translate", &t.translate.x, 0.01f, -reach, reach, "%.3f")) changed = true, *param = "translate";
  Vec3 scale = t.scale;
  if (ImGui::DragFloat3("scale", &scale.x, 0.01f, -reach, reach, "%.3f") && scale.x != 0.f && scale.y != 0.f &&
      scale.z != 0.f)
    t.scale = scale, changed = true, *param = "scale";
  for (size_t i = 0; i < t.rotate.size(); ++i) {
    ImGui::PushID(int(i));
    std::string rotation_param;
    if (edit_params(t.rotate[i], &rotation_param)) changed = true, *param = "rotate" + std::to_string(i) + rotation_param;
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

void material_combo(const SceneDesc& scene, std::string& material, bool* changed, std::string* param) {
  if (!ImGui::BeginCombo("material", material.c_str())) return;
  for (const MaterialDesc& m : scene.materials) {
    if (ImGui::Selectable(m.name.c_str(), m.name == material) && m.name != material) {
      material = m.name;
      *changed = true;
      *param = "material";
    }
  }
  ImGui::EndCombo();
}

void material_section(EditorState& state, int index) {
  const SceneDesc& scene = state.document.scene();
  const Selection sel{ItemKind::material, index};
  MaterialDesc m = scene.materials[size_t(index)];
  std::string param;
  bool changed = false;
  ImGui::PushID("material");
  ParamWidgets name_widget;
  name_widget(text("name", "Unique material name"), m.name);
  if (name_widget.changed) changed = true, param = "name";
  changed |= edit_material_data(state, m, &param);
  if (ImGui::TreeNode("outline overrides")) {
    changed |= edit_params(m.lines, &param);
    ImGui::TreePop();
  }
  ImGui::PopID();
  if (changed) commit_named(state, sel, &SceneDesc::materials, std::move(m), param);
}

void object_section(EditorState& state, int index) {
  const SceneDesc& scene = state.document.scene();
  const Selection sel{ItemKind::object, index};
  ObjectDesc o = scene.objects[size_t(index)];
  std::string param;
  bool changed = false;
  ParamWidgets name_widget;
  name_widget(text("name", "Unique object name"), o.name);
  if (name_widget.changed) changed = true, param = "name";
  material_combo(scene, o.material, &changed, &param);
  if (ImGui::Checkbox("visible", &o.visible)) changed = true, param = "visible";
  section_title("Transform");
  changed |= edit_transform(o.transform, &param);
  section_title("Shape");
  changed |= edit_tagged("shape", o.shape, &param);
  if (ImGui::TreeNode("outline overrides")) {
    changed |= edit_params(o.lines, &param);
    ImGui::TreePop();
  }
  if (changed) {
    commit_named(state, sel, &SceneDesc::objects, std::move(o), param);
    return;
  }
  // The object's material, so the look can be tuned without leaving the object.
  for (int m = 0; m < int(scene.materials.size()); ++m) {
    if (scene.materials[size_t(m)].name == scene.objects[size_t(index)].material) {
      section_title(("Material: " + scene.materials[size_t(m)].name).c_str());
      material_section(state, m);
      break;
    }
  }
  for (int e = 0; e < int(scene.strokes.size()); ++e) {
    if (scene.strokes[size_t(e)].object != scene.objects[size_t(index)].name) continue;
    ImGui::PushID(e);
    section_title(("Strokes: " + scene.strokes[size_t(e)].name).c_str());
    StrokeEmitterDesc emitter = scene.strokes[size_t(e)];
    std::string emitter_param;
    if (edit_emitter(scene, emitter, &emitter_param)) {
      commit_named(state, {ItemKind::emitter, e}, &SceneDesc::strokes, std::move(emitter), emitter_param);
      ImGui::PopID();
      return;
    }
    ImGui::PopID();
  }
}

// Singletons (camera, render settings, outlines, environment) have no name to keep consistent.
template <class T>
void singleton_section(EditorState& state, ItemKind kind, T SceneDesc::*member) {
  T value = state.document.scene().*member;
  std::string param;
  bool changed;
  if constexpr (requires { std::variant_size<T>::value; }) {
    changed = edit_tagged("type", value, &param);
  } else {
    changed = edit_params(value, &param);
  }
  if (changed) {
    SceneDesc scene = state.document.scene();
    scene.*member = std::move(value);
    state.edit(std::move(scene), "Edit " + param, merge_key({kind, -1}, param));
  }
}

}  // namespace

void draw_properties_panel(EditorState& state) {
  const SceneDesc& scene = state.document.scene();
  const Selection sel = validated(scene, state.selection);
  if (sel.kind == ItemKind::none) {
    ImGui::TextDisabled("Select an item in the scene graph or click the viewport.");
    return;
  }
  ImGui::Text("%s", item_name(scene, sel).c_str());
  ImGui::Separator();
  ImGui::PushItemWidth(-130.f);
  switch (sel.kind) {
    case ItemKind::camera: singleton_section(state, sel.kind, &SceneDesc::camera); break;
    case ItemKind::render: singleton_section(state, sel.kind, &SceneDesc::render); break;
    case ItemKind::outlines: singleton_section(state, sel.kind, &SceneDesc::outlines); break;
    case ItemKind::environment: singleton_section(state, sel.kind, &SceneDesc::environment); break;
    case ItemKind::object: object_section(state, sel.index); break;
    case ItemKind::material: material_section(state, sel.index); break;
    case ItemKind::light: {
      LightDesc light = scene.lights[size_t(sel.index)];
      std::string param;
      ParamWidgets name_widget;
      name_widget(text("name", "Light name"), light.name);
      bool changed = name_widget.changed;
      if (changed) param = "name";
      changed |= edit_tagged("type", light.data, &param);
      if (changed) commit_named(state, sel, &SceneDesc::lights, std::move(light), param);
      break;
    }
    case ItemKind::emitter: {
      StrokeEmitterDesc emitter = scene.strokes[size_t(sel.index)];
      std::string param;
      if (edit_emitter(scene, emitter, &param)) commit_named(state, sel, &SceneDesc::strokes, std::move(emitter), param);
      break;
    }
    case ItemKind::none: break;
  }
  ImGui::PopItemWidth();
}

}  // namespace inkray
