#include "ui/widgets/key_actions.h"

#include "core/document/animation_edit.h"

#include <imgui.h>

#include <cstdio>
#include <string>
#include <utility>

namespace inkray {

void apply_key_actions(EditorState& state, KeyTargets& keys) {
  const ImGuiIO& io = ImGui::GetIO();
  using Action = KeyTargets::Action;
  std::string target = keys.hovered;
  if (target.empty() && ImGui::IsWindowHovered(ImGuiHoveredFlags_RootAndChildWindows)) target = keys.focused;
  // ImGui 1.86 indexes keys by the GLFW key code, which for letters is the ASCII capital.
  const bool plain_i = !io.WantTextInput && !io.KeyCtrl && !io.KeyShift && ImGui::IsKeyPressed('I', false);
  if (!target.empty() && plain_i) {
    keys.action = io.KeyAlt ? Action::remove : Action::insert;
    keys.action_path = target;
  }
  if (keys.action == Action::none) return;
  SceneDesc scene = state.document.scene();
  const double frame = scene.render.frame;
  const std::string& path = keys.action_path;
  char at[64];
  std::snprintf(at, sizeof at, " at frame %g", frame);
  switch (keys.action) {
    case Action::insert:
      if (key_shown_value(scene, path, frame)) state.edit(std::move(scene), "Insert key");
      break;
    case Action::remove:
      if (unkey(scene, path, frame)) {
        state.edit(std::move(scene), "Delete key");
      } else {
        state.log.info(path + " has no key" + at);
      }
      break;
    case Action::clear:
      if (clear_keys(scene, path)) state.edit(std::move(scene), "Clear keys");
      break;
    case Action::none:
      break;
  }
}

}  // namespace inkray
