// The node editor's state and input: what a press, drag and release on the canvas do,
// keys, and the edits they commit. Drawing is node_drawing.cpp's.
#include "ui/nodes/node_editor_panel.h"

#include "core/compiler/graph_checks.h"
#include "core/document/graph_edit.h"
#include "ui/widgets/key_actions.h"
#include "ui/widgets/material_swatches.h"
#include "ui/nodes/node_add_menu.h"
#include "ui/nodes/node_drawing.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace inkray {
namespace {

constexpr float kDragThreshold = 3.f;  // pixels before a press becomes a drag
constexpr float kPickPixels = 9.f;     // how near a pin or link must be, on screen
constexpr float kFrameMargin = 20.f;   // pixels around the nodes when framing them
// A zoom gesture (wheel steps) ends this long after its last step, and is then written.
constexpr auto kViewSettle = std::chrono::milliseconds(500);

const PinBox* find_pin(const std::vector<NodeBox>& boxes, std::string_view node, std::string_view name,
                       bool output) {
  for (const NodeBox& b : boxes) {
    if (b.id != node) continue;
    for (const PinBox& p : b.pins)
      if (p.output == output && p.name == name) return &p;
  }
  return nullptr;
}

// The view a material's graph stores; nullopt for a plain material, which has none.
std::optional<CanvasView> stored_view(const MaterialDesc& m) {
  const auto* g = std::get_if<GraphDesc>(&m.data);
  if (!g) return std::nullopt;
  return CanvasView{Vec2(0.f), Vec2(g->editor.pan_x, g->editor.pan_y), g->editor.zoom};
}

bool same_view(const std::optional<CanvasView>& a, const std::optional<CanvasView>& b) {
  if (!a || !b) return !a && !b;
  return a->pan == b->pan && a->zoom == b->zoom;
}

}  // namespace

int node_editor_material(const SceneDesc& scene, const Selection& selection) {
  if (!is_valid(scene, selection)) return -1;
  if (selection.kind == ItemKind::material) return selection.index;
  if (selection.kind != ItemKind::object) return -1;
  const std::string& name = scene.objects[size_t(selection.index)].material;
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == name) return int(i);
  return -1;
}

void NodeEditorPanel::commit(EditorState& state, GraphDesc graph, const std::string& label,
                             const std::string& merge_key) {
  SceneDesc scene = state.document.scene();
  if (material_ < 0 || material_ >= int(scene.materials.size())) return;
  graph_ = graph;  // the rest of this frame sees the edit
  is_graph_ = true;
  scene.materials[size_t(material_)].data = std::move(graph);
  doc_view_ = stored_view(scene.materials[size_t(material_)]);
  state.edit(std::move(scene), label, merge_key);
}

// The view is written alone, one undo step per gesture, so undoing an edit never moves it.
void NodeEditorPanel::commit_view(EditorState& state) {
  view_edited_ = false;
  if (!is_graph_ || same_view(CanvasView{Vec2(0.f), view_.pan, view_.zoom}, doc_view_)) return;
  GraphDesc g = graph_;
  g.editor.pan_x = std::clamp(view_.pan.x, -1e7f, 1e7f);
  g.editor.pan_y = std::clamp(view_.pan.y, -1e7f, 1e7f);
  g.editor.zoom = view_.zoom;
  commit(state, std::move(g), "Pan/zoom nodes", "graph-view:" + material_name_);
  state.document.end_merge();
}

