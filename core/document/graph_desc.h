// A material graph as the document holds it (docs/architecture.md, "Material
// graphs"): nodes with stable ids, links from an output socket to an input socket,
// and an editor block of node positions that never triggers a recompile.
// Sockets are listed generically (node_inputs, node_outputs) from each node
// type's parameter list and declarations in graph_nodes.h.
#pragma once

#include "core/document/graph_nodes.h"
#include "core/document/tagged_variant.h"

#include <string>
#include <string_view>
#include <vector>

namespace inkray {

struct GraphNodeDesc {
  std::string id;  // unique within the graph, kept across edits
  NodeVariant data = OutputNode{};
  bool operator==(const GraphNodeDesc&) const = default;
};

struct GraphLinkDesc {
  std::string from;    // node id
  std::string output;  // socket name on that node
  std::string to;      // node id
  std::string input;   // socket name on that node
  bool operator==(const GraphLinkDesc&) const = default;
};
template <class V> void visit_params(GraphLinkDesc& d, V& v) {
  v(required(text("from", "Id of the node the link leaves")), d.from);
  v(required(text("output", "Output socket it leaves from")), d.output);
  v(required(text("to", "Id of the node the link enters")), d.to);
  v(required(text("input", "Input socket it enters")), d.input);
}

struct NodePlacementDesc {
  std::string node;  // node id
  float x = 0.f, y = 0.f;
  bool operator==(const NodePlacementDesc&) const = default;
};
template <class V> void visit_params(NodePlacementDesc& d, V& v) {
  v(required(text("node", "Node id")), d.node);
  v(number("x", -1e7, 1e7, "Canvas x of the node's top-left corner"), d.x);
  v(number("y", -1e7, 1e7, "Canvas y of the node's top-left corner"), d.y);
}

// The canvas: where nodes sit and how it is viewed. Layout only.
struct GraphEditorDesc {
  std::vector<NodePlacementDesc> nodes;
  float pan_x = 0.f, pan_y = 0.f;
  float zoom = 1.f;
  bool operator==(const GraphEditorDesc&) const = default;
};
template <class V> void visit_params(GraphEditorDesc& d, V& v) {
  v(at(Stage::layout, list("nodes", "Node positions on the canvas")), d.nodes);
  v(at(Stage::layout, number("pan_x", -1e7, 1e7, "Canvas scroll, x")), d.pan_x);
  v(at(Stage::layout, number("pan_y", -1e7, 1e7, "Canvas scroll, y")), d.pan_y);
  v(at(Stage::layout, number("zoom", 0.1, 10, "Canvas zoom").log_slider(0.1, 10)), d.zoom);
}

struct GraphDesc {
  static constexpr std::string_view type_name = "graph";
  std::vector<GraphNodeDesc> nodes;
  std::vector<GraphLinkDesc> links;
  GraphEditorDesc editor;
  bool operator==(const GraphDesc&) const = default;
};
inline constexpr Param kGraphNodes{"nodes", "The nodes: {\"id\": ..., \"type\": ..., inputs and settings}",
                                   ParamKind::nodes};
template <class V> void visit_params(GraphDesc& d, V& v) {
  v(kGraphNodes, d.nodes);
  v(list("links", "Links from an output socket to an input socket"), d.links);
  v(at(Stage::layout, group("editor", "Node positions and the canvas view")), d.editor);
}

// ---------------------------------------------------------------- sockets
struct SocketInfo {
  std::string_view name;
  SocketType type = SocketType::float_value;
  std::string_view doc;
  Implicit implicit = Implicit::none;
  bool has_value = false;  // a parameter holds its value when unlinked (else a link-only input)
  Param param;             // the parameter, when has_value
};

namespace graph_detail {
template <class T>
concept HasLinkInputs = requires { T::link_inputs.size(); };

struct InputCollector {
  std::vector<SocketInfo>* out;
  template <class F>
  void operator()(const Param& p, F&) {
    if (const auto type = socket_type_of(p.kind)) out->push_back({p.name, *type, p.doc, Implicit::none, true, p});
  }
};
}  // namespace graph_detail

// Input sockets of a node type: the valued parameters in list order, then the link-only inputs.
template <class T>
std::vector<SocketInfo> node_inputs_of() {
  std::vector<SocketInfo> inputs;
  T probe{};
  graph_detail::InputCollector collector{&inputs};
  visit_params(probe, collector);
  if constexpr (graph_detail::HasLinkInputs<T>) {
    for (const SocketDecl& s : T::link_inputs) inputs.push_back({s.name, s.type, s.doc, s.implicit, false, {}});
  }
  return inputs;
}

inline std::vector<SocketInfo> node_inputs(const NodeVariant& node) {
  return std::visit([]<class T>(const T&) { return node_inputs_of<T>(); }, node);
}
inline std::span<const SocketDecl> node_outputs(const NodeVariant& node) {
  return std::visit([]<class T>(const T&) { return std::span<const SocketDecl>(T::outputs); }, node);
}
inline std::string_view node_type_name(const NodeVariant& node) { return type_name_of(node); }

}  // namespace inkray
