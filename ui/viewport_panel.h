// The viewport: the renderer's newest snapshot as a GL texture (uploaded only
// when a new one is published), the statistics overlay with an error-against-
// time plot, display controls, and mouse input for camera navigation, picking,
// click-to-focus and drawing a render region.
#pragma once

#include "ui/camera_controller.h"
#include "ui/editor_state.h"

#include <cstdint>

namespace inkray {

struct ViewportFrame {
  uint64_t new_revision_shown = 0;  // the revision whose first image was uploaded this frame, else 0
  float image_x = 0, image_y = 0, image_w = 0, image_h = 0;  // where the image is, in window pixels
};

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
  // For inkray --measure-edits: the image on screen (null before the first) and its revision.
  const std::shared_ptr<const ViewportSnapshot>& shown_snapshot() const { return snapshot_; }
  uint64_t shown_revision() const { return shown_revision_; }
  uint64_t uploaded_generation() const { return uploaded_generation_; }

 private:
  void upload(const ViewportSnapshot& snapshot);
  void toolbar(EditorState& state, ProgressiveRenderer& renderer);
  void overlay(const ViewportSnapshot& snapshot, float x, float y);
  void problems_overlay(const std::vector<std::string>& problems, float x, float y, float w);
  void handle_input(EditorState& state, const ProgressiveRenderer& renderer, float x, float y, float w, float h);

  unsigned texture_ = 0;
  int texture_w_ = 0, texture_h_ = 0;
  uint64_t uploaded_generation_ = 0;
  uint64_t shown_revision_ = 0;
  int shown_divisor_ = 0;
  uint32_t shown_spp_ = 0;
  std::shared_ptr<const ViewportSnapshot> snapshot_;
  CameraController controller_;
  bool dragging_region_ = false;
  float drag_start_x_ = 0, drag_start_y_ = 0;
  float drag_distance_ = 0;
};

}  // namespace inkray
