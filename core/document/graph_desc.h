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
template <>
struct ParamTable<GraphLinkDesc> {
  static constexpr auto rows =
      std::tuple{row(&GraphLinkDesc::from, required(text("from", "Id of the node the link leaves"))),
                 row(&GraphLinkDesc::output, required(text("output", "Output socket it leaves from"))),
                 row(&GraphLinkDesc::to, required(text("to", "Id of the node the link enters"))),
                 row(&GraphLinkDesc::input, required(text("input", "Input socket it enters")))};
};

struct NodePlacementDesc {
  std::string node;  // node id
  float x = 0.f, y = 0.f;
  bool operator==(const NodePlacementDesc&) const = default;
};
template <>
struct ParamTable<NodePlacementDesc> {
  static constexpr auto rows = std::tuple{
      row(&NodePlacementDesc::node, required(text("node", "Node id"))),
      row(&NodePlacementDesc::x, number("x", -1e7, 1e7, "Canvas x of the node's top-left corner")),
      row(&NodePlacementDesc::y, number("y", -1e7, 1e7, "Canvas y of the node's top-left corner"))};
};

// The canvas: where nodes sit and how it is viewed. Layout only.
struct GraphEditorDesc {
  std::vector<NodePlacementDesc> nodes;
  float pan_x = 0.f, pan_y = 0.f;
  float zoom = 1.f;
  bool operator==(const GraphEditorDesc&) const = default;
};
template <>
struct ParamTable<GraphEditorDesc> {
  static constexpr auto rows = std::tuple{
      row(&GraphEditorDesc::nodes, at(Stage::layout, list("nodes", "Node positions on the canvas"))),
      row(&GraphEditorDesc::pan_x, at(Stage::layout, number("pan_x", -1e7, 1e7, "Canvas scroll, x"))),
      row(&GraphEditorDesc::pan_y, at(Stage::layout, number("pan_y", -1e7, 1e7, "Canvas scroll, y"))),
      row(&GraphEditorDesc::zoom,
          at(Stage::layout, number("zoom", 0.1, 10, "Canvas zoom").log_slider(0.1, 10)))};
};

struct GraphDesc {
  static constexpr std::string_view type_name = "graph";
  std::vector<GraphNodeDesc> nodes;
  std::vector<GraphLinkDesc> links;
  GraphEditorDesc editor{};  // {}: designated initialisers may omit it
  bool operator==(const GraphDesc&) const = default;
};
inline constexpr Param kGraphNodes{"nodes", "The nodes: {\"id\": ..., \"type\": ..., inputs and settings}",
                                   ParamKind::nodes};
template <>
struct ParamTable<GraphDesc> {
  static constexpr auto rows = std::tuple{
      row(&GraphDesc::nodes, kGraphNodes),
      row(&GraphDesc::links, list("links", "Links from an output socket to an input socket")),
      row(&GraphDesc::editor, at(Stage::layout, group("editor", "Node positions and the canvas view")))};
};

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
concept HasLinkInputs = requires {
  T::link_inputs.size();
};

struct InputCollector {
  std::vector<SocketInfo>* out;
  template <class F>
  void operator()(const Param& p, F&) {
    if (const auto type = socket_type_of(p.kind))
      out->push_back({p.name, *type, p.doc, Implicit::none, true, p});
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
    for (const SocketDecl& s : T::link_inputs)
      inputs.push_back({s.name, s.type, s.doc, s.implicit, false, {}});
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
