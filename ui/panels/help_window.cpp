#include "ui/panels/help_window.h"

#include <imgui.h>

#include <iterator>

namespace inkray {
namespace {

struct Shortcut {
  const char* keys;
  const char* action;
};

struct ShortcutGroup {
  const char* title;
  const Shortcut* begin;
  const Shortcut* end;
};

constexpr Shortcut kDocument[] = {
    {"Ctrl+N", "New scene"},
    {"Ctrl+O", "Open a scene"},
    {"Ctrl+S / Ctrl+Shift+S", "Save / save as"},
    {"Ctrl+Z", "Undo"},
    {"Ctrl+Shift+Z, Ctrl+Y", "Redo"},
    {"Ctrl+D", "Duplicate the selection"},
    {"Delete", "Delete the selection"},
    {"Ctrl+= / Ctrl+- / Ctrl+0", "Larger / smaller / default UI scale"},
    {"F1", "This window"},
    {"Drop a file on the window",
     ".json opens it, .obj imports it (fitted to the view), an image becomes the "
     "selected material's texture (or the selected emitter's brush)"},
};

constexpr Shortcut kViewport[] = {
    {"Left drag", "Orbit"},
    {"Shift+left drag, middle drag", "Pan"},
    {"Right drag, wheel", "Dolly"},
    {"Click", "Select the object under the cursor"},
    {"Ctrl+click", "Focus the camera at the point under the cursor"},
    {"F", "Frame the selection (or the scene)"},
    {"Gizmo handles",
     "Drag an arrow, a plane square, a ring or the centre to move, rotate or scale the "
     "selection; Ctrl snaps, Esc cancels; each drag is one undo step"},
    {"W", "Cycle the gizmo: move, rotate, scale"},
    {"G / R / S",
     "Move / rotate / scale with the mouse; X, Y, Z constrain to an axis (again: free), digits "
     "type the value ('-' negates), Ctrl snaps, click or Enter confirms, right click or Esc cancels"},
    {"I", "Show or hide the statistics overlay (over a field, I keys it)"},
};

constexpr Shortcut kTimeline[] = {
    {"Space", "Play / pause: from the current frame to the shot's last, then again from its first"},
    {"Left / Right", "Previous / next frame (over the viewport or the timeline)"},
    {"Shift+Left / Shift+Right", "First / last frame of the shot"},
    {"Up / Down", "Next / previous frame with a key"},
    {"Click, drag the timeline", "Go to that frame"},
    {"I", "Key the field under the mouse at the current frame (or the one being edited)"},
    {"Alt+I", "Delete that field's key at the current frame"},
    {"Right click a field", "Insert key, delete key, clear all its keys"},
    {"Edit an animated field",
     "Keys it at the current frame (a yellow diamond: a key here; green: "
     "animated, no key here)"},
};

constexpr Shortcut kNodes[] = {
    {"Shift+A, right click", "Add a node"},
    {"Drag from a pin", "Link; drop on empty canvas to add a node that takes the link"},
    {"Click, Shift+click, drag", "Select nodes"},
    {"Delete, X", "Delete the selected nodes"},
    {"Ctrl+C / Ctrl+V", "Copy / paste"},
    {"Shift+D", "Duplicate"},
    {"Wheel / middle drag, Alt+drag", "Zoom / pan"},
    {"Home", "Frame all nodes"},
};

constexpr ShortcutGroup kGroups[] = {
    {"Documents", std::begin(kDocument), std::end(kDocument)},
    {"Viewport", std::begin(kViewport), std::end(kViewport)},
    {"Timeline and keys", std::begin(kTimeline), std::end(kTimeline)},
    {"Node editor", std::begin(kNodes), std::end(kNodes)},
};

}  // namespace

void HelpWindow::draw() {
  const float em = ImGui::GetFontSize();
  if (shortcuts_open_) {
    ImGui::SetNextWindowSize(ImVec2(46 * em, 34 * em), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::Begin("Shortcuts and help", &shortcuts_open_)) {
      ImGui::TextWrapped(
          "Sliders: drag to change, Ctrl+click to type a value beyond the slider's range. Hover a field to "
          "read "
          "what it does and its key in the scene file. The scene format and every node are described in "
          "docs/scene-format.md; the README explains the editor.");
      for (const ShortcutGroup& group : kGroups) {
        ImGui::Spacing();
        ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.f, 1.f), "%s", group.title);
        if (ImGui::BeginTable(group.title, 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
          ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, 15 * em);
          ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
          for (const Shortcut* s = group.begin; s != group.end; ++s) {
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", s->keys);
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", s->action);
          }
          ImGui::EndTable();
        }
      }
    }
    ImGui::End();
  }
  if (about_open_) {
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(30 * em, 0), ImGuiCond_Appearing);
    if (ImGui::Begin("About inkray", &about_open_, ImGuiWindowFlags_NoCollapse)) {
      ImGui::TextUnformatted("inkray");
      ImGui::TextWrapped(
          "A path tracer for non-photorealistic rendering: toon outlines, cel shading and painterly strokes "
          "computed inside a physically based renderer, so lines show in mirrors and through glass.");
      ImGui::Separator();
      ImGui::TextWrapped(
          "Built with Dear ImGui %s, GLFW, Embree 3, oneTBB, GLM, tinyobjloader, nlohmann_json "
          "and stb. The interface font is DejaVu Sans (Bitstream Vera licence, "
          "resources/fonts/DejaVu-LICENSE.txt).",
          IMGUI_VERSION);
    }
    ImGui::End();
  }
}

}  // namespace inkray
