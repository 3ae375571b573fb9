// Canvas maths for the node editor; see node_canvas.h.
#include "ui/nodes/node_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace inkray {
namespace {

float text_width(std::string_view s, const NodeMetrics& m) { return float(s.size()) * m.char_width; }

float distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.f ? std::clamp(glm::dot(p - a, ab) / len2, 0.f, 1.f) : 0.f;
  return glm::length(p - (a + t * ab));
}

struct RowCollector {
  std::vector<NodeRow>* rows;
  template <class F>
  void operator()(const Param& p, const F&) {
    rows->push_back({NodeRow::Kind::param, p.name, socket_type_of(p.kind), p.kind});
  }
};

}  // namespace

// ---------------------------------------------------------------- the view
Vec2 to_screen(const CanvasView& view, Vec2 canvas) { return view.origin + (canvas + view.pan) * view.zoom; }

Vec2 to_canvas(const CanvasView& view, Vec2 screen) { return (screen - view.origin) / view.zoom - view.pan; }

CanvasView zoom_about(CanvasView view, Vec2 screen, float zoom) {
  const Vec2 anchor = to_canvas(view, screen);
  view.zoom = std::clamp(zoom, kMinCanvasZoom, kMaxCanvasZoom);
  view.pan = (screen - view.origin) / view.zoom - anchor;
  return view;
}

CanvasRect rect_between(Vec2 a, Vec2 b) { return {glm::min(a, b), glm::max(a, b)}; }

CanvasView frame_bounds(CanvasView view, CanvasRect bounds, Vec2 size, float margin) {
  const Vec2 extent = glm::max(bounds.size(), Vec2(1.f));
  const auto fit = [&](float m) {
    const Vec2 room = glm::max(size - Vec2(2.f * m), Vec2(1.f));
    return std::min({room.x / extent.x, room.y / extent.y, 1.f});
  };
  const float zoom = fit(margin) < 1.f && fit(std::min(margin, 4.f)) >= 1.f ? 1.f : fit(margin);
  view.zoom = std::clamp(zoom, kMinCanvasZoom, kMaxCanvasZoom);
  const Vec2 centre = (bounds.min + bounds.max) * 0.5f;
  view.pan = size * 0.5f / view.zoom - centre;
  return view;
}

// ---------------------------------------------------------------- node geometry
std::vector<NodeRow> node_rows(const NodeVariant& node) {
  std::vector<NodeRow> rows;
  for (const SocketDecl& s : node_outputs(node)) rows.push_back({NodeRow::Kind::output, s.name, s.type});
  std::visit(
      [&]<class T>(const T& d) {
        RowCollector collector{&rows};
        visit_params(d, collector);
        if constexpr (graph_detail::HasLinkInputs<T>) {
          for (const SocketDecl& s : T::link_inputs)
            rows.push_back({NodeRow::Kind::link_input, s.name, s.type});
        }
      },
      node);
  return rows;
}

float node_width(const NodeVariant& node, std::string_view id, const NodeMetrics& m) {
  const std::string_view type = node_type_name(node);
  const float title =
      id.empty() || id == type ? text_width(type, m) : text_width(id, m) + 6.f + text_width(type, m);
  float width = title + 2.f * m.pad;
  for (const NodeRow& row : node_rows(node)) {
    float w = text_width(row.name, m) + 2.f * m.pad;
    if (row.kind == NodeRow::Kind::param) {
      const bool wide = row.param == ParamKind::vector || row.param == ParamKind::point ||
                        row.param == ParamKind::direction;
      w += (wide ? m.wide_widget : m.widget) + 4.f;
    }
    width = std::max(width, w);
  }
  return std::clamp(std::ceil(width), m.min_width, m.max_width);
}

NodeBox layout_node(const GraphNodeDesc& node, Vec2 position, const std::vector<float>& row_heights,
                    const NodeMetrics& m) {
  NodeBox box;
  box.id = node.id;
  const float width = node_width(node.data, node.id, m);
  const std::vector<NodeRow> rows = node_rows(node.data);
  float y = m.title + 4.f;
  for (size_t i = 0; i < rows.size(); ++i) {
    const float h = i < row_heights.size() && row_heights[i] > 0.f ? row_heights[i] : m.row;
    box.row_top.push_back(y);
    box.row_height.push_back(h);
    if (rows[i].socket) {
      const bool output = rows[i].kind == NodeRow::Kind::output;
      box.pins.push_back(
          {rows[i].name, *rows[i].socket, output, position + Vec2(output ? width : 0.f, y + m.row * 0.5f)});
    }
    y += h;
  }
  box.rect = {position, position + Vec2(width, y + 4.f)};
  return box;
}

CanvasRect bounds_of(const std::vector<NodeBox>& boxes) {
  if (boxes.empty()) return {};
  CanvasRect r = boxes[0].rect;
  for (const NodeBox& b : boxes) r.min = glm::min(r.min, b.rect.min), r.max = glm::max(r.max, b.rect.max);
  return r;
}

// ---------------------------------------------------------------- links
Bezier link_bezier(Vec2 from, Vec2 to) {
  // Handles grow with the horizontal gap, so a link running backwards loops around its nodes.
  const float dx = to.x - from.x;
  const float handle = std::max(40.f, dx >= 0.f ? dx * 0.5f : std::min(-dx, 200.f));
  return {from, from + Vec2(handle, 0.f), to - Vec2(handle, 0.f), to};
}

Vec2 bezier_point(const Bezier& c, float t) {
  const float u = 1.f - t;
  return u * u * u * c[0] + 3.f * u * u * t * c[1] + 3.f * u * t * t * c[2] + t * t * t * c[3];
}

