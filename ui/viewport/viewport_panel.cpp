#include "ui/viewport/viewport_panel.h"

#include "ui/widgets/fonts.h"
#include "ui/viewport/gizmo_drawing.h"
#include "ui/widgets/gl_texture.h"
#include "ui/viewport/picking.h"
#include "ui/model/scene_edits.h"
#include "ui/viewport/viewport_overlay.h"
#include "ui/widgets/toolbar_flow.h"
#include "ui/widgets/widget_report.h"

#include <GL/gl.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace inkray {
namespace {

constexpr const char* kNavMergeKey = "viewport:camera";
constexpr float kClickSlop = 3.f;  // window pixels a click may stray before it is a drag
constexpr int kStatsKey = 'I';
constexpr int kGizmoModeKey = 'W';

// Whether the viewport may take a plain key: no widget wants text and no Ctrl or Alt
// (those are the menus' shortcuts).
bool plain_key(int key) {
  const ImGuiIO& io = ImGui::GetIO();
  return !io.WantTextInput && !io.KeyCtrl && !io.KeyAlt && ImGui::IsKeyPressed(key, false);
}

bool key_pressed(ImGuiKey key, bool repeat = false) {
  return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), repeat);
}

std::string display_name(int display) {
  if (display == kDisplayNoise) return "noise estimate";
  return display < 0 ? std::string("final") : std::string(kAovNames[size_t(display)]);
}

}  // namespace

ViewportPanel::ViewportPanel() : texture_(make_image_texture()) {}

ViewportPanel::~ViewportPanel() { glDeleteTextures(1, &texture_); }

void ViewportPanel::upload(const ViewportSnapshot& s) {
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (s.width != texture_w_ || s.height != texture_h_) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, s.width, s.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, s.rgba.data());
    texture_w_ = s.width;
    texture_h_ = s.height;
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, s.width, s.height, GL_RGBA, GL_UNSIGNED_BYTE, s.rgba.data());
  }
}

void ViewportPanel::toolbar(EditorState& state) {
  ToolbarFlow flow;
  flow.next(8.f * ImGui::GetFontSize());
  ImGui::SetNextItemWidth(8.f * ImGui::GetFontSize());
  if (ImGui::BeginCombo("##display", display_name(state.view.display).c_str())) {
    // The final image, the noise estimate, then the AOVs.
    for (int d : {kDisplayFinal, kDisplayNoise}) {
      if (ImGui::Selectable(display_name(d).c_str(), d == state.view.display)) state.view.display = d;
    }
    for (int d = 0; d < int(kAovNames.size()); ++d) {
      if (ImGui::Selectable(display_name(d).c_str(), d == state.view.display)) state.view.display = d;
    }
    ImGui::EndCombo();
  }
  widget_report::item("viewport.display");
  flow.next(labelled_width(7.f * ImGui::GetFontSize(), "exposure"));
  ImGui::SetNextItemWidth(7.f * ImGui::GetFontSize());
  ImGui::SliderFloat("exposure", &state.view.encoding.exposure, -8.f, 8.f, "%.1f EV");
  widget_report::item("viewport.exposure");
  flow.next(7.f * ImGui::GetFontSize());
  ImGui::SetNextItemWidth(7.f * ImGui::GetFontSize());
  int transform = int(state.view.encoding.transform);
  if (ImGui::BeginCombo("##transform", std::string(kViewTransformNames[size_t(transform)]).c_str())) {
    for (int t = 0; t < int(kViewTransformNames.size()); ++t) {
      if (ImGui::Selectable(std::string(kViewTransformNames[size_t(t)]).c_str(), t == transform)) {
        state.view.encoding.transform = ViewTransform(t);
      }
    }
    ImGui::EndCombo();
  }
  widget_report::item("viewport.view_transform");
  flow.next(checkbox_width("Denoise"));
  ImGui::Checkbox("Denoise", &state.view.denoise);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Denoise the final image (lines, ids and toon bands stay crisp); the samples so far stay");
  widget_report::item("viewport.denoise");
  const char* pause = state.paused ? "Resume" : "Pause";
  flow.next(button_width(pause));
  if (ImGui::Button(pause)) state.paused = !state.paused;
  widget_report::item("viewport.pause");
  flow.next(checkbox_width("Region"));
  ImGui::Checkbox("Region", &state.region_tool);
  widget_report::item("viewport.region");
  if (!state.region.empty()) {
    flow.next(button_width("Clear region"));
    if (ImGui::Button("Clear region")) state.region = {};
    widget_report::item("viewport.clear_region");
  }
  flow.next(button_width("Frame (F)"));
  if (ImGui::Button("Frame (F)")) state.want_frame_selected = true;
  widget_report::item("viewport.frame");
  flow.next(button_width("Reset camera"));
  if (ImGui::Button("Reset camera")) {
    SceneDesc scene = state.document.scene();
    scene.camera = state.home_camera;
    state.edit(std::move(scene), "Reset camera");
  }
  widget_report::item("viewport.reset_camera");
  static constexpr const char* kModeWidgets[3] = {"viewport.gizmo_move", "viewport.gizmo_rotate",
                                                  "viewport.gizmo_scale"};
  for (int m = 0; m < 3; ++m) {
    const char* label = kGizmoModeNames[m];
    flow.next(checkbox_width(label));
    if (ImGui::RadioButton(label, int(gizmo_mode_) == m)) gizmo_mode_ = GizmoMode(m);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Gizmo mode (W cycles); G, R, S move, rotate, scale with the mouse");
    widget_report::item(kModeWidgets[m]);
  }
  flow.next(checkbox_width("Stats (I)"));
  ImGui::Checkbox("Stats (I)", &show_stats_);
  widget_report::item("viewport.stats");
}