void NodeEditorPanel::draw(EditorState& state, bool* open) {
  const SceneDesc& scene = state.document.scene();
  const int m = node_editor_material(scene, state.selection);
  focused_ = false;
  if (m < 0) {
    material_ = -1;
    material_name_.clear();
    layout_.clear();
    header(state, open);
    ImGui::TextDisabled("Select a material, or an object, to see its nodes.");
    return;
  }
  // The graph's values at the current frame, as every panel shows them; an edit of an
  // animated one keys it (ui/model/document.cpp), and others keep their tracks.
  const MaterialDesc& material = state.shown().materials[size_t(m)];
  const std::optional<CanvasView> stored = stored_view(material);
  if (material.name != material_name_) {
    // Another material: its own view, nothing selected or dragged.
    material_name_ = material.name;
    selected_.clear();
    row_heights_.clear();
    drag_ = Drag::none;
    picked_link_.reset();
    view_ = stored.value_or(CanvasView{});
    doc_view_ = stored;
    view_edited_ = false;
    // A graph written by hand (or a plain material) has no view yet: show all of it.
    want_frame_ |= !stored || (stored->pan == Vec2(0.f) && stored->zoom == 1.f);
  } else if (!same_view(stored, doc_view_)) {
    view_ = stored.value_or(view_);  // undo, redo or a reload moved it
    doc_view_ = stored;
    view_edited_ = false;
  }
  material_ = m;
  is_graph_ = std::holds_alternative<GraphDesc>(material.data);
  graph_ = graph_from_material(material.data);
  place_unplaced_nodes(graph_);
  std::erase_if(selected_, [&](const std::string& id) { return !find_node(graph_, id); });
  if (view_edited_ && drag_ != Drag::pan && std::chrono::steady_clock::now() - view_edit_time_ > kViewSettle)
    commit_view(state);

  header(state, open);
  draw_canvas(state);
}

void NodeEditorPanel::header(EditorState& state, bool* open) {
  ImGui::AlignTextToFramePadding();
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.f, 1.f), "Node editor");
  const float close_x = ImGui::GetWindowContentRegionMax().x - ImGui::CalcTextSize("x").x -
                        ImGui::GetStyle().FramePadding.x * 2.f;
  if (material_ >= 0) {
    const MaterialDesc& material = state.document.scene().materials[size_t(material_)];
    ImGui::SameLine();
    ImGui::TextUnformatted(material.name.c_str());
    ImGui::SameLine();
    if (!is_graph_) {
      const bool mix = std::holds_alternative<MixDesc>(material.data);
      ImGui::TextDisabled(mix ? "(mix material: editing nodes replaces it with a graph; undo restores it)"
                              : "(plain %s material shown as nodes: the first edit makes it a graph)",
                          std::string(type_name_of(material.data)).c_str());
    } else {
      ImGui::TextDisabled("(graph, %zu nodes)", graph_.nodes.size());
    }
    if (!problems_.empty()) {
      // The graph's checks (the same the compiler runs), so a broken graph says why where it is edited.
      ImGui::SameLine();
      ImGui::TextColored(ImVec4(1.f, 0.45f, 0.45f, 1.f), "%zu problem%s", problems_.size(),
                         problems_.size() == 1 ? "" : "s");
      if (ImGui::IsItemHovered()) {
        std::string all;
        for (const std::string& p : problems_) all += p + "\n";
        ImGui::SetTooltip("%s", all.c_str());
      }
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("Add node"))
      open_add_menu_ = true, add_at_ = to_canvas(view_, view_.origin + canvas_size_ * 0.4f);
    ImGui::SameLine();
    if (ImGui::SmallButton("Frame all")) want_frame_ = frame_is_edit_ = true;
    ImGui::SameLine();
    ImGui::TextDisabled("%d%%  ?", int(std::lround(view_.zoom * 100.f)));
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Shift+A or right click: add a node (type to search)\n"
          "Drag from a pin to a pin: link; from a linked input: move or remove the link\n"
          "Click, Shift+click, drag on empty canvas: select\n"
          "Drag a node: move it; drop one onto a link: insert it\n"
          "X or Delete: delete   Shift+D: duplicate   Ctrl+C / Ctrl+V: copy / paste\n"
          "Wheel: zoom   Middle or Alt+left drag: pan   Home: frame all");
  }
  ImGui::SameLine(close_x);
  if (ImGui::SmallButton("x")) *open = false;
}