float bezier_distance(const Bezier& curve, Vec2 p) {
  // Flattened as ImGui draws it; 32 segments keep the error far below a pick tolerance.
  constexpr int kSegments = 32;
  float best = std::numeric_limits<float>::max();
  Vec2 prev = curve[0];
  for (int i = 1; i <= kSegments; ++i) {
    const Vec2 next = bezier_point(curve, float(i) / kSegments);
    best = std::min(best, distance_to_segment(p, prev, next));
    prev = next;
  }
  return best;
}

// ---------------------------------------------------------------- hit testing
int node_at(const std::vector<NodeBox>& boxes, Vec2 p) {
  for (int i = int(boxes.size()) - 1; i >= 0; --i)
    if (boxes[size_t(i)].rect.contains(p)) return i;
  return -1;
}

PinHit pin_at(const std::vector<NodeBox>& boxes, Vec2 p, float radius) {
  PinHit best;
  float best_distance = radius;
  for (int i = int(boxes.size()) - 1; i >= 0; --i) {
    const NodeBox& box = boxes[size_t(i)];
    for (size_t k = 0; k < box.pins.size(); ++k) {
      const float d = glm::length(box.pins[k].center - p);
      if (d <= best_distance) best_distance = d, best = {i, int(k)};
    }
    // Pins of the nodes below are hidden where this one covers the point.
    if (box.rect.contains(p)) break;
  }
  return best;
}

int link_at(const std::vector<Bezier>& curves, Vec2 p, float tolerance) {
  int best = -1;
  float best_distance = tolerance;
  for (size_t i = 0; i < curves.size(); ++i) {
    const float d = bezier_distance(curves[i], p);
    if (d <= best_distance) best_distance = d, best = int(i);
  }
  return best;
}

std::vector<int> nodes_in_rect(const std::vector<NodeBox>& boxes, const CanvasRect& r) {
  std::vector<int> out;
  for (size_t i = 0; i < boxes.size(); ++i)
    if (boxes[i].rect.overlaps(r)) out.push_back(int(i));
  return out;
}

// ---------------------------------------------------------------- selection rules
std::vector<std::string> press_select(std::vector<std::string> selected, const std::string& id,
                                      bool additive) {
  const auto it = std::find(selected.begin(), selected.end(), id);
  if (additive) {
    if (it == selected.end()) {
      selected.push_back(id);
    } else {
      selected.erase(it);
    }
    return selected;
  }
  if (it != selected.end()) return selected;
  return {id};
}

std::vector<std::string> click_select(std::vector<std::string> selected, const std::string& id,
                                      bool additive) {
  if (additive) return selected;  // the press toggled it already
  return {id};
}

std::vector<std::string> box_select(std::vector<std::string> selected, const std::vector<std::string>& in_box,
                                    bool additive) {
  if (!additive) selected.clear();
  for (const std::string& id : in_box)
    if (std::find(selected.begin(), selected.end(), id) == selected.end()) selected.push_back(id);
  return selected;
}

// ---------------------------------------------------------------- colours
Rgb8 socket_rgb(SocketType type) {
  switch (type) {
    case SocketType::float_value:
      return {161, 161, 161};
    case SocketType::color:
      return {199, 199, 41};
    case SocketType::vector:
      return {99, 99, 199};
    case SocketType::closure:
      return {99, 199, 99};
  }
  return {255, 255, 255};
}

Rgb8 category_rgb(NodeCategory category) {
  switch (category) {
    case NodeCategory::input:
      return {148, 56, 84};
    case NodeCategory::texture:
      return {176, 108, 36};
    case NodeCategory::converter:
      return {44, 100, 148};
    case NodeCategory::closure:
      return {40, 128, 68};
    case NodeCategory::output:
      return {140, 36, 36};
  }
  return {255, 255, 255};
}

// ---------------------------------------------------------------- layout export
std::string layout_text(const std::vector<NodeBox>& boxes, const GraphDesc& graph, const CanvasView& view,
                        Vec2 canvas_size) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line, "canvas %d %d %d %d\n", int(std::lround(view.origin.x)),
                int(std::lround(view.origin.y)), int(std::lround(canvas_size.x)),
                int(std::lround(canvas_size.y)));
  out += line;
  for (const NodeBox& b : boxes) {
    const Vec2 a = to_screen(view, b.rect.min), z = to_screen(view, b.rect.max);
    std::snprintf(line, sizeof line, "node %s %d %d %d %d\n", b.id.c_str(), int(std::lround(a.x)),
                  int(std::lround(a.y)), int(std::lround(z.x - a.x)), int(std::lround(z.y - a.y)));
    out += line;
  }
  const auto pin = [&](std::string_view node, std::string_view name, bool output) -> std::optional<Vec2> {
    for (const NodeBox& b : boxes) {
      if (b.id != node) continue;
      for (const PinBox& p : b.pins)
        if (p.output == output && p.name == name) return to_screen(view, p.center);
    }
    return std::nullopt;
  };
  for (const GraphLinkDesc& l : graph.links) {
    const auto from = pin(l.from, l.output, true), to = pin(l.to, l.input, false);
    if (!from || !to) continue;
    std::snprintf(line, sizeof line, "link %s.%s %s.%s %d %d %d %d\n", l.from.c_str(), l.output.c_str(),
                  l.to.c_str(), l.input.c_str(), int(std::lround(from->x)), int(std::lround(from->y)),
                  int(std::lround(to->x)), int(std::lround(to->y)));
    out += line;
  }
  return out;
}

}  // namespace inkray