void ViewportPanel::edit_transform(EditorState& state, int object, const TransformDesc& t, const char* label,
                                   const std::string& merge_key) {
  if (state.shown().objects[size_t(object)].transform == t) return;
  // No button is held through a G/R/S tool, so nothing keeps the merge open: its step
  // is replaced instead, while it is still the newest.
  if (merge_key.empty() && own_revision_ == state.document.revision()) state.document.discard_newest();
  SceneDesc edited = state.document.scene();
  edited.objects[size_t(object)].transform = t;
  state.edit(std::move(edited), label, merge_key);
  own_revision_ = state.document.revision();
}

void ViewportPanel::restore_transform(EditorState& state, int object, const TransformDesc& original) {
  if (own_revision_ != 0 && own_revision_ == state.document.revision()) {
    state.document.discard_newest();  // the drag's own step, still the newest: gone as if never made
  } else if (object < int(state.document.scene().objects.size()) &&
             !(state.shown().objects[size_t(object)].transform == original)) {
    SceneDesc edited = state.document.scene();
    edited.objects[size_t(object)].transform = original;
    state.edit(std::move(edited), "Cancel transform");
  }
  own_revision_ = 0;
}

bool ViewportPanel::tool_input(EditorState& state, const ViewMapping& view, int object) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!tool_.active()) {
    if (object < 0 || !ImGui::IsItemHovered()) return false;
    static constexpr int kKeys[3] = {'G', 'R', 'S'};
    for (int m = 0; m < 3; ++m) {
      if (!plain_key(kKeys[m])) continue;
      tool_.begin(GizmoMode(m), state.shown().objects[size_t(object)], view,
                  Vec2(io.MousePos.x, io.MousePos.y));
      moving_object_ = object;
      own_revision_ = 0;
      return true;
    }
    return false;
  }
  if (object != moving_object_) {  // undone, deleted or deselected under the tool
    tool_.cancel();
    own_revision_ = 0;
    return false;
  }
  tool_.mouse_move(Vec2(io.MousePos.x, io.MousePos.y), io.KeyCtrl);
  for (int a = 0; a < 3; ++a) {
    if (plain_key('X' + a)) tool_.constrain(a);
  }
  for (ImWchar c : io.InputQueueCharacters) {
    if ((c >= '0' && c <= '9') || c == '.' || c == '-') tool_.type(char(c));
  }
  if (key_pressed(ImGuiKey_Backspace, true)) tool_.backspace();
  const char* label = kGizmoModeNames[int(tool_.mode())];
  if (key_pressed(ImGuiKey_Escape) || ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
    restore_transform(state, object, tool_.cancel());
    ignore_until_release_ = ImGui::IsItemActivated();  // the click that cancelled picks nothing
  } else if (key_pressed(ImGuiKey_Enter) || key_pressed(ImGuiKey_KeyPadEnter) ||
             ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    edit_transform(state, object, tool_.confirm(), label, {});
    ignore_until_release_ = ImGui::IsItemActivated();
    own_revision_ = 0;
  } else {
    edit_transform(state, object, tool_.transform(), label, {});
    const GizmoFrame frame = gizmo_frame(state.shown().objects[size_t(object)], tool_.mode(), view);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    if (tool_.axis() >= 0) draw_axis_line(draw, frame, tool_.axis(), view);
    draw_header(draw, ImVec2(view.origin.x + 6.f, view.origin.y + 6.f), tool_.header());
  }
  return true;
}

