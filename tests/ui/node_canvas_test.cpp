// The node editor's canvas maths: view transforms, node geometry, hit testing and
// the selection rules, without a window.
#include "ui/nodes/node_canvas.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

void expect_near(Vec2 a, Vec2 b, float tolerance = 1e-3f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
}

TEST(NodeCanvas, ScreenAndCanvasAreInverse) {
  const CanvasView view{Vec2(100, 50), Vec2(-20, 30), 1.5f};
  const Vec2 c(12.5f, -7.f);
  expect_near(to_canvas(view, to_screen(view, c)), c);
  expect_near(to_screen(view, Vec2(20, -30)), Vec2(100, 50));  // -pan sits at the origin
  expect_near(to_screen(view, Vec2(30, -30)), Vec2(115, 50));  // 10 units are 15 pixels at zoom 1.5
}

TEST(NodeCanvas, ZoomKeepsThePointUnderTheCursor) {
  const CanvasView view{Vec2(10, 10), Vec2(5, 5), 1.f};
  const Vec2 cursor(300, 200);
  const Vec2 under = to_canvas(view, cursor);
  const CanvasView zoomed = zoom_about(view, cursor, 2.f);
  EXPECT_FLOAT_EQ(zoomed.zoom, 2.f);
  expect_near(to_canvas(zoomed, cursor), under);
  EXPECT_FLOAT_EQ(zoom_about(view, cursor, 100.f).zoom, kMaxCanvasZoom);
  EXPECT_FLOAT_EQ(zoom_about(view, cursor, 0.f).zoom, kMinCanvasZoom);
}

TEST(NodeCanvas, FramingCentresAndNeverZoomsIn) {
  CanvasView view{Vec2(0, 0), Vec2(0, 0), 1.f};
  const CanvasRect small{Vec2(100, 100), Vec2(200, 150)};
  const CanvasView framed = frame_bounds(view, small, Vec2(800, 400), 20.f);
  EXPECT_FLOAT_EQ(framed.zoom, 1.f);
  expect_near(to_screen(framed, Vec2(150, 125)), Vec2(400, 200));
  const CanvasRect big{Vec2(0, 0), Vec2(2000, 500)};
  const CanvasView fitted = frame_bounds(view, big, Vec2(1040, 400), 20.f);
  EXPECT_NEAR(fitted.zoom, 0.5f, 1e-5f);
  const Vec2 a = to_screen(fitted, big.min), b = to_screen(fitted, big.max);
  EXPECT_GE(a.x, 19.9f);
  EXPECT_LE(b.x, 1020.1f);
  EXPECT_GE(a.y, 0.f);
  EXPECT_LE(b.y, 400.f);
}

TEST(NodeCanvas, RowsFollowTheParameterList) {
  const std::vector<NodeRow> rows = node_rows(NoiseNode{});
  ASSERT_EQ(rows.size(), 2u + 5u + 1u);  // outputs fac, color; five parameters; vector
  EXPECT_EQ(rows[0].kind, NodeRow::Kind::output);
  EXPECT_EQ(rows[0].name, "fac");
  EXPECT_EQ(rows[2].name, "noise");
  EXPECT_FALSE(rows[2].socket);  // a choice is a setting, not a socket
  EXPECT_FALSE(rows[3].socket);  // octaves: an integer setting
  EXPECT_EQ(rows[4].socket, SocketType::float_value);
  EXPECT_EQ(rows[7].kind, NodeRow::Kind::link_input);
  EXPECT_EQ(rows[7].socket, SocketType::vector);
}

TEST(NodeCanvas, PinsSitOnTheEdgesAtTheirRows) {
  const NodeMetrics m;
  const GraphNodeDesc node{"mix", MixColorNode{}};
  const NodeBox box = layout_node(node, Vec2(40, 60), {});
  const float width = node_width(node.data, node.id);
  EXPECT_FLOAT_EQ(box.rect.size().x, width);
  EXPECT_GE(width, m.min_width);
  // Outputs on the right, inputs on the left, each at its row's first line.
  ASSERT_EQ(box.pins.size(), 1u + 3u);  // color out; fac, a, b in
  EXPECT_TRUE(box.pins[0].output);
  EXPECT_FLOAT_EQ(box.pins[0].center.x, 40 + width);
  for (size_t k = 1; k < box.pins.size(); ++k) {
    EXPECT_FALSE(box.pins[k].output);
    EXPECT_FLOAT_EQ(box.pins[k].center.x, 40);
    EXPECT_GT(box.pins[k].center.y, box.pins[k - 1].center.y);
    EXPECT_LT(box.pins[k].center.y, box.rect.max.y);
  }
  // A taller row (an open list) pushes the rows below it down.
  std::vector<float> heights(node_rows(node.data).size(), m.row);
  heights[1] = 60.f;  // the blend choice
  const NodeBox taller = layout_node(node, Vec2(40, 60), heights);
  EXPECT_FLOAT_EQ(taller.pins.back().center.y - box.pins.back().center.y, 60.f - m.row);
  EXPECT_FLOAT_EQ(taller.rect.size().y - box.rect.size().y, 60.f - m.row);
}

