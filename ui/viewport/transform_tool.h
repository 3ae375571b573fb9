// Blender's G, R and S: a modal move, rotate or scale of the selected object that
// follows the mouse until confirmed or cancelled. A state machine of events in and a
// transform out, free of any window; the viewport feeds it keys and the mouse.
#pragma once

#include "ui/viewport/gizmo.h"

#include <optional>
#include <string>

namespace inkray {

class TransformTool {
 public:
  // Starts with the mouse at `mouse` (window pixels); `object` as it is now.
  void begin(GizmoMode mode, const ObjectDesc& object, const ViewMapping& view, Vec2 mouse);
  bool active() const { return active_; }
  GizmoMode mode() const { return mode_; }

  // `snap` is Ctrl: 0.1-grid positions, 15 degrees, 0.1 factors (see ui/viewport/gizmo.h).
  void mouse_move(Vec2 window, bool snap);
  // 0 x, 1 y, 2 z: world axes, the object's own for scale; the same axis again frees it.
  void constrain(int axis);
  // Digits and '.' type a value that replaces the mouse's; '-' negates it. Others are ignored.
  void type(char c);
  void backspace();

  // The object's transform now.
  TransformDesc transform() const;
  // "Move X: 2.000", for the viewport to show while the tool runs.
  std::string header() const;
  // Both end the tool: the transform to keep, or the one from before it began.
  TransformDesc confirm();
  TransformDesc cancel();

  int axis() const { return axis_; }
  bool typing() const { return !typed_.empty() || negative_; }

 private:
  void start_drag();
  float typed_value() const;
  // The value along the constraint: typed, or measured by the mouse.
  float value() const;

  bool active_ = false;
  GizmoMode mode_ = GizmoMode::translate;
  ObjectDesc object_;
  ViewMapping view_;
  Vec2 start_{0.f}, mouse_{0.f};
  bool snap_ = false;
  int axis_ = -1;
  std::string typed_;
  bool negative_ = false;
  std::optional<GizmoDrag> drag_;
};

}  // namespace inkray