bool ViewportPanel::gizmo_input(EditorState& state, const ViewMapping& view, int object, bool activated,
                                bool active) {
  const ImGuiIO& io = ImGui::GetIO();
  if (object < 0) {
    gizmo_drag_.reset();
    return false;
  }
  const ObjectDesc& o = state.shown().objects[size_t(object)];
  const GizmoFrame frame = gizmo_frame(o, gizmo_mode_, view);
  if (activated && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !state.region_tool) {
    const GizmoHandle handle = pick_handle(frame, gizmo_mode_, view, press_);
    if (handle.kind != HandleKind::none) {
      gizmo_drag_.emplace(o, gizmo_mode_, handle, view, press_);
      moving_object_ = object;
      own_revision_ = 0;
      ++drags_;
      ignore_until_release_ = true;  // its release is no click
    }
  }
  if (gizmo_drag_ && (!active || moving_object_ != object)) gizmo_drag_.reset();
  if (gizmo_drag_ && key_pressed(ImGuiKey_Escape)) {
    restore_transform(state, object, gizmo_drag_->original());
    gizmo_drag_.reset();
    ignore_until_release_ = true;
    return true;
  }
  GizmoHandle hot;
  if (gizmo_drag_) {
    const TransformDesc t = gizmo_drag_->drag_to(Vec2(io.MousePos.x, io.MousePos.y), io.KeyCtrl);
    edit_transform(state, object, t, kGizmoModeNames[int(gizmo_mode_)],
                   "viewport:gizmo:" + std::to_string(drags_));
    hot = gizmo_drag_->handle();
  } else if (!active && ImGui::IsItemHovered()) {
    hot = pick_handle(frame, gizmo_mode_, view, Vec2(io.MousePos.x, io.MousePos.y));
  }
  // Drawn from the document as edited this frame, so the gizmo stays under the mouse.
  draw_gizmo(ImGui::GetWindowDrawList(),
             gizmo_frame(state.shown().objects[size_t(object)], gizmo_mode_, view), gizmo_mode_, view, hot);
  return gizmo_drag_.has_value();
}

void ViewportPanel::handle_input(EditorState& state, const ProgressiveRenderer& renderer, float x, float y,
                                 float w, float h) {
  ImGui::SetCursorScreenPos(ImVec2(x, y));
  ImGui::InvisibleButton("viewport_input", ImVec2(w, h),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  const ImGuiIO& io = ImGui::GetIO();
  const bool hovered = ImGui::IsItemHovered();
  const bool active = ImGui::IsItemActive();
  const bool activated = ImGui::IsItemActivated();
  // What is on screen: the document at its frame. Edits start from it and go to the document.
  const SceneDesc& scene = state.shown();
  const float image_width = float(std::max(scene.render.width, 1)),
              image_height = float(std::max(scene.render.height, 1));
  const float to_image = image_height / std::max(h, 1.f);  // window pixels -> image pixels
  const ViewMapping view{Camera(scene.camera, int(image_width), int(image_height)), Vec2(x, y),
                         1.f / to_image, ui_scale_of_font()};
  const Vec2 mouse(io.MousePos.x, io.MousePos.y);
  const auto fraction = [&](Vec2 p) {
    return Vec2(std::clamp((p.x - x) / w, 0.f, 1.f), std::clamp((p.y - y) / h, 0.f, 1.f));
  };
  const int object = state.selection.kind == ItemKind::object && is_valid(scene, state.selection)
                         ? state.selection.index
                         : -1;

  if (activated) {
    // Where the button went down: the cursor may have jumped there in this very frame.
    for (int b = 0; b < 3; ++b) {
      if (ImGui::IsMouseClicked(b)) press_ = Vec2(io.MouseClickedPos[b].x, io.MouseClickedPos[b].y);
    }
    drag_distance_ = glm::length(mouse - press_);
    dragging_region_ = state.region_tool && ImGui::IsMouseDown(ImGuiMouseButton_Left);
  }
  if (active) drag_distance_ = std::max(drag_distance_, glm::length(mouse - press_));

  const bool tool_running = tool_input(state, view, object);
  const bool gizmo_dragging = !tool_running && gizmo_input(state, view, object, activated, active);
  const bool navigating = !tool_running && !gizmo_dragging && !ignore_until_release_;
  const bool moved = io.MouseDelta.x != 0.f || io.MouseDelta.y != 0.f;

  if (navigating && active && dragging_region_) {
    const Vec2 a = press_;
    ImGui::GetWindowDrawList()->AddRect(ImVec2(std::min(a.x, mouse.x), std::min(a.y, mouse.y)),
                                        ImVec2(std::max(a.x, mouse.x), std::max(a.y, mouse.y)),
                                        IM_COL32(255, 200, 60, 255), 0.f, 0, 1.5f);
  } else if (navigating && active && !activated && moved && drag_distance_ > kClickSlop) {
    CameraDesc camera = state.shown().camera;
    const bool pan_drag = ImGui::IsMouseDown(ImGuiMouseButton_Middle) ||
                          (ImGui::IsMouseDown(ImGuiMouseButton_Left) && io.KeyShift);
    if (pan_drag) {
      camera = pan(camera, io.MouseDelta.x * to_image, io.MouseDelta.y * to_image, image_height);
    } else if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
      camera = controller_.drag_dolly(camera, io.MouseDelta.y);
    } else if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      camera = controller_.drag_orbit(camera, io.MouseDelta.x, io.MouseDelta.y);
    }
    SceneDesc edited = state.document.scene();
    edited.camera = camera;
    state.edit(std::move(edited), "Move camera", kNavMergeKey);
  }
  if (!tool_running && hovered && io.MouseWheel != 0.f) {
    SceneDesc edited = state.document.scene();
    edited.camera = controller_.wheel(state.shown().camera, io.MouseWheel);
    state.edit(std::move(edited), "Dolly camera");
  }
  if (ImGui::IsItemDeactivated()) {
    if (!navigating) {
      // The press belonged to the tool or a cancelled drag.
    } else if (dragging_region_) {
      const Vec2 a = fraction(press_), b = fraction(mouse);
      RegionRect r{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
      if ((r.x1 - r.x0) * w > 4.f && (r.y1 - r.y0) * h > 4.f) state.region = r;
    } else if (drag_distance_ <= kClickSlop && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
      // A click, not a drag: pick, or with Ctrl focus on what is under the cursor.
      if (auto compiled = renderer.scene()) {
        const Vec2 f = fraction(press_);
        const float iw = float(compiled->sampling.width), ih = float(compiled->sampling.height);
        const PickResult hit =
            pick(*compiled, Camera(scene.camera, int(iw), int(ih)), Vec2(f.x * iw, f.y * ih));
        if (io.KeyCtrl) {
          if (hit.object >= 0) {
            SceneDesc edited = state.document.scene();
            edited.camera = focus_at(state.shown().camera, hit.depth);
            state.edit(std::move(edited), "Focus");
            state.log.info("focus distance " + std::to_string(hit.depth));
          }
        } else {
          state.selection = hit.object >= 0 ? Selection{ItemKind::object, hit.object} : Selection{};
        }
      }
    }
    dragging_region_ = false;
    ignore_until_release_ = false;
  }
  if (tool_running) return;
  // ImGui 1.86 indexes keys by the GLFW key code, which for letters is the ASCII capital.
  // Keys reach the viewport only when no widget takes text or keyboard input.
  if (ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) && plain_key('F'))
    state.want_frame_selected = true;
  if (hovered && plain_key(kGizmoModeKey)) gizmo_mode_ = GizmoMode((int(gizmo_mode_) + 1) % 3);
  if (hovered && plain_key(kStatsKey)) show_stats_ = !show_stats_;
}