// Runs the compiler's graph checks when the graph changed; nodes they name are outlined in red.
void NodeEditorPanel::check(const GraphDesc& graph) {
  if (checked_graph_ && *checked_graph_ == graph) return;
  checked_graph_ = graph;
  problems_.clear();
  problem_nodes_.clear();
  CheckedGraph unused;
  if (is_graph_) check_graph(graph, unused, problems_);
  for (const std::string& p : problems_) {
    // A message about a link starts "links[k]": both its ends are outlined.
    if (p.rfind("links[", 0) == 0) {
      const size_t k = size_t(std::strtoul(p.c_str() + 6, nullptr, 10));
      if (k < graph.links.size()) problem_nodes_.insert({graph.links[k].from, graph.links[k].to});
    }
    // Any node a message names as "nodes[i]".
    for (size_t at = p.find("nodes["); at != std::string::npos; at = p.find("nodes[", at + 1)) {
      const size_t index = size_t(std::strtoul(p.c_str() + at + 6, nullptr, 10));
      if (index < graph.nodes.size()) problem_nodes_.insert(graph.nodes[index].id);
    }
  }
}

void NodeEditorPanel::draw_problem_outlines(const std::vector<NodeBox>& boxes) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (const NodeBox& box : boxes) {
    if (!problem_nodes_.count(box.id)) continue;
    const Vec2 a = to_screen(view_, box.rect.min - Vec2(3.f)), b = to_screen(view_, box.rect.max + Vec2(3.f));
    draw->AddRect(ImVec2(a.x, a.y), ImVec2(b.x, b.y), IM_COL32(255, 70, 70, 255), 6.f * view_.zoom, 0, 3.f);
  }
}

// The material's preview swatch, hanging under the output node.
void NodeEditorPanel::draw_swatch(EditorState& state, const std::vector<NodeBox>& boxes) {
  if (!state.swatches || material_name_.empty()) return;
  state.swatches->want(material_name_);
  const GraphNodeDesc* output = nullptr;
  for (const GraphNodeDesc& n : graph_.nodes)
    if (std::holds_alternative<OutputNode>(n.data)) output = &n;
  const auto box = std::find_if(boxes.begin(), boxes.end(),
                                [&](const NodeBox& b) { return output && b.id == output->id; });
  if (box == boxes.end()) return;
  const Vec2 corner = to_screen(view_, Vec2(box->rect.min.x, box->rect.max.y + 6.f));
  const float side = (box->rect.max.x - box->rect.min.x) * view_.zoom;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 a(corner.x, corner.y), b(corner.x + side, corner.y + side);
  if (const ImTextureID swatch = state.swatches->texture(material_name_)) {
    draw->AddImage(swatch, a, b);
  } else {
    draw->AddRectFilled(a, b, IM_COL32(40, 40, 44, 255));
    draw->AddText(ImVec2(a.x + 6.f, a.y + 6.f), IM_COL32(160, 160, 160, 255), "rendering...");
  }
  draw->AddRect(a, b, IM_COL32(90, 90, 96, 255));
}

