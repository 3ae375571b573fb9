// Drawing the node editor's canvas with ImDrawList: the grid, links as cubic
// beziers, and nodes with a title coloured by category, pins coloured by socket
// type, and the generated widgets (param_widgets.h) of their unlinked valued inputs
// and settings. No document edits here: draw_node returns the edited copy.
#pragma once

#include "ui/nodes/node_canvas.h"
#include "ui/widgets/param_widgets.h"
#include "ui/model/selection.h"

#include <imgui.h>

#include <string>
#include <string_view>
#include <vector>

namespace inkray {

ImU32 socket_color(SocketType type);
ImU32 category_color(NodeCategory category);

void draw_grid(ImDrawList* draw, const CanvasView& view, Vec2 size);
void draw_link(ImDrawList* draw, const CanvasView& view, const Bezier& curve, ImU32 color, float thickness);

struct NodeDrawResult {
  bool changed = false;
  NodeVariant edited;              // the node's settings after this frame's widgets
  std::string changed_param;       // the undo merge key's last part
  std::vector<float> row_heights;  // as drawn, canvas units, per row of node_rows
};

// What a node's widgets read beyond the node: the scene, whose folder path fields
// browse from, and for keyable fields the panel's keys and the material the graph is
// of (its parameters are keyed as materials/NAME/nodes/ID/PARAM).
struct NodeWidgetContext {
  const SceneDesc* scene = nullptr;
  KeyTargets* keys = nullptr;
  Selection material;
};

// Draws one node as laid out in `box`. Widgets are drawn only when `widgets` (they
// are unreadable when zoomed far out); rows of linked inputs show their name alone.
NodeDrawResult draw_node(ImDrawList* draw, const CanvasView& view, const GraphNodeDesc& node,
                         const NodeBox& box, const std::vector<std::string_view>& linked_inputs,
                         bool selected, bool widgets, const NodeWidgetContext& context);

}  // namespace inkray
