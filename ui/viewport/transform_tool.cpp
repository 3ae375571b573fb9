#include "ui/viewport/transform_tool.h"

#include "ui/model/scene_edits.h"

#include <cstdio>
#include <cstdlib>

namespace inkray {
namespace {

constexpr const char* kAxisNames[3] = {"X", "Y", "Z"};
constexpr size_t kMaxTyped = 16;

}  // namespace

void TransformTool::begin(GizmoMode mode, const ObjectDesc& object, const ViewMapping& view, Vec2 mouse) {
  active_ = true;
  mode_ = mode;
  object_ = object;
  view_ = view;
  start_ = mouse_ = mouse;
  snap_ = false;
  axis_ = -1;
  typed_.clear();
  negative_ = false;
  start_drag();
}

void TransformTool::start_drag() {
  // Scaling measures the mouse's distance from the pivot on screen, constrained or not,
  // as Blender does: a ratio along the axis would explode near the pivot.
  GizmoHandle handle{HandleKind::view, -1};
  if (axis_ >= 0 && mode_ == GizmoMode::translate) handle = {HandleKind::axis, axis_};
  if (axis_ >= 0 && mode_ == GizmoMode::rotate) handle = {HandleKind::ring, axis_};
  drag_.emplace(object_, mode_, handle, view_, start_);
  drag_->drag_to(mouse_, snap_);
}

void TransformTool::mouse_move(Vec2 window, bool snap) {
  if (!active_) return;
  mouse_ = window;
  snap_ = snap;
  drag_->drag_to(mouse_, snap_);
}

void TransformTool::constrain(int axis) {
  if (!active_ || axis < 0 || axis > 2) return;
  axis_ = axis_ == axis ? -1 : axis;
  start_drag();
}

void TransformTool::type(char c) {
  if (!active_) return;
  if (c == '-') {
    negative_ = !negative_;
  } else if (typed_.size() < kMaxTyped &&
             ((c >= '0' && c <= '9') || (c == '.' && typed_.find('.') == std::string::npos))) {
    typed_ += c;
  }
}

void TransformTool::backspace() {
  if (!typed_.empty()) {
    typed_.pop_back();
  } else {
    negative_ = false;
  }
}

float TransformTool::typed_value() const {
  // Before any digit, "-" alone negates what no value at all would be.
  const bool digits = typed_.find_first_of("0123456789") != std::string::npos;
  const float v = digits ? std::strtof(typed_.c_str(), nullptr) : (mode_ == GizmoMode::scale ? 1.f : 0.f);
  return negative_ ? -v : v;
}

float TransformTool::value() const {
  if (typing()) return typed_value();
  const DragValue& v = drag_->value();
  switch (mode_) {
    case GizmoMode::translate:
      return axis_ >= 0 ? v.delta[axis_] : 0.f;
    case GizmoMode::rotate:
      return v.degrees;
    case GizmoMode::scale:
      return v.factor;
  }
  return 0.f;
}

TransformDesc TransformTool::transform() const {
  if (!active_) return object_.transform;
  const TransformDesc& original = object_.transform;
  switch (mode_) {
    case GizmoMode::translate: {
      if (!typing()) return drag_->apply(drag_->value());
      Vec3 delta(0.f);
      delta[axis_ >= 0 ? axis_ : 0] = typed_value();  // free: along X, as Blender does
      return translated(original, delta);
    }
    case GizmoMode::rotate: {
      DragValue v;
      v.degrees = value();
      return drag_->apply(v);
    }
    case GizmoMode::scale: {
      float factor = value();
      if (std::abs(factor) < 0.01f) factor = factor < 0.f ? -0.01f : 0.01f;  // a flat object cannot come back
      Vec3 f(factor);
      if (axis_ >= 0) f = Vec3(1.f), f[axis_] = factor;
      Point3 lo, hi;
      local_bounds(object_, &lo, &hi);
      return scaled(original, 0.5f * (lo + hi), f);
    }
  }
  return original;
}

std::string TransformTool::header() const {
  if (!active_) return {};
  const char* verb = kGizmoModeNames[size_t(mode_)];
  const int shown_axis = mode_ == GizmoMode::translate && typing() && axis_ < 0 ? 0 : axis_;
  char text[160];
  if (mode_ == GizmoMode::translate && shown_axis < 0) {
    const Vec3 d = drag_->value().delta;
    std::snprintf(text, sizeof text, "Move: %.3f %.3f %.3f", d.x, d.y, d.z);
  } else {
    const std::string where = shown_axis >= 0 ? std::string(" ") + kAxisNames[shown_axis] : std::string();
    std::snprintf(text, sizeof text, mode_ == GizmoMode::rotate ? "%s%s: %.1f deg" : "%s%s: %.3f", verb,
                  where.c_str(), value());
  }
  std::string header = text;
  if (typing()) header += " [" + std::string(negative_ ? "-" : "") + typed_ + "]";
  return header;
}

TransformDesc TransformTool::confirm() {
  const TransformDesc result = transform();
  active_ = false;
  return result;
}

TransformDesc TransformTool::cancel() {
  active_ = false;
  return object_.transform;
}

}  // namespace inkray