void NodeEditorPanel::draw_canvas(EditorState& state) {
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::BeginChild(
      "canvas", ImVec2(0, 0), true,
      ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoMove);
  ImGui::PopStyleVar();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  view_.origin = Vec2(origin.x, origin.y);
  canvas_size_ = Vec2(std::max(avail.x, 1.f), std::max(avail.y, 1.f));

  // Selected nodes are drawn last, on top, and hit first.
  std::vector<const GraphNodeDesc*> order;
  for (const GraphNodeDesc& n : graph_.nodes)
    if (std::find(selected_.begin(), selected_.end(), n.id) == selected_.end()) order.push_back(&n);
  for (const GraphNodeDesc& n : graph_.nodes)
    if (std::find(selected_.begin(), selected_.end(), n.id) != selected_.end()) order.push_back(&n);
  std::vector<NodeBox> boxes;
  for (const GraphNodeDesc* n : order)
    boxes.push_back(layout_node(*n, node_position(graph_, n->id).value_or(Vec2(0.f)), row_heights_[n->id]));
  if (want_frame_ && !boxes.empty()) {
    view_ = frame_bounds(view_, bounds_of(boxes), canvas_size_, kFrameMargin);
    // Asked for, it is a view change like a pan; on opening a material it is only how it is shown.
    if (frame_is_edit_) view_edited_ = true, view_edit_time_ = std::chrono::steady_clock::now();
    want_frame_ = frame_is_edit_ = false;
  }

  curves_.clear();
  curve_link_.clear();
  for (size_t k = 0; k < graph_.links.size(); ++k) {
    const GraphLinkDesc& l = graph_.links[k];
    const PinBox* from = find_pin(boxes, l.from, l.output, true);
    const PinBox* to = find_pin(boxes, l.to, l.input, false);
    if (!from || !to) continue;  // a link to a socket that does not exist: check() reports it
    curves_.push_back(link_bezier(from->center, to->center));
    curve_link_.push_back(int(k));
  }

  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw_grid(draw, view_, canvas_size_);
  for (size_t c = 0; c < curves_.size(); ++c) {
    const GraphLinkDesc& l = graph_.links[size_t(curve_link_[c])];
    if (picked_link_ && *picked_link_ == l) continue;  // drawn as the dragged link instead
    const bool target = curve_link_[c] == insert_link_;
    const GraphNodeDesc* from = find_node(graph_, l.from);
    const ImU32 color =
        target ? IM_COL32(255, 255, 255, 255)
               : socket_color(output_type(from->data, l.output).value_or(SocketType::float_value));
    draw_link(draw, view_, curves_[c], color, target ? 4.f : 2.5f);
  }

  // Widgets at the canvas zoom, with padding and spacing scaled alike, so a widget's
  // frame and its row are NodeMetrics' 16 and 18 units at any zoom.
  const float z = view_.zoom;
  const NodeMetrics metrics;
  const float frame_pad = (metrics.frame - metrics.text) * 0.5f;
  ImGui::SetWindowFontScale(z * metrics.text / ImGui::GetFont()->FontSize);
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(4.f * z, frame_pad * z));
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(4.f * z, (metrics.row - metrics.frame) * z));
  ImGui::PushStyleVar(ImGuiStyleVar_ItemInnerSpacing, ImVec2(4.f * z, 4.f * z));
  ImGui::PushStyleVar(ImGuiStyleVar_IndentSpacing, 12.f * z);
  std::optional<NodeDrawResult> edited;
  std::string edited_id;
  KeyTargets keys;
  keys.document = &state.document.scene();
  keys.report = state.report_params;
  const NodeWidgetContext context{&state.document.scene(), &keys, Selection{ItemKind::material, material_}};
  for (size_t i = 0; i < boxes.size(); ++i) {
    const GraphNodeDesc& node = *order[i];
    std::vector<std::string_view> linked;
    for (const GraphLinkDesc& l : graph_.links)
      if (l.to == node.id) linked.push_back(l.input);
    const bool selected = std::find(selected_.begin(), selected_.end(), node.id) != selected_.end();
    NodeDrawResult r = draw_node(draw, view_, node, boxes[i], linked, selected, z >= 0.5f, context);
    if (z >= 0.5f) row_heights_[node.id] = r.row_heights;
    if (r.changed) edited = std::move(r), edited_id = node.id;
  }
  ImGui::PopStyleVar(4);
  ImGui::SetWindowFontScale(1.f);
  draw_swatch(state, boxes);
  check(graph_);
  draw_problem_outlines(boxes);
  if (edited) {
    GraphDesc g = graph_;
    for (GraphNodeDesc& n : g.nodes)
      if (n.id == edited_id) n.data = edited->edited;
    commit(state, std::move(g), "Edit " + edited_id + "." + edited->changed_param,
           "graph-param:" + material_name_ + ":" + edited_id + ":" + edited->changed_param);
  }

  draw_drag_feedback(boxes);
  handle_mouse(state, boxes);
  handle_keys(state);
  apply_key_actions(state, keys);
  add_menu(state);
  layout_ = layout_text(boxes, graph_, view_, canvas_size_);
  focused_ = ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows);
  ImGui::EndChild();
}

std::optional<std::string> NodeEditorPanel::drag_target_refusal(const std::vector<NodeBox>& boxes,
                                                                PinHit* target) const {
  const Vec2 mouse = to_canvas(view_, Vec2(ImGui::GetIO().MousePos.x, ImGui::GetIO().MousePos.y));
  *target = pin_at(boxes, mouse, kPickPixels / view_.zoom);
  if (!*target) return std::nullopt;
  const NodeBox& box = boxes[size_t(target->node)];
  const PinBox& pin = box.pins[size_t(target->pin)];
  if (pin.output == link_from_output_)
    return link_from_output_ ? "an output links to an input: drop the link on an input pin"
                             : "an input takes a link from an output: drop the link on an output pin";
  GraphDesc g = graph_;
  if (picked_link_) disconnect(g, picked_link_->to, picked_link_->input);
  return link_from_output_ ? check_link(g, link_node_, link_socket_, box.id, pin.name)
                           : check_link(g, box.id, pin.name, link_node_, link_socket_);
}

