// The node editor's canvas without ImGui: the view between screen pixels and canvas
// units, where a node's rows and pins sit, hit testing (pins, nodes, links by their
// distance to the drawn bezier) and the selection rules, so they can be unit-tested.
// node_editor_panel.cpp draws and handles input with these.
#pragma once

#include "core/document/graph_edit.h"
#include "core/math/types.h"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// ---------------------------------------------------------------- the view
// Canvas units are those of the graph's node positions; at zoom 1 a unit is a pixel.
// The canvas point at the widget's top-left corner is -pan (pan is in canvas units,
// so it means the same at every zoom).
struct CanvasView {
  Vec2 origin{0.f};  // screen position of the canvas widget's top-left corner
  Vec2 pan{0.f};
  float zoom = 1.f;
};
// Within GraphEditorDesc::zoom's range; far out nodes are unreadable dots, far in one socket fills the panel.
inline constexpr float kMinCanvasZoom = 0.2f, kMaxCanvasZoom = 3.f;

Vec2 to_screen(const CanvasView& view, Vec2 canvas);
Vec2 to_canvas(const CanvasView& view, Vec2 screen);
// The view at `zoom` (clamped) with the canvas point under `screen` kept in place.
CanvasView zoom_about(CanvasView view, Vec2 screen, float zoom);

struct CanvasRect {
  Vec2 min{0.f}, max{0.f};
  Vec2 size() const { return max - min; }
  bool contains(Vec2 p) const { return p.x >= min.x && p.y >= min.y && p.x <= max.x && p.y <= max.y; }
  bool overlaps(const CanvasRect& o) const {
    return min.x < o.max.x && o.min.x < max.x && min.y < o.max.y && o.min.y < max.y;
  }
};
// The rectangle spanned by two corners in any order (a box-selection drag).
CanvasRect rect_between(Vec2 a, Vec2 b);
// The view that shows `bounds` centred in a widget of `size` pixels with `margin` pixels
// around it; it zooms out to fit but never in beyond 1, where the text is sharpest, and
// gives up the margin (down to 4 pixels) before it zooms out below 1.
CanvasView frame_bounds(CanvasView view, CanvasRect bounds, Vec2 size, float margin);

// ---------------------------------------------------------------- node geometry
// Sizes in canvas units. Text is ImGui's default font (ProggyClean, 13 units high, 7 a
// character). Rows are compact (a 16-unit frame, 2 apart) so a closure node with twenty
// inputs stays under 420 units, as the example scenes place them.
struct NodeMetrics {
  float title = 22.f;  // title bar
  float row = 18.f;    // one socket or setting
  float frame = 16.f;  // a widget's frame within its row
  float text = 13.f;   // text height: the UI font is scaled to it, whatever the interface size
  float pad = 8.f;     // inner margin left and right
  float pin_radius = 5.5f;
  float char_width = 7.f;
  float widget = 110.f;       // a setting's or valued input's widget
  float wide_widget = 150.f;  // three-number widgets (vectors)
  float min_width = 140.f, max_width = 320.f;
};

// A node's rows top to bottom: its outputs, then its parameter list in order (valued
// inputs with a pin, settings without), then its link-only inputs.
struct NodeRow {
  enum class Kind : unsigned char { output, param, link_input } kind = Kind::param;
  std::string_view name;
  std::optional<SocketType> socket;     // a pin: every output and input; none for settings
  ParamKind param = ParamKind::number;  // for Kind::param
};
std::vector<NodeRow> node_rows(const NodeVariant& node);
// Wide enough for the title (the id, and the type when it differs) and every row's
// widget and label, the same linked or not.
float node_width(const NodeVariant& node, std::string_view id = {}, const NodeMetrics& m = {});

struct PinBox {
  std::string_view name;
  SocketType type = SocketType::float_value;
  bool output = false;
  Vec2 center{0.f};  // canvas units
};
struct NodeBox {
  std::string id;
  CanvasRect rect;             // canvas units
  std::vector<float> row_top;  // per row of node_rows, relative to rect.min.y
  std::vector<float> row_height;
  std::vector<PinBox> pins;  // in row order
};
// The node at `position`. `row_heights` are the drawn heights of its rows (a widget
// may take more than a row, a list opened in place more still); rows without one are
// one row high.
NodeBox layout_node(const GraphNodeDesc& node, Vec2 position, const std::vector<float>& row_heights,
                    const NodeMetrics& m = {});
CanvasRect bounds_of(const std::vector<NodeBox>& boxes);

// ---------------------------------------------------------------- links
using Bezier = std::array<Vec2, 4>;
// The curve from an output pin to an input pin: it leaves rightwards and enters from the left.
Bezier link_bezier(Vec2 from, Vec2 to);
float bezier_distance(const Bezier& curve, Vec2 p);
Vec2 bezier_point(const Bezier& curve, float t);

// ---------------------------------------------------------------- hit testing
// The topmost node (the last in draw order) containing p, else -1.
int node_at(const std::vector<NodeBox>& boxes, Vec2 p);
struct PinHit {
  int node = -1, pin = -1;
  explicit operator bool() const { return node >= 0; }
};
// The pin nearest p within `radius` (canvas units), preferring the topmost node's.
PinHit pin_at(const std::vector<NodeBox>& boxes, Vec2 p, float radius);
// The link whose curve passes nearest p within `tolerance`, else -1.
int link_at(const std::vector<Bezier>& curves, Vec2 p, float tolerance);
// Indices of the nodes the rectangle touches.
std::vector<int> nodes_in_rect(const std::vector<NodeBox>& boxes, const CanvasRect& r);

// ---------------------------------------------------------------- selection rules
// A press on a node: with `additive` (Shift) it toggles; otherwise a node already
// selected keeps the selection (so a drag moves them all), another becomes the only one.
std::vector<std::string> press_select(std::vector<std::string> selected, const std::string& id,
                                      bool additive);
// A click released without a drag on a selected node selects it alone (unless additive).
std::vector<std::string> click_select(std::vector<std::string> selected, const std::string& id,
                                      bool additive);
// A box drag: the nodes in it, added to the selection with `additive`.
std::vector<std::string> box_select(std::vector<std::string> selected, const std::vector<std::string>& in_box,
                                    bool additive);

// ---------------------------------------------------------------- colours
// 8-bit sRGB, here rather than in the drawing so the screenshot test can look for them.
struct Rgb8 {
  unsigned char r = 0, g = 0, b = 0;
};
// Pins and links by socket type: float grey, colour yellow, vector blue, closure green.
Rgb8 socket_rgb(SocketType type);
// Title bars by category, as Blender colours them.
Rgb8 category_rgb(NodeCategory category);

// ---------------------------------------------------------------- layout export
// One line per node ("node ID X Y W H") and per link ("link FROM.OUT TO.IN X0 Y0 X1 Y1"),
// screen pixels rounded, after a "canvas X Y W H" line: what the screenshot test compares.
std::string layout_text(const std::vector<NodeBox>& boxes, const GraphDesc& graph, const CanvasView& view,
                        Vec2 canvas_size);

}  // namespace inkray
