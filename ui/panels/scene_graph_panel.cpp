#include "ui/panels/scene_graph_panel.h"

#include "ui/widgets/material_swatches.h"
#include "ui/model/scene_edits.h"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace inkray {
namespace {

// A structural edit that would leave the scene unrenderable (deleting a material a
// mix uses) is refused, and the log says why (EditorState::edit_checked).
void apply_structural(EditorState& state, const char* label, const auto& change) {
  SceneDesc scene = state.document.scene();
  const Selection selected = change(scene);
  if (state.edit_checked(std::move(scene), label)) state.selection = selected;
}

void delete_selected(EditorState& state, const Selection& item, const std::string& name) {
  SceneDesc s = state.document.scene();
  if (!delete_item(s, item)) {
    state.log.warning("cannot delete " + name + ": objects still use it");
  } else if (state.edit_checked(std::move(s), "Delete")) {
    state.selection = {};
  }
}

void item_row(EditorState& state, const Selection& item, const std::string& name, bool hidden = false) {
  ImGui::PushID(int(item.kind) * 100000 + item.index);
  if (item.kind == ItemKind::material && state.swatches) {
    // The material's swatch, as the node editor's output shows it.
    const float side = ImGui::GetTextLineHeight();
    if (const ImTextureID swatch = state.swatches->texture(name))
      ImGui::Image(swatch, ImVec2(side, side));
    else
      ImGui::Dummy(ImVec2(side, side));
    ImGui::SameLine();
  }
  if (hidden) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  if (ImGui::Selectable(name.c_str(), state.selection == item)) state.selection = item;
  if (hidden) ImGui::PopStyleColor();
  if (ImGui::BeginPopupContextItem()) {
    state.selection = item;
    if (item.index >= 0) {
      if (ImGui::MenuItem("Duplicate", "Ctrl+D")) {
        apply_structural(state, "Duplicate", [&](SceneDesc& s) { return duplicate_item(s, item); });
      }
      if (ImGui::MenuItem("Delete", "Del")) delete_selected(state, item, name);
      if (item.kind == ItemKind::object) {
        const bool visible = state.document.scene().objects[size_t(item.index)].visible;
        if (ImGui::MenuItem(visible ? "Hide" : "Show")) {
          SceneDesc s = state.document.scene();
          set_visible(s, item, !visible);
          state.edit(std::move(s), visible ? "Hide" : "Show");
        }
        if (ImGui::MenuItem("Add stroke emitter")) {
          apply_structural(state, "Add stroke emitter",
                           [&](SceneDesc& s) { return add_stroke_emitter(s, name); });
        }
      }
    }
    ImGui::EndPopup();
  }
  ImGui::PopID();
}

template <class T>
void item_list(EditorState& state, const char* title, ItemKind kind, const SharedList<T>& items) {
  if (!ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::Indent(8.f);
  for (int i = 0; i < int(items.size()); ++i) {
    bool hidden = false;
    if constexpr (std::is_same_v<T, ObjectDesc>) hidden = !items[size_t(i)].visible;
    item_row(state, {kind, i}, items[size_t(i)].name + (hidden ? "  (hidden)" : ""), hidden);
  }
  ImGui::Unindent(8.f);
}

void add_menu(EditorState& state) {
  if (ImGui::Button("Add...")) ImGui::OpenPopup("add_menu");
  if (!ImGui::BeginPopup("add_menu")) return;
  if (ImGui::MenuItem("Sphere"))
    apply_structural(state, "Add sphere", [](SceneDesc& s) { return add_shape(s, NewShape::sphere); });
  if (ImGui::MenuItem("Quad"))
    apply_structural(state, "Add quad", [](SceneDesc& s) { return add_shape(s, NewShape::quad); });
  if (ImGui::MenuItem("Box"))
    apply_structural(state, "Add box", [](SceneDesc& s) { return add_shape(s, NewShape::box); });
  if (ImGui::MenuItem("Mesh from OBJ...")) state.want_add_mesh = true, state.add_mesh_native_size = false;
  if (ImGui::MenuItem("Mesh from OBJ, native size..."))
    state.want_add_mesh = true, state.add_mesh_native_size = true;
  ImGui::Separator();
  if (ImGui::MenuItem("Point light"))
    apply_structural(state, "Add light", [](SceneDesc& s) { return add_point_light(s); });
  if (ImGui::MenuItem("Material"))
    apply_structural(state, "Add material", [](SceneDesc& s) { return add_material(s); });
  const SceneDesc& scene = state.document.scene();
  const bool object_selected = state.selection.kind == ItemKind::object && is_valid(scene, state.selection);
  if (ImGui::MenuItem("Stroke emitter on selection", nullptr, false, object_selected)) {
    const std::string object = scene.objects[size_t(state.selection.index)].name;
    apply_structural(state, "Add stroke emitter",
                     [&](SceneDesc& s) { return add_stroke_emitter(s, object); });
  }
  ImGui::EndPopup();
}

}  // namespace

void draw_scene_graph_panel(EditorState& state) {
  add_menu(state);
  ImGui::SameLine();
  const bool has_item = state.selection.index >= 0 && is_valid(state.document.scene(), state.selection);
  ImGui::BeginDisabled(!has_item);
  if (ImGui::Button("Duplicate")) {
    const Selection item = state.selection;
    apply_structural(state, "Duplicate", [&](SceneDesc& s) { return duplicate_item(s, item); });
  }
  ImGui::SameLine();
  if (ImGui::Button("Delete"))
    delete_selected(state, state.selection, item_name(state.document.scene(), state.selection));
  ImGui::EndDisabled();
  ImGui::Separator();

  ImGui::BeginChild("tree");
  const SceneDesc& scene = state.document.scene();
  for (auto [kind, name] : {std::pair{ItemKind::camera, "Camera"},
                            {ItemKind::render, "Render settings"},
                            {ItemKind::environment, "Environment"},
                            {ItemKind::outlines, "Outlines"}}) {
    item_row(state, {kind, -1}, name);
  }
  item_list(state, "Objects", ItemKind::object, scene.objects);
  item_list(state, "Lights", ItemKind::light, scene.lights);
  item_list(state, "Materials", ItemKind::material, scene.materials);
  item_list(state, "Stroke emitters", ItemKind::emitter, scene.strokes);
  ImGui::EndChild();
}

}  // namespace inkray
