// ImDrawList drawing of nodes, links and the grid, and the widgets inside nodes.
#include "ui/nodes/node_drawing.h"

#include "core/document/param_text.h"
#include "ui/widgets/param_widgets.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

constexpr ImU32 kBody = IM_COL32(46, 46, 50, 245);
constexpr ImU32 kBorder = IM_COL32(18, 18, 20, 255);
constexpr ImU32 kSelectedBorder = IM_COL32(255, 170, 50, 255);
constexpr ImU32 kLabel = IM_COL32(215, 215, 215, 255);
constexpr ImU32 kTitle = IM_COL32(250, 250, 250, 255);
constexpr ImU32 kTitleType = IM_COL32(250, 250, 250, 150);

ImVec2 im(Vec2 v) { return ImVec2(v.x, v.y); }

// Text at the canvas zoom: NodeMetrics::text canvas units, whatever the UI font size.
void canvas_text(ImDrawList* draw, float zoom, ImVec2 at, ImU32 color, std::string_view text,
                 const ImVec4* clip) {
  ImFont* font = ImGui::GetFont();
  draw->AddText(font, NodeMetrics{}.text * zoom, at, color, text.data(), text.data() + text.size(), 0.f,
                clip);
}

float canvas_text_width(float zoom, std::string_view text) {
  ImFont* font = ImGui::GetFont();
  return font->CalcTextSizeA(NodeMetrics{}.text * zoom, FLT_MAX, 0.f, text.data(), text.data() + text.size())
      .x;
}

// A colour as a bar the width of a widget, opening a picker: ImGui's ColorEdit3 squeezes
// three numbers into a node's width, which nobody can read.
bool color_bar(const Param& p, Color& c, float width) {
  ImGui::PushID(p.name.data(), p.name.data() + p.name.size());
  const ImVec4 shown(std::min(c.x, 1.f), std::min(c.y, 1.f), std::min(c.z, 1.f), 1.f);
  // One item, bar and label, for what follows (key marks, a key's menu).
  ImGui::BeginGroup();
  if (ImGui::ColorButton("##bar", shown, ImGuiColorEditFlags_NoTooltip,
                         ImVec2(width, ImGui::GetFrameHeight())))
    ImGui::OpenPopup("picker");
  if (ImGui::IsItemHovered() && !p.doc.empty()) ImGui::SetTooltip("%s", param_tooltip(p, false).c_str());
  ImGui::SameLine(0.f, ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(param_label(p).c_str());
  ImGui::EndGroup();
  bool changed = false;
  if (ImGui::BeginPopup("picker")) {
    ImGui::SetWindowFontScale(1.f);  // the picker is a window of its own, at the normal size
    Color edited = c;
    if (ImGui::ColorPicker3("##picker", &edited.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR)) {
      // Within what the reader accepts, like every generated widget.
      for (int k = 0; k < 3; ++k)
        edited[k] = float(std::clamp(double(edited[k]), std::max(p.min, 0.0), p.max));
      if (edited != c) c = edited, changed = true;
    }
    ImGui::EndPopup();
  }
  ImGui::PopID();
  return changed;
}

// Draws a node's parameter rows in parameter table order: a widget at each unlinked row.
struct RowWidgets {
  const NodeBox& box;
  const std::vector<std::string_view>& linked;
  const CanvasView& view;
  ImDrawList* draw;
  ImVec4 clip;
  size_t row = 0;  // the next parameter's row in node_rows
  bool widgets = true;
  NodeMetrics m;
  ParamWidgets generated;
  bool bar_changed = false;
  std::string bar_param;
  std::vector<float>* heights;

  template <class F>
  void operator()(const Param& p, F& field) {
    const size_t r = row++;
    const float z = view.zoom;
    const Vec2 top = to_screen(view, box.rect.min + Vec2(m.pad, box.row_top[r]));
    const bool socket = socket_type_of(p.kind).has_value();
    const bool is_linked = socket && std::find(linked.begin(), linked.end(), p.name) != linked.end();
    if (is_linked || !widgets) {
      const float text_y = top.y + (m.row - m.text) * z * 0.5f;
      canvas_text(draw, z, ImVec2(top.x, text_y), kLabel, param_label(p), &clip);
      return;
    }
    const float inset = (m.row - m.frame) * 0.5f * z;
    ImGui::SetCursorScreenPos(ImVec2(top.x, top.y + inset));
    const bool wide =
        p.kind == ParamKind::vector || p.kind == ParamKind::point || p.kind == ParamKind::direction;
    const float width = (wide ? m.wide_widget : m.widget) * z;
    ImGui::PushItemWidth(width);
    if constexpr (std::is_same_v<F, Vec3>) {
      if (p.kind == ParamKind::color) {
        if (color_bar(p, field, width)) bar_changed = true, bar_param = p.name;
        generated.key_marks(
            p, top.x + width - 0.5f * ImGui::GetFrameHeight());  // in the bar: the label fills the row
      } else {
        generated(p, field);
      }
    } else if constexpr (std::is_same_v<F, ColorInput>) {
      if (Color* constant = std::get_if<Color>(&field)) {
        if (color_bar(p, *constant, width)) bar_changed = true, bar_param = p.name;
        generated.key_marks(
            p, top.x + width - 0.5f * ImGui::GetFrameHeight());  // in the bar: the label fills the row
      } else {
        generated(p, field);  // a texture object kept from a plain material: its own widgets
      }
    } else {
      generated(p, field);
    }
    ImGui::PopItemWidth();
    (*heights)[r] = std::max(m.row, (ImGui::GetCursorScreenPos().y - top.y - inset) / z);
  }
};

}  // namespace

