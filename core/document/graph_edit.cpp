// Graph edits for the node editor. Every structural edit that adds a link goes through
// check_link, so the editor's edits keep a graph within what compile_graph accepts.
#include "core/document/graph_edit.h"

#include "core/document/json_io.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <type_traits>

namespace inkray {
namespace {

template <class T>
constexpr NodeCategory category_of() {
  if constexpr (std::is_same_v<T, OutputNode>) {
    return NodeCategory::output;
  } else if constexpr (std::is_same_v<T, ValueNode> || std::is_same_v<T, RgbNode> ||
                       std::is_same_v<T, GeometryNode> || std::is_same_v<T, LightInputNode> ||
                       std::is_same_v<T, FresnelNode> || std::is_same_v<T, LayerWeightNode>) {
    return NodeCategory::input;
  } else if constexpr (std::is_same_v<T, ImageTextureNode> || std::is_same_v<T, CheckerNode> ||
                       std::is_same_v<T, NoiseNode> || std::is_same_v<T, VoronoiNode>) {
    return NodeCategory::texture;
  } else if constexpr (T::outputs.size() == 1 && T::outputs[0].type == SocketType::closure) {
    return NodeCategory::closure;  // the plain materials, mix_closure and add_closure
  } else {
    return NodeCategory::converter;
  }
}

std::string in_quotes_(std::string_view s) { return "\"" + std::string(s) + "\""; }

std::string describe_node(const GraphNodeDesc& n) {
  return in_quotes_(n.id) + " (" + std::string(node_type_name(n.data)) + ")";
}

std::string type_word(SocketType t) { return std::string(kSocketTypeNames[size_t(t)]); }

bool is_output(const GraphNodeDesc& n) { return std::holds_alternative<OutputNode>(n.data); }

bool has_output_node(const GraphDesc& g) { return std::any_of(g.nodes.begin(), g.nodes.end(), is_output); }

// Whether `target` is downstream of `start` (or is it): a link start -> target would close a cycle.
bool reaches(const GraphDesc& g, std::string_view start, std::string_view target) {
  std::set<std::string_view> seen = {start};
  std::vector<std::string_view> stack = {start};
  while (!stack.empty()) {
    const std::string_view at = stack.back();
    stack.pop_back();
    if (at == target) return true;
    for (const GraphLinkDesc& l : g.links) {
      if (l.from == at && seen.insert(l.to).second) stack.push_back(l.to);
    }
  }
  return false;
}

struct RowCounter {
  size_t* rows;
  template <class F>
  void operator()(const Param&, const F&) {
    ++*rows;
  }
};

// A rough height for laying out nodes that have no position: title, one row per socket or setting.
float estimated_height(const NodeVariant& node) {
  size_t rows = node_outputs(node).size();
  std::visit(
      [&]<class T>(const T& d) {
        RowCounter counter{&rows};
        visit_params(d, counter);
        if constexpr (graph_detail::HasLinkInputs<T>) rows += T::link_inputs.size();
      },
      node);
  return 30.f + 22.f * float(rows);
}

std::vector<std::string> ids_present(const GraphDesc& g, const std::vector<std::string>& ids) {
  std::vector<std::string> out;
  for (const GraphNodeDesc& n : g.nodes)
    if (std::find(ids.begin(), ids.end(), n.id) != ids.end()) out.push_back(n.id);
  return out;
}

Vec2 position_or_origin(const GraphDesc& g, std::string_view id) {
  return node_position(g, id).value_or(Vec2(0.f));
}

// The clipboard is a graph material's JSON; the scene reader checks it like any file.
constexpr std::string_view kClipboardName = "clipboard";

std::optional<GraphDesc> read_fragment(const std::string& text, std::string* error) {
  const auto fail = [&](std::string message) -> std::optional<GraphDesc> {
    if (error) *error = std::move(message);
    return std::nullopt;
  };
  nlohmann::json material = nlohmann::json::parse(text, nullptr, false);
  if (material.is_discarded() || !material.is_object() || material.value("type", "") != GraphDesc::type_name)
    return fail("the clipboard holds no nodes (expected a graph material's JSON)");
  material["name"] = kClipboardName;
  const nlohmann::json scene = {{"format", kSceneFormatName},
                                {"version", kSceneFormatVersion},
                                {"materials", nlohmann::json::array({material})}};
  SceneLoadResult loaded = parse_scene(scene.dump(), {}, kClipboardName, ReadFor::editing);
  if (!loaded.scene) {
    std::string all;
    for (std::string line : loaded.errors) {
      // "clipboard: materials[0].nodes[1]..." names a place the user never saw.
      const std::string wrapper = "materials[0].";
      if (const size_t at = line.find(wrapper); at != std::string::npos) line.erase(at, wrapper.size());
      all += (all.empty() ? "" : "\n") + line;
    }
    return fail(all);
  }
  return std::get<GraphDesc>(loaded.scene->materials.at(0).data);
}

// "a, b, c" for the sockets' names, "none" for no socket.
template <class Sockets>
std::string socket_names(const Sockets& sockets) {
  std::string names;
  for (const auto& s : sockets) names += (names.empty() ? "" : ", ") + std::string(s.name);
  return names.empty() ? "none" : names;
}

}  // namespace

// ---------------------------------------------------------------- node types
NodeCategory node_category(const NodeVariant& node) {
  return std::visit([]<class T>(const T&) { return category_of<T>(); }, node);
}

std::vector<std::string_view> node_type_names() {
  std::vector<std::string_view> names;
  for_each_alternative<NodeVariant>([&]<class T>(std::type_identity<T>) { names.push_back(T::type_name); });
  return names;
}

std::optional<NodeVariant> make_node(std::string_view type_name) {
  NodeVariant node;
  if (!emplace_by_type_name(node, type_name)) return std::nullopt;
  return node;
}

// ---------------------------------------------------------------- lookups
const GraphNodeDesc* find_node(const GraphDesc& graph, std::string_view id) {
  const auto it = std::find_if(graph.nodes.begin(), graph.nodes.end(),
                               [&](const GraphNodeDesc& n) { return n.id == id; });
  return it == graph.nodes.end() ? nullptr : &*it;
}

const GraphLinkDesc* link_into(const GraphDesc& graph, std::string_view to, std::string_view input) {
  const auto it = std::find_if(graph.links.begin(), graph.links.end(),
                               [&](const GraphLinkDesc& l) { return l.to == to && l.input == input; });
  return it == graph.links.end() ? nullptr : &*it;
}

std::optional<SocketType> output_type(const NodeVariant& node, std::string_view output) {
  for (const SocketDecl& s : node_outputs(node))
    if (s.name == output) return s.type;
  return std::nullopt;
}

std::optional<SocketType> input_type(const NodeVariant& node, std::string_view input) {
  for (const SocketInfo& s : node_inputs(node))
    if (s.name == input) return s.type;
  return std::nullopt;
}

std::string unique_node_id(const GraphDesc& graph, std::string_view base) {
  std::string stem(base.empty() ? "node" : base);
  const size_t dot = stem.rfind('.');
  if (dot != std::string::npos && dot + 1 < stem.size() &&
      std::all_of(stem.begin() + long(dot) + 1, stem.end(), [](char c) { return c >= '0' && c <= '9'; }))
    stem.resize(dot);
  if (!find_node(graph, stem)) return stem;
  for (int k = 1;; ++k) {
    std::string id = stem + "." + std::to_string(k);
    if (!find_node(graph, id)) return id;
  }
}

// ---------------------------------------------------------------- conversion and layout
GraphDesc graph_from_material(const MaterialVariant& material) {
  return std::visit(
      []<class T>(const T& m) -> GraphDesc {
        if constexpr (std::is_same_v<T, GraphDesc>) {
          return m;
        } else {
          GraphDesc g;
          if constexpr (!std::is_same_v<T, MixDesc>) {
            g.nodes.push_back({"surface", NodeVariant(m)});
            g.editor.nodes.push_back({"surface", 0.f, 0.f});
          }
          g.nodes.push_back({"output", OutputNode{}});
          // Right of the widest closure node (toon, about 250 units), as data flows left to right.
          g.editor.nodes.push_back({"output", std::is_same_v<T, MixDesc> ? 0.f : 320.f, 0.f});
          if constexpr (!std::is_same_v<T, MixDesc>)
            g.links.push_back({"surface", "closure", "output", "surface"});
          return g;
        }
      },
      material);
}

void place_unplaced_nodes(GraphDesc& graph) {
  std::vector<size_t> unplaced;
  for (size_t i = 0; i < graph.nodes.size(); ++i)
    if (!node_position(graph, graph.nodes[i].id)) unplaced.push_back(i);
  if (unplaced.empty()) return;
  // Column of a node: the longest chain of links from it to a node without users.
  std::map<std::string, int> column;
  for (size_t i = 0; i < graph.nodes.size(); ++i) column[graph.nodes[i].id] = 0;
  // Relaxation bounded by the node count, so a cycle cannot loop forever.
  for (size_t pass = 0; pass < graph.nodes.size(); ++pass) {
    bool changed = false;
    for (const GraphLinkDesc& l : graph.links) {
      if (!column.count(l.from) || !column.count(l.to)) continue;
      if (column[l.from] < column[l.to] + 1) column[l.from] = column[l.to] + 1, changed = true;
    }
    if (!changed) break;
  }
  int deepest = 0;
  for (const auto& [id, c] : column) deepest = std::max(deepest, c);
  std::map<int, float> next_y;
  for (size_t i : unplaced) {
    const GraphNodeDesc& n = graph.nodes[i];
    const int c = column[n.id];
    float& y = next_y[c];
    graph.editor.nodes.push_back({n.id, float(deepest - c) * 280.f, y});
    y += estimated_height(n.data) + 30.f;
  }
}

std::optional<Vec2> node_position(const GraphDesc& graph, std::string_view id) {
  for (const NodePlacementDesc& p : graph.editor.nodes)
    if (p.node == id) return Vec2(p.x, p.y);
  return std::nullopt;
}

void set_node_position(GraphDesc& graph, std::string_view id, Vec2 position) {
  // Placements stay within what the reader accepts.
  const float x = std::clamp(position.x, -1e7f, 1e7f), y = std::clamp(position.y, -1e7f, 1e7f);
  for (NodePlacementDesc& p : graph.editor.nodes) {
    if (p.node == id) {
      p.x = x, p.y = y;
      return;
    }
  }
  graph.editor.nodes.push_back({std::string(id), x, y});
}

// ---------------------------------------------------------------- structural edits
std::string add_node(GraphDesc& graph, std::string_view type_name, float x, float y) {
  std::optional<NodeVariant> node = make_node(type_name);
  if (!node || (std::holds_alternative<OutputNode>(*node) && has_output_node(graph))) return {};
  std::string id = unique_node_id(graph, type_name);
  graph.nodes.push_back({id, std::move(*node)});
  set_node_position(graph, id, Vec2(x, y));
  return id;
}

size_t remove_nodes(GraphDesc& graph, const std::vector<std::string>& ids) {
  std::set<std::string> gone;
  for (const GraphNodeDesc& n : graph.nodes)
    if (!is_output(n) && std::find(ids.begin(), ids.end(), n.id) != ids.end()) gone.insert(n.id);
  std::erase_if(graph.nodes, [&](const GraphNodeDesc& n) { return gone.count(n.id) > 0; });
  std::erase_if(graph.links, [&](const GraphLinkDesc& l) { return gone.count(l.from) || gone.count(l.to); });
  std::erase_if(graph.editor.nodes, [&](const NodePlacementDesc& p) { return gone.count(p.node) > 0; });
  return gone.size();
}

std::optional<std::string> check_link(const GraphDesc& graph, std::string_view from, std::string_view output,
                                      std::string_view to, std::string_view input) {
  const GraphNodeDesc* f = find_node(graph, from);
  const GraphNodeDesc* t = find_node(graph, to);
  if (!f) return "no node " + in_quotes_(from);
  if (!t) return "no node " + in_quotes_(to);
  if (from == to) return "cannot link " + in_quotes_(from) + " to itself";
  const std::optional<SocketType> out = output_type(f->data, output);
  if (!out)
    return describe_node(*f) + " has no output " + in_quotes_(output) +
           " (outputs: " + socket_names(node_outputs(f->data)) + ")";
  const std::optional<SocketType> in = input_type(t->data, input);
  if (!in)
    return describe_node(*t) + " has no input " + in_quotes_(input) +
           " (inputs: " + socket_names(node_inputs(t->data)) + ")";
  if (!socket_converts(*out, *in))
    return "cannot link " + type_word(*out) + " output " + in_quotes_(output) + " of " + in_quotes_(from) +
           " to " + type_word(*in) + " input " + in_quotes_(input) + " of " + in_quotes_(to);
  if (reaches(graph, to, from))
    return "linking " + in_quotes_(from) + " to " + in_quotes_(to) + " would make a cycle";
  return std::nullopt;
}

std::optional<std::string> connect(GraphDesc& graph, std::string_view from, std::string_view output,
                                   std::string_view to, std::string_view input) {
  if (auto refused = check_link(graph, from, output, to, input)) return refused;
  // Copied first: the names may point into the link this replaces.
  GraphLinkDesc link{std::string(from), std::string(output), std::string(to), std::string(input)};
  std::erase_if(graph.links,
                [&](const GraphLinkDesc& l) { return l.to == link.to && l.input == link.input; });
  graph.links.push_back(std::move(link));
  return std::nullopt;
}

bool disconnect(GraphDesc& graph, std::string_view to, std::string_view input) {
  const std::string node(to), socket(input);  // the names may point into the link removed
  return std::erase_if(graph.links,
                       [&](const GraphLinkDesc& l) { return l.to == node && l.input == socket; }) > 0;
}

void move_nodes(GraphDesc& graph, const std::vector<std::string>& ids, float dx, float dy) {
  for (const std::string& id : ids_present(graph, ids))
    set_node_position(graph, id, position_or_origin(graph, id) + Vec2(dx, dy));
}

std::vector<std::string> duplicate_nodes(GraphDesc& graph, const std::vector<std::string>& ids, float dx,
                                         float dy) {
  std::map<std::string, std::string> copy_of;
  std::vector<std::string> copies;
  for (const std::string& id : ids) {
    const GraphNodeDesc* n = find_node(graph, id);
    if (!n || is_output(*n) || copy_of.count(id)) continue;
    GraphNodeDesc copy = *n;  // before push_back, which may move *n
    copy.id = unique_node_id(graph, id);
    const Vec2 at = position_or_origin(graph, id) + Vec2(dx, dy);
    copy_of[id] = copy.id;
    copies.push_back(copy.id);
    graph.nodes.push_back(std::move(copy));
    set_node_position(graph, copies.back(), at);
  }
  const std::vector<GraphLinkDesc> links = graph.links;
  for (const GraphLinkDesc& l : links) {
    if (copy_of.count(l.from) && copy_of.count(l.to))
      graph.links.push_back({copy_of[l.from], l.output, copy_of[l.to], l.input});
  }
  return copies;
}

std::string copy_nodes(const GraphDesc& graph, const std::vector<std::string>& ids) {
  GraphDesc fragment;
  const std::vector<std::string> present = ids_present(graph, ids);
  const auto in_set = [&](std::string_view id) {
    return std::find(present.begin(), present.end(), id) != present.end();
  };
  for (const GraphNodeDesc& n : graph.nodes)
    if (in_set(n.id)) fragment.nodes.push_back(n);
  for (const GraphLinkDesc& l : graph.links)
    if (in_set(l.from) && in_set(l.to)) fragment.links.push_back(l);
  for (const NodePlacementDesc& p : graph.editor.nodes)
    if (in_set(p.node)) fragment.editor.nodes.push_back(p);
  // Written by the scene writer, so the clipboard reads like a material in a scene file.
  SceneDesc wrapper;
  wrapper.materials.push_back({std::string(kClipboardName), std::move(fragment), {}});
  nlohmann::json material = scene_to_json(wrapper)["materials"][0];
  material.erase("name");
  material.erase("lines");
  return material.dump(2);
}

std::vector<std::string> paste_nodes(GraphDesc& graph, const std::string& clipboard, float x, float y,
                                     std::string* error) {
  const std::optional<GraphDesc> fragment = read_fragment(clipboard, error);
  if (!fragment) return {};
  bool output_taken = has_output_node(graph);
  Vec2 corner(std::numeric_limits<float>::max());
  for (const GraphNodeDesc& n : fragment->nodes)
    corner = glm::min(corner, position_or_origin(*fragment, n.id));
  std::map<std::string, std::string> new_id;
  std::vector<std::string> added;
  for (const GraphNodeDesc& n : fragment->nodes) {
    if (is_output(n) && output_taken) continue;
    output_taken |= is_output(n);
    if (new_id.count(n.id)) continue;  // a duplicate id in the text: the first wins
    GraphNodeDesc copy = n;
    copy.id = unique_node_id(graph, n.id);
    new_id[n.id] = copy.id;
    added.push_back(copy.id);
    graph.nodes.push_back(std::move(copy));
    set_node_position(graph, added.back(), Vec2(x, y) + position_or_origin(*fragment, n.id) - corner);
  }
  for (const GraphLinkDesc& l : fragment->links) {
    if (new_id.count(l.from) && new_id.count(l.to))
      (void)connect(graph, new_id[l.from], l.output, new_id[l.to], l.input);
  }
  return added;
}

std::optional<std::string> insert_on_link(GraphDesc& graph, size_t link_index, std::string_view node_id) {
  if (link_index >= graph.links.size()) return "no link " + std::to_string(link_index);
  const GraphLinkDesc link = graph.links[link_index];
  const GraphNodeDesc* node = find_node(graph, node_id);
  if (!node) return "no node " + in_quotes_(node_id);
  if (link.from == node_id || link.to == node_id)
    return in_quotes_(node_id) + " is already an end of that link";
  const GraphNodeDesc* from = find_node(graph, link.from);
  const GraphNodeDesc* to = find_node(graph, link.to);
  const std::optional<SocketType> carried = from ? output_type(from->data, link.output) : std::nullopt;
  const std::optional<SocketType> wanted = to ? input_type(to->data, link.input) : std::nullopt;
  if (!carried || !wanted) return "the link does not join two existing sockets";
  const SocketType carried_type = *carried, wanted_type = *wanted;

  // Unlinked inputs first (inserting should not cut another link), and within each the same type first.
  const std::vector<SocketInfo> inputs = node_inputs(node->data);
  std::optional<std::string_view> input;
  for (int pass = 0; pass < 4 && !input; ++pass) {
    const bool free_only = pass < 2, exact = pass % 2 == 0;
    for (const SocketInfo& s : inputs) {
      if (free_only && link_into(graph, node_id, s.name)) continue;
      if (exact ? s.type == carried_type : socket_converts(carried_type, s.type)) {
        input = s.name;
        break;
      }
    }
  }
  std::optional<std::string_view> output;
  for (int pass = 0; pass < 2 && !output; ++pass) {
    for (const SocketDecl& s : node_outputs(node->data)) {
      if (pass == 0 ? s.type == wanted_type : socket_converts(s.type, wanted_type)) {
        output = s.name;
        break;
      }
    }
  }
  if (!input) return describe_node(*node) + " has no input that takes a " + type_word(carried_type);
  if (!output)
    return describe_node(*node) + " has no output that fits " + type_word(wanted_type) + " input " +
           in_quotes_(link.input) + " of " + in_quotes_(link.to);
  GraphDesc edited = graph;
  edited.links.erase(edited.links.begin() + long(link_index));
  if (auto refused = connect(edited, link.from, link.output, node_id, *input)) return refused;
  if (auto refused = connect(edited, node_id, *output, link.to, link.input)) return refused;
  graph = std::move(edited);
  return std::nullopt;
}

}  // namespace inkray
