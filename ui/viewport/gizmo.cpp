#include "ui/viewport/gizmo.h"

#include "core/compiler/compile_objects.h"
#include "ui/model/scene_edits.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace inkray {
namespace {

Transform rotation_of(const TransformDesc& t) {
  Transform r;
  for (const RotationDesc& d : t.rotate) r = Transform::rotate(d.degrees, d.axis) * r;
  return r;
}

// Two unit vectors spanning the plane normal to n, e1 x e2 = n.
std::array<Vec3, 2> plane_basis(const Vec3& n) {
  const Vec3 helper = std::abs(n.x) < 0.9f ? Vec3(1.f, 0.f, 0.f) : Vec3(0.f, 1.f, 0.f);
  const Vec3 e1 = glm::normalize(glm::cross(helper, n));
  return {e1, glm::cross(n, e1)};
}

float segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.f ? std::clamp(glm::dot(p - a, ab) / len2, 0.f, 1.f) : 0.f;
  return glm::length(p - (a + t * ab));
}

float cross2(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

bool inside_convex(Vec2 p, const std::array<Vec2, 4>& q) {
  bool pos = false, neg = false;
  for (size_t i = 0; i < 4; ++i) {
    const float c = cross2(q[(i + 1) % 4] - q[i], p - q[i]);
    pos |= c > 0.f;
    neg |= c < 0.f;
  }
  return !(pos && neg);
}

Point3 local_centre(const ObjectDesc& object) {
  Point3 lo, hi;
  local_bounds(object, &lo, &hi);
  return 0.5f * (lo + hi);
}

float snapped(float v, float step) { return step > 0.f ? std::round(v / step) * step : v; }

}  // namespace

bool ViewMapping::project(const Point3& p, Vec2* window) const {
  Vec2 image;
  if (!camera.project(p, &image)) return false;
  *window = to_window(image);
  return true;
}

GizmoFrame gizmo_frame(const ObjectDesc& object, GizmoMode mode, const ViewMapping& view) {
  GizmoFrame f;
  const Transform to_world = transform_from_desc(object.transform);
  f.pivot = to_world.point(local_centre(object));
  const float depth = glm::dot(f.pivot - view.camera.origin(), view.camera.forward());
  if (!(depth > 0.f)) return f;
  if (mode == GizmoMode::scale) {
    const Transform r = rotation_of(object.transform);
    for (int a = 0; a < 3; ++a) {
      Vec3 e(0.f);
      e[a] = object.transform.scale[a] < 0.f ? -1.f : 1.f;
      f.axes[size_t(a)] = glm::normalize(r.vector(e));
    }
  }
  f.view_axis = -view.camera.forward();
  f.length = kGizmoPixels * view.ui_scale / (view.scale * view.camera.world_to_pixels(1.f, depth));
  f.visible = std::isfinite(f.length) && f.length > 0.f;
  return f;
}

std::vector<GizmoHandle> gizmo_handles(GizmoMode mode) {
  // Centres and planes first: where handles overlap, the smaller target wins a tie.
  std::vector<GizmoHandle> handles;
  if (mode != GizmoMode::rotate) handles.push_back({HandleKind::view, -1});
  for (int a = 0; a < 3; ++a) {
    if (mode == GizmoMode::translate) handles.push_back({HandleKind::plane, a});
  }
  for (int a = 0; a < 3; ++a)
    handles.push_back({mode == GizmoMode::rotate ? HandleKind::ring : HandleKind::axis, a});
  if (mode == GizmoMode::rotate) handles.push_back({HandleKind::view, -1});
  return handles;
}

bool handle_shown(const GizmoFrame& frame, GizmoHandle handle, const ViewMapping& view) {
  if (!frame.visible) return false;
  switch (handle.kind) {
    case HandleKind::axis: {
      Vec2 a, b;
      if (!view.project(frame.pivot, &a) ||
          !view.project(frame.pivot + frame.axes[size_t(handle.axis)] * frame.length, &b))
        return false;
      return glm::length(b - a) > 0.2f * kGizmoPixels * view.ui_scale;
    }
    case HandleKind::plane:
      return std::abs(glm::dot(frame.axes[size_t(handle.axis)], frame.view_axis)) > 0.15f;
    case HandleKind::ring:  // edge-on it is a line, and turns by the angle on screen
    case HandleKind::view:
      return true;
    case HandleKind::none:
      return false;
  }
  return false;
}

std::vector<Point3> ring_points(const GizmoFrame& frame, GizmoHandle ring, int segments) {
  const bool outer = ring.kind == HandleKind::view;
  const Vec3 n = outer ? frame.view_axis : frame.axes[size_t(ring.axis)];
  const float radius = frame.length * (outer ? kViewRingScale : 1.f);
  const auto [e1, e2] = plane_basis(n);
  std::vector<Point3> points;
  points.reserve(size_t(segments) + 1);
  for (int i = 0; i <= segments; ++i) {
    const float t = 2.f * kPi * float(i) / float(segments);
    points.push_back(frame.pivot + radius * (std::cos(t) * e1 + std::sin(t) * e2));
  }
  return points;
}

