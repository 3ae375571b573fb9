// The viewport: the renderer's newest snapshot as a GL texture (uploaded only
// when a new one is published) under its overlays (ui/viewport/viewport_overlay.h),
// display controls, and mouse input for camera navigation, picking,
// click-to-focus, drawing a render region, and moving the selected object with
// the gizmo or Blender's G/R/S keys.
#pragma once

#include "ui/viewport/camera_controller.h"
#include "ui/model/editor_state.h"
#include "ui/viewport/gizmo.h"
#include "ui/viewport/transform_tool.h"

#include <cstdint>
#include <optional>

namespace inkray {

struct ViewportFrame {
  uint64_t new_revision_shown = 0;  // the revision whose first image was uploaded this frame, else 0
  float image_x = 0, image_y = 0, image_w = 0, image_h = 0;  // where the image is, in window pixels
};

// Keys with the mouse over the viewport (besides F, frame selected): G, R, S start a
// modal move, rotate, scale; W cycles the gizmo between them; I shows or hides the
// statistics overlay.
class ViewportPanel {
 public:
  ViewportPanel();
  ~ViewportPanel();
  ViewportPanel(const ViewportPanel&) = delete;
  ViewportPanel& operator=(const ViewportPanel&) = delete;

  ViewportFrame draw(EditorState& state, ProgressiveRenderer& renderer);
  // Whether a snapshot at full resolution has been shown (screenshots wait for it).
  bool shown_full_resolution() const { return shown_divisor_ == 1; }
  uint32_t shown_spp() const { return shown_spp_; }
  bool shown_denoised() const { return shown_denoised_; }
  // For inkray --measure-edits: the image on screen (null before the first) and its revision.
  const std::shared_ptr<const ViewportSnapshot>& shown_snapshot() const { return snapshot_; }
  uint64_t shown_revision() const { return shown_revision_; }
  uint64_t uploaded_generation() const { return uploaded_generation_; }

 private:
  void upload(const ViewportSnapshot& snapshot);
  void toolbar(EditorState& state);
  void handle_input(EditorState& state, const ProgressiveRenderer& renderer, float x, float y, float w,
                    float h);
  // Each returns true when it took this frame's mouse input.
  bool tool_input(EditorState& state, const ViewMapping& view, int object);
  bool gizmo_input(EditorState& state, const ViewMapping& view, int object, bool activated, bool active);
  // An edit of one object's transform that the running drag or tool owns: one undo step
  // for all of it (the gizmo merges by key while its button is held; the tool, which
  // holds no button, replaces its own newest step).
  void edit_transform(EditorState& state, int object, const TransformDesc& t, const char* label,
                      const std::string& merge_key);
  // Puts back the transform from before the drag or tool, dropping its undo step.
  void restore_transform(EditorState& state, int object, const TransformDesc& original);

  unsigned texture_ = 0;
  int texture_w_ = 0, texture_h_ = 0;
  uint64_t uploaded_generation_ = 0;
  uint64_t shown_revision_ = 0;
  int shown_divisor_ = 0;
  uint32_t shown_spp_ = 0;
  bool shown_denoised_ = false;
  std::shared_ptr<const ViewportSnapshot> snapshot_;
  CameraController controller_;
  bool show_stats_ = true;
  // Mouse: where the button went down (clicks count there: the cursor may jump in the
  // frame of the press) and how far the drag has strayed from it.
  bool dragging_region_ = false;
  Vec2 press_{0.f};
  float drag_distance_ = 0;
  bool ignore_until_release_ = false;  // the press ended a tool or cancelled a drag
  // The gizmo and the G/R/S tool.
  GizmoMode gizmo_mode_ = GizmoMode::translate;
  std::optional<GizmoDrag> gizmo_drag_;
  uint64_t drags_ = 0;  // numbers each drag's merge key
  TransformTool tool_;
  int moving_object_ = -1;     // the object the drag or tool moves
  uint64_t own_revision_ = 0;  // the document revision right after its newest edit; 0: none
};

}  // namespace inkray
