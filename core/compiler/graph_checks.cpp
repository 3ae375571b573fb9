// Graph checks: ids, the output node, links (nodes, sockets, types, doubled
// inputs), and cycles by Kahn's algorithm over the whole graph (no recursion).
#include "core/compiler/graph_checks.h"

#include "core/document/json_syntax.h"

#include <algorithm>
#include <deque>
#include <map>

namespace inkray {

std::string node_label(const GraphDesc& g, size_t i) {
  return element_path("nodes", i) + " \"" + g.nodes[i].id + "\" (" +
         std::string(node_type_name(g.nodes[i].data)) + ")";
}

namespace {

std::string socket_list(std::span<const SocketDecl> sockets) {
  std::string out;
  for (const SocketDecl& s : sockets) out += (out.empty() ? "" : ", ") + std::string(s.name);
  return out.empty() ? "none" : out;
}
std::string socket_list(const std::vector<SocketInfo>& sockets) {
  std::string out;
  for (const SocketInfo& s : sockets) out += (out.empty() ? "" : ", ") + std::string(s.name);
  return out.empty() ? "none" : out;
}
std::string type_name(SocketType t) { return std::string(kSocketTypeNames[size_t(t)]); }

}  // namespace

bool check_graph(const GraphDesc& g, CheckedGraph& c, std::vector<std::string>& errors) {
  const size_t before = errors.size();
  std::map<std::string, size_t> by_id;
  std::vector<size_t> outputs;
  c.inputs.resize(g.nodes.size());
  c.incoming.resize(g.nodes.size());
  for (size_t i = 0; i < g.nodes.size(); ++i) {
    c.inputs[i] = node_inputs(g.nodes[i].data);
    c.incoming[i].resize(c.inputs[i].size());
    if (std::holds_alternative<OutputNode>(g.nodes[i].data)) outputs.push_back(i);
    if (g.nodes[i].id.empty()) continue;  // the reader reported it
    const auto [it, fresh] = by_id.emplace(g.nodes[i].id, i);
    if (!fresh)
      errors.push_back(element_path("nodes", i) + ".id: duplicate node id \"" + g.nodes[i].id + "\" (also " +
                       element_path("nodes", it->second) + ")");
  }
  if (outputs.empty())
    errors.push_back("nodes: the graph has no output node (add {\"id\": ..., \"type\": \"output\"})");
  for (size_t k = 1; k < outputs.size(); ++k)
    errors.push_back(node_label(g, outputs[k]) + ": a second output node (the first is " +
                     node_label(g, outputs[0]) + ")");
  if (!outputs.empty()) c.output_node = outputs[0];

  std::string ids;
  for (size_t i = 0; i < g.nodes.size() && i < 10; ++i) ids += (i ? ", " : "") + g.nodes[i].id;
  if (g.nodes.size() > 10) ids += ", ...";
  std::vector<std::vector<size_t>> users(g.nodes.size());
  std::vector<size_t> pending(g.nodes.size(), 0);
  for (size_t k = 0; k < g.links.size(); ++k) {
    const GraphLinkDesc& l = g.links[k];
    const std::string at = element_path("links", k);
    const auto from = by_id.find(l.from), to = by_id.find(l.to);
    if (from == by_id.end()) errors.push_back(at + ".from: no node \"" + l.from + "\" (nodes: " + ids + ")");
    if (to == by_id.end()) errors.push_back(at + ".to: no node \"" + l.to + "\" (nodes: " + ids + ")");
    if (from == by_id.end() || to == by_id.end()) continue;
    const auto outs = node_outputs(g.nodes[from->second].data);
    const auto out_it =
        std::find_if(outs.begin(), outs.end(), [&](const SocketDecl& s) { return s.name == l.output; });
    const auto& ins = c.inputs[to->second];
    const auto in_it =
        std::find_if(ins.begin(), ins.end(), [&](const SocketInfo& s) { return s.name == l.input; });
    if (out_it == outs.end())
      errors.push_back(at + ".output: " + node_label(g, from->second) + " has no output \"" + l.output +
                       "\" (outputs: " + socket_list(outs) + ")");
    if (in_it == ins.end())
      errors.push_back(at + ".input: " + node_label(g, to->second) + " has no input \"" + l.input +
                       "\" (inputs: " + socket_list(ins) + ")");
    if (out_it == outs.end() || in_it == ins.end()) continue;
    if (!socket_converts(out_it->type, in_it->type)) {
      errors.push_back(at + ": cannot link " + type_name(out_it->type) + " output \"" + l.output +
                       "\" of \"" + l.from + "\" to " + type_name(in_it->type) + " input \"" + l.input +
                       "\" of \"" + l.to + "\"");
      continue;
    }
    const size_t input = size_t(in_it - ins.begin());
    auto& slot = c.incoming[to->second][input];
    if (slot) {
      errors.push_back(at + ".input: input \"" + l.input + "\" of \"" + l.to +
                       "\" is already linked from \"" + g.nodes[slot->from].id + "\"");
      continue;
    }
    slot = GraphEdge{from->second, size_t(out_it - outs.begin()), to->second, input};
    users[from->second].push_back(to->second);
    ++pending[to->second];
  }
  // Kahn's algorithm over the whole graph: nodes never released sit on or behind a cycle.
  std::deque<size_t> ready;
  for (size_t i = 0; i < g.nodes.size(); ++i)
    if (pending[i] == 0) ready.push_back(i);
  std::vector<size_t> order;
  std::vector<size_t> left = pending;
  while (!ready.empty()) {
    const size_t i = ready.front();
    ready.pop_front();
    order.push_back(i);
    for (size_t u : users[i])
      if (--left[u] == 0) ready.push_back(u);
  }
  if (order.size() < g.nodes.size()) {
    std::string cycle;
    for (size_t i = 0; i < g.nodes.size(); ++i)
      if (left[i] > 0) cycle += (cycle.empty() ? "" : ", ") + g.nodes[i].id;
    errors.push_back("links: these nodes form or follow a cycle: " + cycle);
  }
  if (errors.size() > before) return false;

  // Only what reaches the output is lowered.
  std::vector<bool> reach(g.nodes.size(), false);
  std::vector<size_t> stack = {c.output_node};
  reach[c.output_node] = true;
  while (!stack.empty()) {
    const size_t i = stack.back();
    stack.pop_back();
    for (const auto& e : c.incoming[i])
      if (e && !reach[e->from]) reach[e->from] = true, stack.push_back(e->from);
  }
  for (size_t i : order)
    if (reach[i]) c.order.push_back(i);
  return true;
}

}  // namespace inkray