std::array<Point3, 4> plane_corners(const GizmoFrame& frame, int normal_axis) {
  const Vec3 u = frame.axes[size_t((normal_axis + 1) % 3)] * frame.length;
  const Vec3 v = frame.axes[size_t((normal_axis + 2) % 3)] * frame.length;
  return {frame.pivot + kPlaneNear * u + kPlaneNear * v, frame.pivot + kPlaneFar * u + kPlaneNear * v,
          frame.pivot + kPlaneFar * u + kPlaneFar * v, frame.pivot + kPlaneNear * u + kPlaneFar * v};
}

GizmoHandle pick_handle(const GizmoFrame& frame, GizmoMode mode, const ViewMapping& view, Vec2 window) {
  GizmoHandle best;
  float best_distance = kPickPixels * view.ui_scale;
  Vec2 centre;
  if (!frame.visible || !view.project(frame.pivot, &centre)) return best;
  for (const GizmoHandle h : gizmo_handles(mode)) {
    if (!handle_shown(frame, h, view)) continue;
    float d = std::numeric_limits<float>::infinity();
    if (h.kind == HandleKind::view && mode != GizmoMode::rotate) {
      d = std::max(glm::length(window - centre) - kCentrePixels * view.ui_scale, 0.f);
    } else if (h.kind == HandleKind::plane) {
      std::array<Vec2, 4> quad;
      bool ok = true;
      const auto corners = plane_corners(frame, h.axis);
      for (size_t i = 0; i < 4; ++i) ok = ok && view.project(corners[i], &quad[i]);
      if (ok && inside_convex(window, quad)) d = 0.f;
    } else if (h.kind == HandleKind::axis) {
      Vec2 a, b;
      const Vec3 axis = frame.axes[size_t(h.axis)] * frame.length;
      if (view.project(frame.pivot + kAxisStart * axis, &a) && view.project(frame.pivot + axis, &b))
        d = segment_distance(window, a, b);
    } else {
      const std::vector<Point3> ring = ring_points(frame, h, 64);
      Vec2 previous;
      bool have_previous = false;
      for (const Point3& p : ring) {
        Vec2 q;
        const bool ok = view.project(p, &q);
        if (ok && have_previous) d = std::min(d, segment_distance(window, previous, q));
        previous = q, have_previous = ok;
      }
    }
    if (d < best_distance) best = h, best_distance = d;
  }
  return best;
}

TransformDesc translated(const TransformDesc& t, const Vec3& delta) {
  TransformDesc out = t;
  out.translate += delta;
  return out;
}

TransformDesc rotated(const TransformDesc& t, const Point3& pivot, const Vec3& axis, float degrees) {
  if (degrees == 0.f || glm::length(axis) == 0.f) return t;
  TransformDesc out = t;
  const Vec3 n = glm::normalize(axis);
  // Turning about the same axis again adds to the last rotation instead of growing the list.
  if (!out.rotate.empty() && out.rotate.back().axis == n) {
    out.rotate.back().degrees += degrees;
  } else {
    out.rotate.push_back({n, degrees});
  }
  // p -> R (p - pivot) + pivot, with p = (the rest) + translate.
  out.translate = Transform::rotate(degrees, n).vector(t.translate - pivot) + pivot;
  return out;
}

TransformDesc scaled(const TransformDesc& t, const Point3& local_pivot, const Vec3& factor) {
  TransformDesc out = t;
  out.scale = t.scale * factor;
  // The pivot is R S p + translate before and after: move the translate by R (S - S') p.
  out.translate = t.translate + rotation_of(t).vector((t.scale - out.scale) * local_pivot);
  return out;
}

float translate_snap_step(float object_radius) {
  const float r = std::max(object_radius, 1e-6f);
  return 0.1f * std::pow(10.f, std::round(std::log10(r)));
}

GizmoDrag::GizmoDrag(const ObjectDesc& object, GizmoMode mode, GizmoHandle handle, const ViewMapping& view,
                     Vec2 start)
    : original_(object.transform), mode_(mode), handle_(handle), view_(view) {
  frame_ = gizmo_frame(object, mode, view);
  local_pivot_ = local_centre(object);
  Point3 centre;
  float radius = 1.f;
  object_bounds(object, &centre, &radius);
  snap_step_ = translate_snap_step(radius);
  if (!view.project(frame_.pivot, &pivot_on_screen_)) pivot_on_screen_ = start;
  bool ok = true;
  switch (mode) {
    case GizmoMode::translate:
      if (handle.kind == HandleKind::axis) {
        start_param_ = axis_param(start, &ok);
      } else if (!plane_hit(start, handle.kind == HandleKind::plane ? axis() : frame_.view_axis,
                            &start_point_)) {
        start_point_ = frame_.pivot;
      }
      break;
    case GizmoMode::rotate:
      // A ring seen nearly edge-on gives wild angles on its plane: turn by the angle on screen.
      screen_angle_ = std::abs(glm::dot(axis(), glm::normalize(view.ray(start).d))) < 0.2f;
      last_angle_ = ring_angle(start);
      break;
    case GizmoMode::scale:
      start_param_ =
          handle.kind == HandleKind::axis ? axis_param(start, &ok) : glm::length(start - pivot_on_screen_);
      if (!ok || std::abs(start_param_) < 1e-3f * (handle.kind == HandleKind::axis ? frame_.length : 1.f))
        start_param_ = handle.kind == HandleKind::axis ? frame_.length : 1.f;
      break;
  }
}