ImU32 socket_color(SocketType type) {
  const Rgb8 c = socket_rgb(type);
  return IM_COL32(c.r, c.g, c.b, 255);
}

ImU32 category_color(NodeCategory category) {
  const Rgb8 c = category_rgb(category);
  return IM_COL32(c.r, c.g, c.b, 255);
}

void draw_grid(ImDrawList* draw, const CanvasView& view, Vec2 size) {
  draw->AddRectFilled(im(view.origin), im(view.origin + size), IM_COL32(30, 30, 34, 255));
  // Lines every 32 units, fading out when they would crowd closer than 8 pixels.
  const float step = 32.f * view.zoom;
  if (step < 8.f) return;
  const Vec2 offset = glm::mod(view.pan * view.zoom, Vec2(step));
  for (float x = offset.x; x < size.x; x += step)
    draw->AddLine(ImVec2(view.origin.x + x, view.origin.y), ImVec2(view.origin.x + x, view.origin.y + size.y),
                  IM_COL32(48, 48, 54, 255));
  for (float y = offset.y; y < size.y; y += step)
    draw->AddLine(ImVec2(view.origin.x, view.origin.y + y), ImVec2(view.origin.x + size.x, view.origin.y + y),
                  IM_COL32(48, 48, 54, 255));
}

void draw_link(ImDrawList* draw, const CanvasView& view, const Bezier& curve, ImU32 color, float thickness) {
  draw->AddBezierCubic(im(to_screen(view, curve[0])), im(to_screen(view, curve[1])),
                       im(to_screen(view, curve[2])), im(to_screen(view, curve[3])), color,
                       thickness * view.zoom);
}

NodeDrawResult draw_node(ImDrawList* draw, const CanvasView& view, const GraphNodeDesc& node,
                         const NodeBox& box, const std::vector<std::string_view>& linked_inputs,
                         bool selected, bool widgets, const NodeWidgetContext& context) {
  const NodeMetrics m;
  const float z = view.zoom;
  const ImVec2 a = im(to_screen(view, box.rect.min)), b = im(to_screen(view, box.rect.max));
  const float rounding = 5.f * z;
  draw->AddRectFilled(a, b, kBody, rounding);
  draw->AddRectFilled(a, ImVec2(b.x, a.y + m.title * z), category_color(node_category(node.data)), rounding,
                      ImDrawFlags_RoundCornersTop);
  const ImVec4 clip(a.x, a.y, b.x - m.pad * 0.5f * z, b.y);
  const float font = m.text * z;
  const float title_y = a.y + (m.title * z - font) * 0.5f;
  // The id names the node in links and messages; the type says what it is.
  canvas_text(draw, z, ImVec2(a.x + m.pad * z, title_y), kTitle, node.id, &clip);
  const std::string_view type = node_type_name(node.data);
  if (node.id != type) {
    const float after = a.x + m.pad * z + canvas_text_width(z, node.id) + 6.f * z;
    canvas_text(draw, z, ImVec2(after, title_y), kTitleType, type, &clip);
  }

  NodeDrawResult result;
  const std::vector<NodeRow> rows = node_rows(node.data);
  result.row_heights.assign(rows.size(), m.row);
  size_t first_param = rows.size();
  for (size_t r = 0; r < rows.size(); ++r) {
    const float row_y = to_screen(view, box.rect.min + Vec2(0.f, box.row_top[r])).y;
    const float text_y = row_y + (m.row * z - font) * 0.5f;
    if (rows[r].kind == NodeRow::Kind::output) {
      const float w = canvas_text_width(z, rows[r].name);
      canvas_text(draw, z, ImVec2(b.x - m.pad * z - w, text_y), kLabel, rows[r].name, &clip);
    } else if (rows[r].kind == NodeRow::Kind::link_input) {
      canvas_text(draw, z, ImVec2(a.x + m.pad * z, text_y), kLabel, rows[r].name, &clip);
    } else {
      first_param = std::min(first_param, r);
    }
  }

  // Widgets edit a copy; clipped to the node, so they neither show nor take clicks outside it.
  result.edited = node.data;
  ImGui::PushID(node.id.c_str());
  ImGui::PushClipRect(ImVec2(clip.x, clip.y), ImVec2(clip.z, clip.w), true);
  std::visit(
      [&](auto& settings) {
        RowWidgets rw{box, linked_inputs,      view, draw, clip, first_param, widgets, m, {}, false,
                      {},  &result.row_heights};
        rw.generated.scene = context.scene;  // an image node's browse button starts in the scene's folder
        rw.generated.keys = context.keys;
        rw.generated.key_item = context.material;
        rw.generated.key_group = "nodes." + node.id;
        visit_params(settings, rw);
        result.changed = rw.generated.changed || rw.bar_changed;
        result.changed_param = rw.bar_changed ? rw.bar_param : rw.generated.changed_param;
      },
      result.edited);
  ImGui::PopClipRect();
  ImGui::PopID();

  draw->AddRect(a, b, selected ? kSelectedBorder : kBorder, rounding, 0,
                (selected ? 2.f : 1.f) * std::max(z, 0.5f));
  for (const PinBox& pin : box.pins) {
    const ImVec2 c = im(to_screen(view, pin.center));
    draw->AddCircleFilled(c, m.pin_radius * z, socket_color(pin.type));
    draw->AddCircle(c, m.pin_radius * z, IM_COL32(20, 20, 20, 255), 0, 1.5f * std::max(z, 0.5f));
  }
  return result;
}

}  // namespace inkray