TEST(NodeCanvas, HitTestingPrefersTheTopmostNode) {
  const std::vector<NodeBox> boxes = {layout_node({"a", ValueNode{}}, Vec2(0, 0), {}),
                                      layout_node({"b", ValueNode{}}, Vec2(50, 10), {})};
  EXPECT_EQ(node_at(boxes, Vec2(60, 20)), 1);  // both contain it; b is drawn above
  EXPECT_EQ(node_at(boxes, Vec2(10, 20)), 0);
  EXPECT_EQ(node_at(boxes, Vec2(-5, 20)), -1);
  const Vec2 pin = boxes[0].pins[0].center;  // a's output, on its right edge, under b
  ASSERT_TRUE(boxes[1].rect.contains(pin));
  EXPECT_FALSE(pin_at(boxes, pin + Vec2(-2, 1), 8.f));
  const PinHit a_in = pin_at(boxes, boxes[0].pins[1].center + Vec2(-3, 0), 8.f);  // a's input, left of b
  EXPECT_EQ(a_in.node, 0);
  EXPECT_EQ(a_in.pin, 1);
  const PinHit b_out = pin_at(boxes, boxes[1].pins[0].center + Vec2(2, 0), 8.f);
  EXPECT_EQ(b_out.node, 1);
  EXPECT_EQ(b_out.pin, 0);
  EXPECT_FALSE(pin_at(boxes, Vec2(500, 500), 8.f));
}

TEST(NodeCanvas, LinksArePickedByTheirCurve) {
  const Bezier straight = link_bezier(Vec2(0, 0), Vec2(200, 0));
  EXPECT_NEAR(bezier_distance(straight, Vec2(100, 3)), 3.f, 0.05f);
  const Bezier s_curve = link_bezier(Vec2(0, 0), Vec2(200, 100));
  const Vec2 mid = bezier_point(s_curve, 0.5f);
  EXPECT_NEAR(mid.x, 100.f, 1e-3f);  // symmetric handles: the middle is halfway
  EXPECT_NEAR(mid.y, 50.f, 1e-3f);
  EXPECT_LT(bezier_distance(s_curve, mid + Vec2(0, 2)), 2.01f);
  // A point on the chord but off the curve is far from it: the curve is not a straight line.
  EXPECT_GT(bezier_distance(s_curve, Vec2(40, 20)), 8.f);
  const std::vector<Bezier> curves = {straight, s_curve};
  EXPECT_EQ(link_at(curves, mid + Vec2(1, 1), 6.f), 1);
  EXPECT_EQ(link_at(curves, Vec2(100, 1), 6.f), 0);
  EXPECT_EQ(link_at(curves, Vec2(100, 300), 6.f), -1);
}

TEST(NodeCanvas, BoxSelection) {
  const std::vector<NodeBox> boxes = {layout_node({"a", ValueNode{}}, Vec2(0, 0), {}),
                                      layout_node({"b", ValueNode{}}, Vec2(300, 0), {}),
                                      layout_node({"c", ValueNode{}}, Vec2(0, 300), {})};
  // Dragged from bottom-right to top-left: corners in any order.
  const std::vector<int> hit = nodes_in_rect(boxes, rect_between(Vec2(310, 20), Vec2(-10, -10)));
  EXPECT_EQ(hit, (std::vector<int>{0, 1}));
  EXPECT_EQ(box_select({"c"}, {"a", "b"}, false), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(box_select({"c"}, {"a", "c"}, true), (std::vector<std::string>{"c", "a"}));
}

TEST(NodeCanvas, ClickSelection) {
  EXPECT_EQ(press_select({"a"}, "b", false), (std::vector<std::string>{"b"}));
  EXPECT_EQ(press_select({"a", "b"}, "b", false), (std::vector<std::string>{"a", "b"}));  // a drag moves both
  EXPECT_EQ(click_select({"a", "b"}, "b", false), (std::vector<std::string>{"b"}));       // no drag: b alone
  EXPECT_EQ(press_select({"a"}, "b", true), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(press_select({"a", "b"}, "a", true), (std::vector<std::string>{"b"}));
  EXPECT_EQ(click_select({"b"}, "a", true), (std::vector<std::string>{"b"}));
}

TEST(NodeCanvas, LayoutTextNamesNodesAndLinkEnds) {
  GraphDesc g;
  g.nodes = {{"v", ValueNode{}}, {"m", MathNode{}}};
  g.links = {{"v", "value", "m", "b"}};
  const std::vector<NodeBox> boxes = {layout_node(g.nodes[0], Vec2(0, 0), {}),
                                      layout_node(g.nodes[1], Vec2(200, 0), {})};
  const CanvasView view{Vec2(10, 20), Vec2(0, 0), 1.f};
  const std::string text = layout_text(boxes, g, view, Vec2(640, 480));
  EXPECT_NE(text.find("canvas 10 20 640 480\n"), std::string::npos) << text;
  const int w = int(node_width(g.nodes[0].data, g.nodes[0].id));
  EXPECT_NE(text.find("node v 10 20 " + std::to_string(w) + " "), std::string::npos) << text;
  // From v's right edge to m's left edge.
  EXPECT_NE(text.find("link v.value m.b " + std::to_string(10 + w) + " "), std::string::npos) << text;
  EXPECT_NE(text.find(" 210 "), std::string::npos) << text;
}

}  // namespace
}  // namespace inkray