ViewportFrame ViewportPanel::draw(EditorState& state, ProgressiveRenderer& renderer) {
  ViewportFrame frame;
  toolbar(state);
  const uint64_t generation = renderer.generation();
  if (generation != uploaded_generation_) {
    if (auto s = renderer.latest()) {
      upload(*s);
      if (s->revision != shown_revision_) frame.new_revision_shown = s->revision;
      shown_revision_ = s->revision;
      shown_divisor_ = s->divisor;
      shown_spp_ = s->stats.spp;
      shown_denoised_ = s->denoised;
      snapshot_ = std::move(s);
    }
    uploaded_generation_ = generation;
  }
  // Fit the image's aspect into the space left, centred.
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const SceneDesc& scene = state.document.scene();
  const float aspect = float(scene.render.width) / float(std::max(scene.render.height, 1));
  float w = avail.x, h = avail.x / aspect;
  if (h > avail.y) h = avail.y, w = avail.y * aspect;
  w = std::max(w, 1.f), h = std::max(h, 1.f);
  const float x = std::floor(origin.x + (avail.x - w) * 0.5f),
              y = std::floor(origin.y + (avail.y - h) * 0.5f);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h), IM_COL32(20, 20, 22, 255));
  if (snapshot_)
    draw->AddImage(reinterpret_cast<ImTextureID>(uintptr_t(texture_)), ImVec2(x, y), ImVec2(x + w, y + h));
  if (!state.region.empty()) {
    draw->AddRect(ImVec2(x + state.region.x0 * w, y + state.region.y0 * h),
                  ImVec2(x + state.region.x1 * w, y + state.region.y1 * h), IM_COL32(255, 200, 60, 200), 0.f,
                  0, 1.f);
  }
  handle_input(state, renderer, x, y, w, h);
  if (!state.render_problems.empty()) {
    draw_problems_overlay(state.render_problems, x, y, w);
  } else if (snapshot_ && show_stats_ && !tool_.active()) {
    draw_stats_overlay(*snapshot_, x, y);  // the tool's header takes its corner
  }
  frame.image_x = x, frame.image_y = y, frame.image_w = w, frame.image_h = h;
  return frame;
}

}  // namespace inkray
