// The transform gizmo's maths, free of any window: where its handles are for an object
// seen by the scene camera, which handle a point on screen picks, and what dragging one
// does to the object's TransformDesc. ui/viewport/gizmo_drawing.cpp draws what this places.
#pragma once

#include "core/camera/camera.h"
#include "core/document/desc.h"

#include <array>
#include <vector>

namespace inkray {

enum class GizmoMode { translate, rotate, scale };
// Names for labels, undo steps and the G/R/S header.
inline constexpr const char* kGizmoModeNames[3] = {"Move", "Rotate", "Scale"};

// axis: an arrow (translate) or a stick with a cube (scale) along `axis`;
// plane: a square that translates in the plane normal to `axis`;
// ring: rotates about `axis`;
// view: the centre (translate in the view plane, scale uniformly) or, rotating, the outer
// ring about the view axis.
enum class HandleKind { none, axis, plane, ring, view };
struct GizmoHandle {
  HandleKind kind = HandleKind::none;
  int axis = -1;  // 0 x, 1 y, 2 z
  bool operator==(const GizmoHandle&) const = default;
};

// The viewport's image of the scene camera: image pixels (the render resolution) placed
// in the window at `origin`, `scale` window pixels each.
struct ViewMapping {
  Camera camera;
  Vec2 origin{0.f};
  float scale = 1.f;
  float ui_scale = 1.f;  // the interface's size: the gizmo's pixel sizes below grow with it

  Vec2 to_window(Vec2 image) const { return origin + image * scale; }
  Vec2 to_image(Vec2 window) const { return (window - origin) / scale; }
  Ray ray(Vec2 window) const { return camera.generate_ray(to_image(window), Vec2(0.5f)); }
  // False behind the camera.
  bool project(const Point3& p, Vec2* window) const;
};

// Sizes on screen, in window pixels at UI scale 1.
inline constexpr float kGizmoPixels = 90.f;    // an axis handle's length, the rings' radius
inline constexpr float kPickPixels = 7.f;      // how near the cursor must come to a handle
inline constexpr float kCentrePixels = 9.f;    // the centre handle's radius
inline constexpr float kViewRingScale = 1.2f;  // the view ring's radius, in axis lengths
// Handle extents in axis lengths: where an axis stick starts, where a plane square spans.
inline constexpr float kAxisStart = 0.2f;
inline constexpr float kPlaneNear = 0.3f, kPlaneFar = 0.5f;

struct GizmoFrame {
  bool visible = false;  // false when the pivot is behind the camera
  Point3 pivot{0.f};     // the centre of the object's local bounds, placed
  // World axes for translate and rotate; the object's own axes for scale, since its
  // scale is along them.
  std::array<Vec3, 3> axes{Vec3(1.f, 0.f, 0.f), Vec3(0.f, 1.f, 0.f), Vec3(0.f, 0.f, 1.f)};
  Vec3 view_axis{0.f, 0.f, 1.f};  // the camera's forward axis reversed: towards the viewer
  float length = 1.f;             // world length of kGizmoPixels at the pivot's depth
};

GizmoFrame gizmo_frame(const ObjectDesc& object, GizmoMode mode, const ViewMapping& view);
// Handles seen edge-on (an axis pointing at the camera, a plane seen from its side) are
// hidden: dragging them would be ill-conditioned.
bool handle_shown(const GizmoFrame& frame, GizmoHandle handle, const ViewMapping& view);
std::vector<GizmoHandle> gizmo_handles(GizmoMode mode);
// The shown handle nearest `window` within kPickPixels; none when there is none.
GizmoHandle pick_handle(const GizmoFrame& frame, GizmoMode mode, const ViewMapping& view, Vec2 window);

// World-space outlines of handles, shared by picking and drawing.
std::vector<Point3> ring_points(const GizmoFrame& frame, GizmoHandle ring, int segments);
std::array<Point3, 4> plane_corners(const GizmoFrame& frame, int normal_axis);

// Edits of a transform. Rotations are about a world axis through a world pivot (the new
// rotation goes last, so it applies after the others); scale factors are per local axis
// about a local point that stays where it was.
TransformDesc translated(const TransformDesc& t, const Vec3& delta);
TransformDesc rotated(const TransformDesc& t, const Point3& pivot, const Vec3& axis, float degrees);
TransformDesc scaled(const TransformDesc& t, const Point3& local_pivot, const Vec3& factor);

// Ctrl while dragging: positions on a grid of a tenth of the power of ten nearest the
// object's size (0.1 for a size of 1, 10 for 100), angles in 15 degrees, factors in 0.1.
float translate_snap_step(float object_radius);
inline constexpr float kSnapDegrees = 15.f;
inline constexpr float kSnapFactor = 0.1f;

// What a drag has done so far.
struct DragValue {
  Vec3 delta{0.f};    // translate: world offset
  float degrees = 0;  // rotate: about the handle's axis (the view axis for `view`)
  float factor = 1;   // scale: along the handle's axis, or uniform for `view`
};

// One drag of one handle, from where the button went down. The maths of each handle:
// axis: the point of the axis line nearest the mouse ray; plane: the mouse ray meeting
// the plane; ring: the angle on the ring's plane (on screen when the ring is seen nearly
// edge-on); scale: the ratio of distances from the pivot, along the axis or on screen.
class GizmoDrag {
 public:
  GizmoDrag(const ObjectDesc& object, GizmoMode mode, GizmoHandle handle, const ViewMapping& view,
            Vec2 start);

  // The object's transform with the mouse at `window`; `snap` is Ctrl. Rings count the
  // turns between calls, so a drag may turn past half a turn.
  TransformDesc drag_to(Vec2 window, bool snap);
  // The transform for a value (typed in, or measured by drag_to).
  TransformDesc apply(const DragValue& value) const;
  const DragValue& value() const { return value_; }
  const TransformDesc& original() const { return original_; }
  GizmoHandle handle() const { return handle_; }
  // The axis a value applies along (the view axis for `view`).
  Vec3 axis() const;

 private:
  float axis_param(Vec2 window, bool* ok) const;
  bool plane_hit(Vec2 window, const Vec3& normal, Point3* hit) const;
  float ring_angle(Vec2 window) const;

  TransformDesc original_;
  GizmoMode mode_;
  GizmoHandle handle_;
  ViewMapping view_;
  GizmoFrame frame_;
  Point3 local_pivot_{0.f};
  float snap_step_ = 0.1f;
  Vec2 pivot_on_screen_{0.f};
  Point3 start_point_{0.f};  // plane drags: where the ray met the plane
  float start_param_ = 0.f;  // axis drags: the parameter along the axis; uniform scale: screen distance
  bool screen_angle_ = false;
  float last_angle_ = 0.f, turned_ = 0.f;  // radians
  DragValue value_;
};

}  // namespace inkray