void NodeEditorPanel::draw_drag_feedback(const std::vector<NodeBox>& boxes) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  if (drag_ == Drag::box && dragged_) {
    draw->AddRectFilled(ImVec2(press_.x, press_.y), mouse, IM_COL32(90, 140, 230, 40));
    draw->AddRect(ImVec2(press_.x, press_.y), mouse, IM_COL32(90, 140, 230, 200));
  }
  if (drag_ != Drag::link) return;
  const PinBox* fixed = find_pin(boxes, link_node_, link_socket_, link_from_output_);
  if (!fixed) return;
  PinHit target;
  const std::optional<std::string> refusal = drag_target_refusal(boxes, &target);
  // The free end snaps to a pin that would take the link.
  Vec2 end = to_canvas(view_, Vec2(mouse.x, mouse.y));
  if (target && !refusal) end = boxes[size_t(target.node)].pins[size_t(target.pin)].center;
  const Bezier curve = link_from_output_ ? link_bezier(fixed->center, end) : link_bezier(end, fixed->center);
  draw_link(draw, view_, curve, refusal ? IM_COL32(235, 60, 60, 255) : socket_color(link_type_), 3.f);
  if (refusal) ImGui::SetTooltip("%s", refusal->c_str());
}

void NodeEditorPanel::handle_mouse(EditorState& state, const std::vector<NodeBox>& boxes) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetCursorScreenPos(ImVec2(view_.origin.x, view_.origin.y));
  // Submitted after the nodes' widgets, so a widget under the mouse takes it first.
  ImGui::InvisibleButton("canvas_input", ImVec2(canvas_size_.x, canvas_size_.y),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  const Vec2 mouse(io.MousePos.x, io.MousePos.y);
  const Vec2 at = to_canvas(view_, mouse);
  const float pick = kPickPixels / view_.zoom;

  if (ImGui::IsWindowHovered() && io.MouseWheel != 0.f) {
    view_ = zoom_about(view_, mouse, view_.zoom * std::pow(1.15f, io.MouseWheel));
    view_edited_ = true, view_edit_time_ = std::chrono::steady_clock::now();
  }

  if (ImGui::IsItemActivated()) {
    press_ = mouse;
    dragged_ = false;
    additive_ = io.KeyShift;
    insert_link_ = -1;
    picked_link_.reset();
    right_press_ = ImGui::IsMouseClicked(ImGuiMouseButton_Right);
    drag_ = Drag::none;
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Middle) ||
        (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && io.KeyAlt)) {
      drag_ = Drag::pan;
    } else if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
      if (const PinHit pin = pin_at(boxes, at, pick)) {
        const NodeBox& box = boxes[size_t(pin.node)];
        const PinBox& p = box.pins[size_t(pin.pin)];
        drag_ = Drag::link;
        link_from_output_ = p.output;
        link_node_ = box.id, link_socket_ = std::string(p.name);
        link_type_ = p.type;
        if (const GraphLinkDesc* l = p.output ? nullptr : link_into(graph_, box.id, p.name)) {
          // Picking up a linked input's end: the link now hangs from its output.
          picked_link_ = *l;
          link_from_output_ = true;
          link_node_ = l->from, link_socket_ = l->output;
          const GraphNodeDesc* from = find_node(graph_, l->from);  // null in a broken graph
          link_type_ = from ? output_type(from->data, l->output).value_or(p.type) : p.type;
        }
      } else if (const int n = node_at(boxes, at); n >= 0) {
        drag_ = Drag::move;
        press_node_ = boxes[size_t(n)].id;
        selected_ = press_select(selected_, press_node_, additive_);
      } else {
        drag_ = Drag::box;
      }
    }
  }

  if (ImGui::IsItemActive()) {
    if (!dragged_ && glm::length(mouse - press_) > kDragThreshold) dragged_ = true;
    const Vec2 delta = Vec2(io.MouseDelta.x, io.MouseDelta.y) / view_.zoom;
    if (drag_ == Drag::pan && (delta.x != 0.f || delta.y != 0.f)) {
      view_.pan += delta;
      view_edited_ = true, view_edit_time_ = std::chrono::steady_clock::now();
    } else if (drag_ == Drag::move && dragged_ && !selected_.empty()) {
      if (delta.x != 0.f || delta.y != 0.f) {
        GraphDesc g = graph_;
        move_nodes(g, selected_, delta.x, delta.y);
        commit(state, std::move(g), "Move nodes", "graph-move:" + material_name_);
      }
      // One node without links, dropped on a link, goes in between.
      insert_link_ = -1;
      const std::string& id = selected_.front();
      const bool unlinked = std::none_of(graph_.links.begin(), graph_.links.end(),
                                         [&](const GraphLinkDesc& l) { return l.from == id || l.to == id; });
      if (selected_.size() == 1 && unlinked) {
        if (const int c = link_at(curves_, at, pick); c >= 0) insert_link_ = curve_link_[size_t(c)];
      }
    }
  }

  if (ImGui::IsItemDeactivated()) {
    switch (drag_) {
      case Drag::move:
        if (!dragged_) {
          selected_ = click_select(selected_, press_node_, additive_);
        } else if (insert_link_ >= 0) {
          GraphDesc g = graph_;
          if (const auto refused = insert_on_link(g, size_t(insert_link_), selected_.front())) {
            state.log.warning("insert node: " + *refused);
          } else {
            commit(state, std::move(g), "Move nodes", "graph-move:" + material_name_);
          }
        }
        state.document.end_merge();  // one drag, one undo step
        break;
      case Drag::box:
        if (dragged_) {
          std::vector<std::string> ids;
          for (int n : nodes_in_rect(boxes, rect_between(to_canvas(view_, press_), at)))
            ids.push_back(boxes[size_t(n)].id);
          selected_ = box_select(selected_, ids, additive_);
        } else if (!additive_) {
          selected_.clear();
        }
        break;
      case Drag::link:
        finish_link(state, boxes);
        break;
      case Drag::pan:
        commit_view(state);
        break;
      case Drag::none:
        if (right_press_ && !dragged_) open_add_menu_ = true, add_at_ = at;
        break;
    }
    drag_ = Drag::none;
    picked_link_.reset();
    insert_link_ = -1;
  }
}

