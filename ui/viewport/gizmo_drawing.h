// Draws the transform gizmo that ui/viewport/gizmo.h places, and the G/R/S tool's axis line and
// header, over the viewport image with ImGui's draw list. Red, green and blue are X, Y
// and Z as in Blender; the hovered or dragged handle turns yellow.
#pragma once

#include "ui/viewport/gizmo.h"

#include <imgui.h>

#include <string>

namespace inkray {

void draw_gizmo(ImDrawList* draw, const GizmoFrame& frame, GizmoMode mode, const ViewMapping& view,
                GizmoHandle hot);
// A line through the pivot along `axis`, as long as the view is wide.
void draw_axis_line(ImDrawList* draw, const GizmoFrame& frame, int axis, const ViewMapping& view);
// Text on a dark band at the top left of the image.
void draw_header(ImDrawList* draw, ImVec2 at, const std::string& text);

}  // namespace inkray
