// Edits of a material graph for the node editor, as plain functions over GraphDesc
// (docs/architecture.md, "Material graphs"). Each edits the graph in place and says
// what it did (an id, a list of ids, or an error message when it refuses and leaves
// the graph unchanged). Undo is the caller's: copy the scene, edit the copy, hand it
// to Document::edit. A graph that compiled before an edit compiles after it, with
// one exception: a new image_texture node has no file until one is chosen, so linked
// towards the output it stops the graph (unlinked nodes are not compiled).
#pragma once

#include "core/document/desc.h"
#include "core/math/types.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// ---------------------------------------------------------------- node types
// The add menu's groups and the title colours of the node editor.
enum class NodeCategory : unsigned char { input, texture, converter, closure, output };
inline constexpr std::array<std::string_view, 5> kNodeCategoryNames = {"Input", "Texture", "Converter",
                                                                       "Closure", "Output"};
NodeCategory node_category(const NodeVariant& node);
// Every node type's JSON name, in NodeVariant order.
std::vector<std::string_view> node_type_names();
// A default node of that type; nullopt for an unknown name.
std::optional<NodeVariant> make_node(std::string_view type_name);

// ---------------------------------------------------------------- lookups
const GraphNodeDesc* find_node(const GraphDesc& graph, std::string_view id);
// The link entering that input, or null.
const GraphLinkDesc* link_into(const GraphDesc& graph, std::string_view to, std::string_view input);
std::optional<SocketType> output_type(const NodeVariant& node, std::string_view output);
std::optional<SocketType> input_type(const NodeVariant& node, std::string_view input);
// `base` when no node has that id, else "base.1", "base.2", ... (a copy of "rim.1" is "rim.2").
std::string unique_node_id(const GraphDesc& graph, std::string_view base);

// ---------------------------------------------------------------- conversion and layout
// A plain material becomes one closure node (id "surface", its settings kept, colour
// textures included) wired into an output node; a graph is returned as it is; a mix
// names two other materials, which a graph cannot refer to, so it becomes an output
// node alone (the caller keeps the mix until the user builds the graph).
GraphDesc graph_from_material(const MaterialVariant& material);
// Places nodes that have no position (a graph written by hand) in columns by their
// distance from the output, right to left; placed nodes stay where they are.
void place_unplaced_nodes(GraphDesc& graph);

// The canvas position of a node's top-left corner; nullopt when it has none.
std::optional<Vec2> node_position(const GraphDesc& graph, std::string_view id);
void set_node_position(GraphDesc& graph, std::string_view id, Vec2 position);

// ---------------------------------------------------------------- structural edits
// Adds a default node of the type at (x, y); returns its new id, or "" for an unknown
// type or a second output node (a graph has one).
std::string add_node(GraphDesc& graph, std::string_view type_name, float x, float y);
// Removes the nodes, their links and their placements; the output node is kept (a
// graph without one cannot render). Returns how many nodes were removed.
size_t remove_nodes(GraphDesc& graph, const std::vector<std::string>& ids);

// Why linking output `output` of `from` to input `input` of `to` is refused (unknown
// node or socket, a node linked to itself, types socket_converts refuses, a cycle),
// or nullopt when it is allowed. The editor asks this while a link is dragged.
std::optional<std::string> check_link(const GraphDesc& graph, std::string_view from, std::string_view output,
                                      std::string_view to, std::string_view input);
// Adds the link, replacing any link into that input; the refusal message otherwise.
std::optional<std::string> connect(GraphDesc& graph, std::string_view from, std::string_view output,
                                   std::string_view to, std::string_view input);
// Removes the link into that input; false when there was none.
bool disconnect(GraphDesc& graph, std::string_view to, std::string_view input);

// Moves the nodes' placements (a node without one is placed at its default first).
void move_nodes(GraphDesc& graph, const std::vector<std::string>& ids, float dx, float dy);
// Copies the nodes (never the output) with new ids, offset by (dx, dy), and the links
// among them; returns the copies' ids in the order given.
std::vector<std::string> duplicate_nodes(GraphDesc& graph, const std::vector<std::string>& ids, float dx,
                                         float dy);

// The nodes, the links among them and their placements as the JSON of a graph
// material ({"type": "graph", "nodes": ..., "links": ..., "editor": ...}): the
// clipboard text, which a scene file's graph material also is.
std::string copy_nodes(const GraphDesc& graph, const std::vector<std::string>& ids);
// Adds the clipboard's nodes (an output node only when the graph has none) with new
// ids, their top-left at (x, y), and the links among them that are legal here.
// Returns the new ids; on unreadable text, none, with the reader's messages in *error.
std::vector<std::string> paste_nodes(GraphDesc& graph, const std::string& clipboard, float x, float y,
                                     std::string* error = nullptr);

// Reroutes link `link_index` through the node: the link's source feeds the node's
// first input that takes its type (the same type first, else one it converts to), and
// the node's first output that fits the link's input feeds it. Refused (message,
// graph unchanged) when the node is an end of the link, has no fitting sockets, or the
// reroute would make a cycle.
std::optional<std::string> insert_on_link(GraphDesc& graph, size_t link_index, std::string_view node_id);

}  // namespace inkray