void NodeEditorPanel::finish_link(EditorState& state, const std::vector<NodeBox>& boxes) {
  PinHit target;
  const std::optional<std::string> refusal = drag_target_refusal(boxes, &target);
  if (!target) {
    // A picked-up link dropped on empty canvas is removed; a new one opens the add
    // menu there, and the node chosen takes the link on its first socket that fits.
    if (picked_link_) {
      GraphDesc g = graph_;
      disconnect(g, picked_link_->to, picked_link_->input);
      commit(state, std::move(g), "Remove link");
    } else {
      const ImVec2 mouse = ImGui::GetIO().MousePos;
      pending_link_ = PendingLink{link_from_output_, link_node_, link_socket_};
      open_add_menu_ = true;
      add_at_ = to_canvas(view_, Vec2(mouse.x, mouse.y));
    }
    return;
  }
  if (refusal) return;  // shown while dragging; the graph stays as it was
  const NodeBox& box = boxes[size_t(target.node)];
  const std::string pin(box.pins[size_t(target.pin)].name);
  if (picked_link_ && picked_link_->to == box.id && picked_link_->input == pin) return;  // put back
  GraphDesc g = graph_;
  if (picked_link_) disconnect(g, picked_link_->to, picked_link_->input);
  const auto refused = link_from_output_ ? connect(g, link_node_, link_socket_, box.id, pin)
                                         : connect(g, box.id, pin, link_node_, link_socket_);
  if (refused) {
    state.log.warning("link: " + *refused);
  } else if (g != graph_) {
    commit(state, std::move(g),
           "Link " + (link_from_output_ ? link_node_ + " -> " + box.id : box.id + " -> " + link_node_));
  }
}

