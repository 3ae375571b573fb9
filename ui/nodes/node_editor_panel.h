// The node editor: the graph of the selected material (or of the selected object's)
// on a canvas. Nodes are added from a searchable menu, linked by dragging between
// pins, moved, box-selected, copied and pasted; every change is one document edit
// (undoable, recompiling that material only), and node positions, pan and zoom are
// written to the graph's editor block, which never recompiles. Geometry, hit testing
// and selection rules are node_canvas.h's, drawing node_drawing.h's, the graph
// operations core/document/graph_edit.h's.
#pragma once

#include "ui/model/editor_state.h"
#include "ui/nodes/node_canvas.h"

#include <chrono>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace inkray {

// The material the node editor shows: the selected material, or the selected object's; -1 for none.
int node_editor_material(const SceneDesc& scene, const Selection& selection);

class NodeEditorPanel {
 public:
  // Draws into the current window (the app shell places it, without a title bar: the
  // panel's first row is its title, with a close button that clears *open).
  void draw(EditorState& state, bool* open);
  // The canvas had the keyboard last frame: the app leaves Delete and Ctrl+D to it.
  bool focused() const { return focused_; }
  // Node boxes and link ends as drawn last frame (node_canvas.h, layout_text).
  const std::string& layout() const { return layout_; }

 private:
  enum class Drag { none, pan, move, box, link };

  void commit(EditorState& state, GraphDesc graph, const std::string& label,
              const std::string& merge_key = {});
  void commit_view(EditorState& state);
  void header(EditorState& state, bool* open);
  void draw_canvas(EditorState& state);
  void draw_swatch(EditorState& state, const std::vector<NodeBox>& boxes);
  void check(const GraphDesc& graph);
  void draw_problem_outlines(const std::vector<NodeBox>& boxes);
  void handle_mouse(EditorState& state, const std::vector<NodeBox>& boxes);
  void finish_link(EditorState& state, const std::vector<NodeBox>& boxes);
  void handle_keys(EditorState& state);
  void add_menu(EditorState& state);
  // A new link dropped on empty canvas, waiting for the add menu's node.
  struct PendingLink {
    bool from_output = true;  // its fixed end is an output (else an input)
    std::string node, socket;
  };
  static void link_new_node(GraphDesc& g, const std::string& id, const PendingLink& link);
  void draw_drag_feedback(const std::vector<NodeBox>& boxes);
  // Why the pin under the mouse cannot take the dragged link (nullopt: it can, or no pin is there).
  std::optional<std::string> drag_target_refusal(const std::vector<NodeBox>& boxes, PinHit* target) const;

  // What is shown: refreshed at the start of each frame.
  int material_ = -1;
  std::string material_name_;
  GraphDesc graph_;  // the material as a graph (a plain material converted, unplaced nodes placed)
  bool is_graph_ = false;
  CanvasView view_;
  std::optional<CanvasView> doc_view_;  // the graph's stored view when last seen (none for a plain material)
  bool view_edited_ = false;            // view_ is ahead of the document (a pan or zoom in progress)
  std::chrono::steady_clock::time_point view_edit_time_;
  Vec2 canvas_size_{0.f};

  std::vector<std::string> selected_;
  std::map<std::string, std::vector<float>> row_heights_;  // drawn row heights per node id
  std::vector<Bezier> curves_;                             // this frame's links, canvas units
  std::vector<int> curve_link_;                            // the graph link each curve draws
  std::optional<GraphDesc> checked_graph_;                 // the graph problems_ were found in
  std::vector<std::string> problems_;                      // graph_checks' messages
  std::set<std::string> problem_nodes_;                    // ids of the nodes they name

  Drag drag_ = Drag::none;
  Vec2 press_{0.f};  // screen
  bool dragged_ = false;
  bool additive_ = false;
  bool right_press_ = false;
  std::string press_node_;
  // A link being dragged: its fixed end is an output (the usual case) or an input.
  bool link_from_output_ = true;
  std::string link_node_, link_socket_;
  SocketType link_type_ = SocketType::float_value;
  std::optional<GraphLinkDesc> picked_link_;  // an existing link whose end was picked up
  int insert_link_ = -1;                      // the link a dragged node would be inserted on

  bool open_add_menu_ = false;
  std::optional<PendingLink> pending_link_;
  Vec2 add_at_{0.f};  // canvas
  std::string add_filter_;
  bool want_frame_ = false;
  bool frame_is_edit_ = false;  // the framing was asked for (Home), so it is written like a pan
  bool focused_ = false;
  std::string layout_;
};

}  // namespace inkray