Vec3 GizmoDrag::axis() const {
  if (handle_.kind == HandleKind::view || handle_.axis < 0) return frame_.view_axis;
  return frame_.axes[size_t(handle_.axis)];
}

float GizmoDrag::axis_param(Vec2 window, bool* ok) const {
  // The point of the axis line nearest the mouse ray (both directions unit length).
  const Ray ray = view_.ray(window);
  const Vec3 a = axis(), d = glm::normalize(ray.d), w0 = ray.o - frame_.pivot;
  const float b = glm::dot(a, d);
  const float denom = 1.f - b * b;
  *ok = denom > 1e-6f;
  if (!*ok) return 0.f;
  return (glm::dot(a, w0) - b * glm::dot(d, w0)) / denom;
}

bool GizmoDrag::plane_hit(Vec2 window, const Vec3& normal, Point3* hit) const {
  const Ray ray = view_.ray(window);
  const float dn = glm::dot(ray.d, normal);
  if (std::abs(dn) < 1e-6f) return false;
  const float s = glm::dot(frame_.pivot - ray.o, normal) / dn;
  if (!(s > 0.f)) return false;
  *hit = ray.o + s * ray.d;
  return true;
}

float GizmoDrag::ring_angle(Vec2 window) const {
  const Vec3 n = axis();
  Point3 hit;
  if (!screen_angle_ && plane_hit(window, n, &hit)) {
    const auto [e1, e2] = plane_basis(n);
    const Vec3 v = hit - frame_.pivot;
    return std::atan2(glm::dot(v, e2), glm::dot(v, e1));
  }
  // Counter-clockwise on screen (y grows downwards) is right-handed about an axis that
  // points at the viewer.
  const Vec2 v = window - pivot_on_screen_;
  const float sign = glm::dot(n, frame_.view_axis) >= 0.f ? 1.f : -1.f;
  return sign * std::atan2(-v.y, v.x);
}

TransformDesc GizmoDrag::apply(const DragValue& value) const {
  switch (mode_) {
    case GizmoMode::translate:
      return translated(original_, value.delta);
    case GizmoMode::rotate:
      return rotated(original_, frame_.pivot, axis(), value.degrees);
    case GizmoMode::scale: {
      Vec3 factor(value.factor);
      if (handle_.kind == HandleKind::axis) factor = Vec3(1.f), factor[handle_.axis] = value.factor;
      return scaled(original_, local_pivot_, factor);
    }
  }
  return original_;
}

TransformDesc GizmoDrag::drag_to(Vec2 window, bool snap) {
  bool ok = true;
  switch (mode_) {
    case GizmoMode::translate: {
      Vec3 delta = value_.delta;
      if (handle_.kind == HandleKind::axis) {
        const float t = axis_param(window, &ok);
        if (ok) delta = axis() * (t - start_param_);
      } else {
        Point3 hit;
        if (plane_hit(window, handle_.kind == HandleKind::plane ? axis() : frame_.view_axis, &hit))
          delta = hit - start_point_;
      }
      if (snap) {
        // The world components the handle moves, put on the grid; the others stay.
        Vec3 moved = original_.translate + delta;
        for (int c = 0; c < 3; ++c) {
          const bool free =
              handle_.kind == HandleKind::view || (handle_.kind == HandleKind::axis) == (c == handle_.axis);
          if (free) moved[c] = snapped(moved[c], snap_step_);
        }
        delta = moved - original_.translate;
      }
      value_.delta = delta;
      break;
    }
    case GizmoMode::rotate: {
      const float angle = ring_angle(window);
      float step = angle - last_angle_;
      step -= 2.f * kPi * std::round(step / (2.f * kPi));
      turned_ += step;
      last_angle_ = angle;
      const float degrees = glm::degrees(turned_);
      value_.degrees = snap ? snapped(degrees, kSnapDegrees) : degrees;
      break;
    }
    case GizmoMode::scale: {
      float factor = value_.factor;
      if (handle_.kind == HandleKind::axis) {
        const float t = axis_param(window, &ok);
        if (ok) factor = t / start_param_;
      } else {
        factor = glm::length(window - pivot_on_screen_) / start_param_;
      }
      if (snap) factor = snapped(factor, kSnapFactor);
      // Never quite zero: a flat object cannot be scaled back.
      if (std::abs(factor) < 0.01f) factor = factor < 0.f ? -0.01f : 0.01f;
      value_.factor = factor;
      break;
    }
  }
  return apply(value_);
}

}  // namespace inkray