void NodeEditorPanel::handle_keys(EditorState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) || io.WantTextInput) return;
  const Vec2 mouse(io.MousePos.x, io.MousePos.y);
  const bool over_canvas = CanvasRect{view_.origin, view_.origin + canvas_size_}.contains(mouse);
  const Vec2 at = to_canvas(view_, over_canvas ? mouse : view_.origin + canvas_size_ * 0.4f);
  // ImGui 1.86 indexes keys by the GLFW key code, which for letters is the ASCII capital.
  const bool plain = !io.KeyCtrl && !io.KeyAlt && !io.KeySuper;
  if (plain && io.KeyShift && ImGui::IsKeyPressed('A', false)) open_add_menu_ = true, add_at_ = at;
  if (plain && !io.KeyShift &&
      (ImGui::IsKeyPressed('X', false) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Delete), false))) {
    GraphDesc g = graph_;
    if (remove_nodes(g, selected_) > 0) commit(state, std::move(g), "Delete nodes");
  }
  if (plain && io.KeyShift && ImGui::IsKeyPressed('D', false) && !selected_.empty()) {
    GraphDesc g = graph_;
    std::vector<std::string> copies = duplicate_nodes(g, selected_, 30.f, 30.f);
    if (!copies.empty()) commit(state, std::move(g), "Duplicate nodes"), selected_ = std::move(copies);
  }
  if (io.KeyCtrl && ImGui::IsKeyPressed('C', false) && !selected_.empty())
    ImGui::SetClipboardText(copy_nodes(graph_, selected_).c_str());
  if (io.KeyCtrl && ImGui::IsKeyPressed('V', false)) {
    const char* text = ImGui::GetClipboardText();
    GraphDesc g = graph_;
    std::string error;
    std::vector<std::string> pasted = paste_nodes(g, text ? text : "", at.x, at.y, &error);
    if (!pasted.empty()) {
      commit(state, std::move(g), "Paste nodes");
      selected_ = std::move(pasted);
    } else if (!error.empty()) {
      state.log.warning("paste: " + error);
    }
  }
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Home), false)) want_frame_ = frame_is_edit_ = true;
}

// Links a node just added to the end of the link that was dropped where it stands:
// its first input (or, for a link hanging from an input, its first output) that fits.
void NodeEditorPanel::link_new_node(GraphDesc& g, const std::string& id, const PendingLink& link) {
  const GraphNodeDesc* node = nullptr;
  for (const GraphNodeDesc& n : g.nodes)
    if (n.id == id) node = &n;
  if (!node) return;
  if (link.from_output) {
    for (const SocketInfo& in : node_inputs(node->data))
      if (!check_link(g, link.node, link.socket, id, in.name)) {
        connect(g, link.node, link.socket, id, in.name);
        return;
      }
  } else {
    for (const SocketDecl& out : node_outputs(node->data))
      if (!check_link(g, id, out.name, link.node, link.socket)) {
        connect(g, id, out.name, link.node, link.socket);
        return;
      }
  }
}

void NodeEditorPanel::add_menu(EditorState& state) {
  if (open_add_menu_) {
    ImGui::OpenPopup("add_node");
    add_filter_.clear();
    open_add_menu_ = false;
  }
  if (!ImGui::BeginPopup("add_node")) {
    pending_link_.reset();  // the menu closed without a choice
    return;
  }
  const bool has_output = std::any_of(graph_.nodes.begin(), graph_.nodes.end(), [](const GraphNodeDesc& n) {
    return std::holds_alternative<OutputNode>(n.data);
  });
  if (const std::string chosen = node_add_menu(&add_filter_, has_output); !chosen.empty()) {
    GraphDesc g = graph_;
    const std::string id = add_node(g, chosen, add_at_.x, add_at_.y);
    if (!id.empty()) {
      if (pending_link_) link_new_node(g, id, *pending_link_);
      commit(state, std::move(g), "Add " + chosen + " node");
      selected_ = {id};
    }
    pending_link_.reset();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace inkray
