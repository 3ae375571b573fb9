#include "ui/viewport_panel.h"

#include "ui/picking.h"
#include "ui/scene_edits.h"

#include <GL/gl.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace inkray {
namespace {

constexpr const char* kNavMergeKey = "viewport:camera";

std::string display_name(int display) {
  if (display == kDisplayNoise) return "noise estimate";
  return display < 0 ? std::string("final") : std::string(kAovNames[size_t(display)]);
}

}  // namespace

ViewportPanel::ViewportPanel() {
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

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

void ViewportPanel::toolbar(EditorState& state, ProgressiveRenderer& renderer) {
  ImGui::SetNextItemWidth(120.f);
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
  ImGui::SameLine();
  ImGui::SetNextItemWidth(110.f);
  ImGui::SliderFloat("exposure", &state.view.encoding.exposure, -8.f, 8.f, "%.1f EV");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(100.f);
  int transform = int(state.view.encoding.transform);
  if (ImGui::BeginCombo("##transform", std::string(kViewTransformNames[size_t(transform)]).c_str())) {
    for (int t = 0; t < int(kViewTransformNames.size()); ++t) {
      if (ImGui::Selectable(std::string(kViewTransformNames[size_t(t)]).c_str(), t == transform)) {
        state.view.encoding.transform = ViewTransform(t);
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Button(state.paused ? "Resume" : "Pause")) state.paused = !state.paused;
  ImGui::SameLine();
  ImGui::Checkbox("Region", &state.region_tool);
  if (!state.region.empty()) {
    ImGui::SameLine();
    if (ImGui::Button("Clear region")) state.region = {};
  }
  ImGui::SameLine();
  if (ImGui::Button("Frame (F)")) state.want_frame_selected = true;
  ImGui::SameLine();
  if (ImGui::Button("Reset camera")) {
    SceneDesc scene = state.document.scene();
    scene.camera = state.home_camera;
    state.edit(std::move(scene), "Reset camera");
  }
  (void)renderer;
}

void ViewportPanel::problems_overlay(const std::vector<std::string>& problems, float x, float y, float w) {
  std::string text = "This scene cannot render until this is mended:";
  constexpr size_t kShown = 6;
  for (size_t i = 0; i < problems.size() && i < kShown; ++i) text += "\n" + problems[i];
  if (problems.size() > kShown) text += "\n... and " + std::to_string(problems.size() - kShown) + " more (see the log)";
  const float wrap = std::max(w - 28.f, 200.f);
  const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(ImVec2(x + 6, y + 6), ImVec2(x + 18 + size.x, y + 16 + size.y), IM_COL32(90, 20, 20, 220), 4.f);
  draw->AddText(nullptr, 0.f, ImVec2(x + 12, y + 11), IM_COL32(255, 230, 220, 255), text.c_str(), nullptr, wrap);
}

void ViewportPanel::overlay(const ViewportSnapshot& s, float x, float y) {
  const RenderStats& st = s.stats;
  const double rays_per_s = st.elapsed_seconds > 0 ? double(st.rays) / st.elapsed_seconds : 0.0;
  char text[256];
  std::snprintf(text, sizeof text, "%s%u spp  %u passes  %.1f s\n%.2f Mrays/s  error %.2f%%%s",
                s.divisor > 1 ? "preview 1/" : "", st.spp, st.passes, st.elapsed_seconds, rays_per_s * 1e-6,
                st.relative_error * 100.0, s.finished ? "  (done)" : "");
  if (s.divisor > 1) {
    std::snprintf(text, sizeof text, "preview 1/%d  %.1f s", s.divisor, st.elapsed_seconds);
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 size = ImGui::CalcTextSize(text);
  draw->AddRectFilled(ImVec2(x + 6, y + 6), ImVec2(x + 14 + std::max(size.x, 180.f), y + 14 + size.y + 48),
                      IM_COL32(0, 0, 0, 150), 4.f);
  draw->AddText(ImVec2(x + 10, y + 10), IM_COL32(235, 235, 235, 255), text);
  if (s.error_curve.size() >= 2) {
    // log10 of the error against pass: straight lines for 1/sqrt(n) convergence.
    std::vector<float> values;
    values.reserve(s.error_curve.size());
    for (const ErrorSample& e : s.error_curve) values.push_back(float(std::log10(std::max(e.relative_error, 1e-6))));
    ImGui::SetCursorScreenPos(ImVec2(x + 10, y + 12 + size.y));
    ImGui::PlotLines("##error", values.data(), int(values.size()), 0, "log error / time", FLT_MAX, FLT_MAX,
                     ImVec2(std::max(size.x, 180.f) - 4.f, 42.f));
  }
}

void ViewportPanel::handle_input(EditorState& state, const ProgressiveRenderer& renderer, float x, float y, float w,
                                 float h) {
  ImGui::SetCursorScreenPos(ImVec2(x, y));
  ImGui::InvisibleButton("viewport_input", ImVec2(w, h),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  const ImGuiIO& io = ImGui::GetIO();
  const bool hovered = ImGui::IsItemHovered();
  const bool active = ImGui::IsItemActive();
  const SceneDesc& scene = state.document.scene();
  const float image_height = float(scene.render.height);
  const float to_image = image_height / std::max(h, 1.f);  // window pixels -> image pixels
  const ImVec2 mouse = io.MousePos;
  const auto fraction = [&](ImVec2 p) { return ImVec2(std::clamp((p.x - x) / w, 0.f, 1.f), std::clamp((p.y - y) / h, 0.f, 1.f)); };

  if (ImGui::IsItemActivated()) {
    drag_start_x_ = mouse.x, drag_start_y_ = mouse.y;
    drag_distance_ = 0.f;
    dragging_region_ = state.region_tool && ImGui::IsMouseDown(ImGuiMouseButton_Left);
  }
  if (active) drag_distance_ += std::abs(io.MouseDelta.x) + std::abs(io.MouseDelta.y);
  const bool moved = io.MouseDelta.x != 0.f || io.MouseDelta.y != 0.f;

  if (active && dragging_region_) {
    const ImVec2 a = ImVec2(drag_start_x_, drag_start_y_);
    ImGui::GetWindowDrawList()->AddRect(ImVec2(std::min(a.x, mouse.x), std::min(a.y, mouse.y)),
                                        ImVec2(std::max(a.x, mouse.x), std::max(a.y, mouse.y)),
                                        IM_COL32(255, 200, 60, 255), 0.f, 0, 1.5f);
  } else if (active && moved && drag_distance_ > 2.f) {
    CameraDesc camera = scene.camera;
    const bool pan_drag = ImGui::IsMouseDown(ImGuiMouseButton_Middle) ||
                          (ImGui::IsMouseDown(ImGuiMouseButton_Left) && io.KeyShift);
    if (pan_drag) {
      camera = pan(camera, io.MouseDelta.x * to_image, io.MouseDelta.y * to_image, image_height);
    } else if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
      camera = controller_.drag_dolly(camera, io.MouseDelta.y);
    } else if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      camera = controller_.drag_orbit(camera, io.MouseDelta.x, io.MouseDelta.y);
    }
    SceneDesc edited = scene;
    edited.camera = camera;
    state.edit(std::move(edited), "Move camera", kNavMergeKey);
  }
  if (hovered && io.MouseWheel != 0.f) {
    SceneDesc edited = scene;
    edited.camera = controller_.wheel(scene.camera, io.MouseWheel);
    state.edit(std::move(edited), "Dolly camera");
  }
  if (ImGui::IsItemDeactivated()) {
    if (dragging_region_) {
      const ImVec2 a = fraction(ImVec2(drag_start_x_, drag_start_y_)), b = fraction(mouse);
      RegionRect r{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
      if ((r.x1 - r.x0) * w > 4.f && (r.y1 - r.y0) * h > 4.f) state.region = r;
      dragging_region_ = false;
    } else if (drag_distance_ <= 2.f && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
      // A click, not a drag: pick, or with Ctrl focus on what is under the cursor.
      if (auto compiled = renderer.scene()) {
        const ImVec2 f = fraction(mouse);
        const float iw = float(compiled->settings.width), ih = float(compiled->settings.height);
        const PickResult hit = pick(*compiled, Camera(scene.camera, int(iw), int(ih)), Vec2(f.x * iw, f.y * ih));
        if (io.KeyCtrl) {
          if (hit.object >= 0) {
            SceneDesc edited = scene;
            edited.camera = focus_at(scene.camera, hit.depth);
            state.edit(std::move(edited), "Focus");
            state.log.info("focus distance " + std::to_string(hit.depth));
          }
        } else {
          state.selection = hit.object >= 0 ? Selection{ItemKind::object, hit.object} : Selection{};
        }
      }
    }
  }
  // ImGui 1.86 indexes keys by the GLFW key code, which for letters is the ASCII capital.
  // Keys reach the viewport only when no widget takes text or keyboard input.
  if (ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) && !io.WantTextInput &&
      ImGui::IsKeyPressed('F', false) && !io.KeyCtrl) {
    state.want_frame_selected = true;
  }
}

ViewportFrame ViewportPanel::draw(EditorState& state, ProgressiveRenderer& renderer) {
  ViewportFrame frame;
  toolbar(state, renderer);
  const uint64_t generation = renderer.generation();
  if (generation != uploaded_generation_) {
    if (auto s = renderer.latest()) {
      upload(*s);
      if (s->revision != shown_revision_) frame.new_revision_shown = s->revision;
      shown_revision_ = s->revision;
      shown_divisor_ = s->divisor;
      shown_spp_ = s->stats.spp;
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
  const float x = std::floor(origin.x + (avail.x - w) * 0.5f), y = std::floor(origin.y + (avail.y - h) * 0.5f);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h), IM_COL32(20, 20, 22, 255));
  if (snapshot_) draw->AddImage(reinterpret_cast<ImTextureID>(uintptr_t(texture_)), ImVec2(x, y), ImVec2(x + w, y + h));
  if (!state.region.empty()) {
    draw->AddRect(ImVec2(x + state.region.x0 * w, y + state.region.y0 * h),
                  ImVec2(x + state.region.x1 * w, y + state.region.y1 * h), IM_COL32(255, 200, 60, 200), 0.f, 0,
                  1.f);
  }
  handle_input(state, renderer, x, y, w, h);
  if (!state.render_problems.empty()) {
    problems_overlay(state.render_problems, x, y, w);
  } else if (snapshot_) {
    overlay(*snapshot_, x, y);
  }
  frame.image_x = x, frame.image_y = y, frame.image_w = w, frame.image_h = h;
  return frame;
}

}  // namespace inkray
