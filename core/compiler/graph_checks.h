// The checks of a material graph before lowering (docs/architecture.md, "Material
// graphs"): every problem of the whole graph at once, each naming its JSON path
// inside the material and the node. What passes comes back indexed for lowering.
#pragma once

#include "core/document/graph_desc.h"

#include <optional>
#include <string>
#include <vector>

namespace inkray {

// A link that passed the checks, by node index and socket index.
struct GraphEdge {
  size_t from, output, to, input;
};

struct CheckedGraph {
  size_t output_node = 0;
  std::vector<std::vector<SocketInfo>> inputs;                  // per node
  std::vector<std::vector<std::optional<GraphEdge>>> incoming;  // per node, per input socket
  std::vector<size_t> order;                                    // nodes that reach the output, sources first
};

// "nodes[2] \"ramp\" (color_ramp)": how messages name a node.
std::string node_label(const GraphDesc& g, size_t node);

// False with the problems appended to `errors`.
bool check_graph(const GraphDesc& g, CheckedGraph& checked, std::vector<std::string>& errors);

}  // namespace inkray
