#include "ui/viewport/gizmo_drawing.h"

#include <cmath>

namespace inkray {
namespace {

constexpr ImU32 kAxisColours[3] = {IM_COL32(235, 64, 80, 255), IM_COL32(130, 205, 40, 255),
                                   IM_COL32(60, 130, 245, 255)};
constexpr ImU32 kViewColour = IM_COL32(225, 225, 225, 255);
constexpr ImU32 kHotColour = IM_COL32(255, 225, 70, 255);

ImVec2 im(Vec2 v) { return ImVec2(v.x, v.y); }

ImU32 with_alpha(ImU32 colour, int alpha) {
  return (colour & ~IM_COL32_A_MASK) | (ImU32(alpha) << IM_COL32_A_SHIFT);
}

ImU32 colour_of(GizmoHandle h, GizmoHandle hot) {
  if (h == hot) return kHotColour;
  return h.axis >= 0 ? kAxisColours[h.axis] : kViewColour;
}

void draw_axis(ImDrawList* draw, const GizmoFrame& f, GizmoMode mode, const ViewMapping& view, GizmoHandle h,
               ImU32 colour) {
  const Vec3 axis = f.axes[size_t(h.axis)] * f.length;
  Vec2 a, b;
  if (!view.project(f.pivot + kAxisStart * axis, &a) || !view.project(f.pivot + axis, &b)) return;
  draw->AddLine(im(a), im(b), colour, 3.f);
  const Vec2 along = glm::length(b - a) > 0.f ? glm::normalize(b - a) : Vec2(1.f, 0.f);
  const Vec2 across(-along.y, along.x);
  if (mode == GizmoMode::translate) {
    draw->AddTriangleFilled(im(b + along * 14.f), im(b + across * 6.f), im(b - across * 6.f), colour);
  } else {
    draw->AddQuadFilled(im(b + (along + across) * 5.f), im(b + (along - across) * 5.f),
                        im(b - (along + across) * 5.f), im(b - (along - across) * 5.f), colour);
  }
}

void draw_ring(ImDrawList* draw, const GizmoFrame& f, const ViewMapping& view, GizmoHandle h, ImU32 colour) {
  // The half turned away from the camera is faint, so the rings read as a sphere.
  const std::vector<Point3> ring = ring_points(f, h, 72);
  for (size_t i = 0; i + 1 < ring.size(); ++i) {
    Vec2 a, b;
    if (!view.project(ring[i], &a) || !view.project(ring[i + 1], &b)) continue;
    const bool front =
        h.kind == HandleKind::view || glm::dot(ring[i] + ring[i + 1] - 2.f * f.pivot, f.view_axis) >= 0.f;
    draw->AddLine(im(a), im(b), front ? colour : with_alpha(colour, 70), front ? 2.5f : 1.5f);
  }
}

void draw_plane(ImDrawList* draw, const GizmoFrame& f, const ViewMapping& view, GizmoHandle h, ImU32 colour) {
  const auto corners = plane_corners(f, h.axis);
  ImVec2 q[4];
  for (size_t i = 0; i < 4; ++i) {
    Vec2 p;
    if (!view.project(corners[i], &p)) return;
    q[i] = im(p);
  }
  draw->AddQuadFilled(q[0], q[1], q[2], q[3], with_alpha(colour, 110));
  draw->AddQuad(q[0], q[1], q[2], q[3], colour, 1.5f);
}

}  // namespace

void draw_gizmo(ImDrawList* draw, const GizmoFrame& frame, GizmoMode mode, const ViewMapping& view,
                GizmoHandle hot) {
  Vec2 centre;
  if (!frame.visible || !view.project(frame.pivot, &centre)) return;
  for (const GizmoHandle h : gizmo_handles(mode)) {
    if (!handle_shown(frame, h, view)) continue;
    const ImU32 colour = colour_of(h, hot);
    switch (h.kind) {
      case HandleKind::axis:
        draw_axis(draw, frame, mode, view, h, colour);
        break;
      case HandleKind::plane:
        draw_plane(draw, frame, view, h, colour);
        break;
      case HandleKind::ring:
        draw_ring(draw, frame, view, h, colour);
        break;
      case HandleKind::view:
        if (mode == GizmoMode::rotate) {
          draw_ring(draw, frame, view, h, colour);
        } else if (mode == GizmoMode::scale) {
          draw->AddCircleFilled(im(centre), kCentrePixels * view.ui_scale, with_alpha(colour, 160));
          draw->AddCircle(im(centre), kCentrePixels * view.ui_scale, colour, 0, 1.5f);
        } else {
          draw->AddCircle(im(centre), kCentrePixels * view.ui_scale, colour, 0, 2.f);
        }
        break;
      case HandleKind::none:
        break;
    }
  }
  draw->AddCircleFilled(im(centre), 2.5f, kViewColour);
}

void draw_axis_line(ImDrawList* draw, const GizmoFrame& frame, int axis, const ViewMapping& view) {
  if (!frame.visible || axis < 0 || axis > 2) return;
  // Far enough each way to leave the image, short enough to stay in front of the camera.
  const Vec3 d = frame.axes[size_t(axis)] * frame.length;
  for (float reach = 40.f; reach > 0.5f; reach *= 0.5f) {
    Vec2 a, b;
    if (view.project(frame.pivot - reach * d, &a) && view.project(frame.pivot + reach * d, &b)) {
      draw->AddLine(im(a), im(b), with_alpha(kAxisColours[axis], 200), 1.5f);
      return;
    }
  }
}

void draw_header(ImDrawList* draw, ImVec2 at, const std::string& text) {
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  draw->AddRectFilled(at, ImVec2(at.x + size.x + 16.f, at.y + size.y + 10.f), IM_COL32(0, 0, 0, 170), 4.f);
  draw->AddText(ImVec2(at.x + 8.f, at.y + 5.f), IM_COL32(255, 255, 255, 255), text.c_str());
}

}  // namespace inkray
