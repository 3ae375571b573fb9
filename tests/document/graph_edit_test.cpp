// The node editor's graph edits: what each does, what it refuses and why, and that a
// graph that compiled still compiles after every edit.
#include "core/document/graph_edit.h"
#include "core/compiler/compile_graph.h"
#include "core/document/json_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace inkray {
namespace {

// The first graph of scenes/graph_toon_rim.json, kept here so the tests do not move
// when the example scene does.
constexpr std::string_view kToonRimScene = R"({
  "format": "inkray-scene", "version": 1,
  "materials": [{"name": "facing_ramp_rim", "type": "graph",
    "nodes": [
      {"id": "geometry", "type": "geometry"},
      {"id": "ramp", "type": "color_ramp", "interpolation": "constant",
       "stops": [{"position": 0, "color": [0.18, 0.1, 0.35]}, {"position": 0.35, "color": [0.75, 0.25, 0.35]},
                 {"position": 0.7, "color": [0.98, 0.62, 0.4]}]},
      {"id": "fresnel", "type": "fresnel", "ior": 1.6},
      {"id": "rim", "type": "math", "operation": "smoothstep", "b": 0.25, "c": 0.3},
      {"id": "rim_color", "type": "mix_color", "blend": "add", "b": [0.9, 0.95, 1.0]},
      {"id": "surface", "type": "unlit"},
      {"id": "out", "type": "output"}],
    "links": [
      {"from": "geometry", "output": "facing", "to": "ramp", "input": "fac"},
      {"from": "fresnel", "output": "fac", "to": "rim", "input": "a"},
      {"from": "ramp", "output": "color", "to": "rim_color", "input": "a"},
      {"from": "rim", "output": "value", "to": "rim_color", "input": "fac"},
      {"from": "rim_color", "output": "color", "to": "surface", "input": "color"},
      {"from": "surface", "output": "closure", "to": "out", "input": "surface"}],
    "editor": {"nodes": [{"node": "geometry", "x": 0, "y": 0}, {"node": "ramp", "x": 220, "y": 0},
                         {"node": "fresnel", "x": 0, "y": 260}, {"node": "rim", "x": 220, "y": 260},
                         {"node": "rim_color", "x": 460, "y": 120}, {"node": "surface", "x": 680, "y": 120},
                         {"node": "out", "x": 880, "y": 120}]}}]
})";

GraphDesc toon_rim_graph() {
  const SceneLoadResult loaded = parse_scene(kToonRimScene, INKRAY_SOURCE_DIR, "toon_rim", ReadFor::editing);
  EXPECT_TRUE(loaded.scene) << (loaded.errors.empty() ? "" : loaded.errors[0]);
  if (!loaded.scene) return {};
  return std::get<GraphDesc>(loaded.scene->materials.at(0).data);
}

// The compiler's verdict, with its messages when it refuses.
std::string compile_errors(const GraphDesc& g) {
  AssetCache assets;
  std::vector<std::string> errors;
  const auto program = compile_graph(g, INKRAY_SOURCE_DIR, assets, errors);
  if (program) return {};
  std::string all;
  for (const auto& e : errors) all += e + "\n";
  return all.empty() ? "refused without a message" : all;
}

bool has_link(const GraphDesc& g, std::string_view from, std::string_view output, std::string_view to,
              std::string_view input) {
  return std::any_of(g.links.begin(), g.links.end(), [&](const GraphLinkDesc& l) {
    return l.from == from && l.output == output && l.to == to && l.input == input;
  });
}

void expect_unique_ids(const GraphDesc& g) {
  std::set<std::string> ids;
  for (const GraphNodeDesc& n : g.nodes) EXPECT_TRUE(ids.insert(n.id).second) << "duplicate id " << n.id;
}

TEST(GraphEdit, TheExampleGraphCompiles) { EXPECT_EQ(compile_errors(toon_rim_graph()), ""); }

TEST(GraphEdit, EveryNodeTypeHasACategoryAndADefault) {
  const std::vector<std::string_view> names = node_type_names();
  EXPECT_EQ(names.size(), std::variant_size_v<NodeVariant>);
  for (std::string_view name : names) {
    const std::optional<NodeVariant> node = make_node(name);
    ASSERT_TRUE(node) << name;
    EXPECT_EQ(node_type_name(*node), name);
  }
  EXPECT_EQ(node_category(OutputNode{}), NodeCategory::output);
  EXPECT_EQ(node_category(GeometryNode{}), NodeCategory::input);
  EXPECT_EQ(node_category(NoiseNode{}), NodeCategory::texture);
  EXPECT_EQ(node_category(ColorRampNode{}), NodeCategory::converter);
  EXPECT_EQ(node_category(MathNode{}), NodeCategory::converter);
  EXPECT_EQ(node_category(ToonDesc{}), NodeCategory::closure);
  EXPECT_EQ(node_category(MixClosureNode{}), NodeCategory::closure);
  EXPECT_FALSE(make_node("teapot"));
}

TEST(GraphEdit, PlainMaterialsBecomeOneClosureWiredToAnOutput) {
  DiffuseDesc diffuse;
  diffuse.albedo = CheckerTextureDesc{};
  const GraphDesc g = graph_from_material(diffuse);
  ASSERT_EQ(g.nodes.size(), 2u);
  EXPECT_EQ(std::get<DiffuseDesc>(g.nodes[0].data), diffuse);  // textures and settings kept
  EXPECT_TRUE(std::holds_alternative<OutputNode>(g.nodes[1].data));
  EXPECT_TRUE(has_link(g, "surface", "closure", "output", "surface"));
  ASSERT_TRUE(node_position(g, "surface") && node_position(g, "output"));
  EXPECT_LT(node_position(g, "surface")->x, node_position(g, "output")->x);
  EXPECT_EQ(compile_errors(g), "");
  for (const MaterialVariant& m : {MaterialVariant(ToonDesc{}), MaterialVariant(DielectricDesc{}),
                                   MaterialVariant(EmissiveDesc{}), MaterialVariant(TransparentDesc{})})
    EXPECT_EQ(compile_errors(graph_from_material(m)), "") << type_name_of(m);

  const GraphDesc graph = toon_rim_graph();
  EXPECT_EQ(graph_from_material(graph), graph);
  // A mix names other materials, which a graph cannot: an output alone.
  const GraphDesc mix = graph_from_material(MixDesc{"a", "b", Color(0.5f)});
  ASSERT_EQ(mix.nodes.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<OutputNode>(mix.nodes[0].data));
  EXPECT_TRUE(mix.links.empty());
}

TEST(GraphEdit, AddNodeGivesUniqueIdsAndOneOutput) {
  GraphDesc g = toon_rim_graph();
  EXPECT_EQ(add_node(g, "noise_texture", 10, 20), "noise_texture");
  EXPECT_EQ(add_node(g, "noise_texture", 10, 60), "noise_texture.1");
  EXPECT_EQ(add_node(g, "noise_texture", 10, 90), "noise_texture.2");
  EXPECT_EQ(add_node(g, "fresnel", 0, 0), "fresnel.1");  // "fresnel" is taken
  EXPECT_EQ(*node_position(g, "noise_texture.1"), Vec2(10, 60));
  const GraphDesc before = g;
  EXPECT_EQ(add_node(g, "teapot", 0, 0), "");
  EXPECT_EQ(add_node(g, "output", 0, 0), "");  // a graph has one output
  EXPECT_EQ(g, before);
  expect_unique_ids(g);
  EXPECT_EQ(compile_errors(g), "");
  EXPECT_EQ(unique_node_id(g, "noise_texture.1"), "noise_texture.3");
}

TEST(GraphEdit, RemoveNodesTakesTheirLinksAndPlacementsButKeepsTheOutput) {
  GraphDesc g = toon_rim_graph();
  EXPECT_EQ(remove_nodes(g, {"rim", "out", "nothing"}), 1u);
  EXPECT_FALSE(find_node(g, "rim"));
  ASSERT_TRUE(find_node(g, "out"));
  for (const GraphLinkDesc& l : g.links) EXPECT_TRUE(l.from != "rim" && l.to != "rim");
  EXPECT_FALSE(node_position(g, "rim"));
  EXPECT_EQ(compile_errors(g), "");  // rim_color.fac falls back to its value
  EXPECT_EQ(remove_nodes(g, {"surface"}), 1u);
  EXPECT_EQ(compile_errors(g), "");  // an unlinked surface is allowed
}

TEST(GraphEdit, ConnectRefusesWithReasons) {
  GraphDesc g = toon_rim_graph();
  const GraphDesc before = g;
  EXPECT_EQ(connect(g, "ghost", "value", "rim", "b"), "no node \"ghost\"");
  EXPECT_EQ(connect(g, "rim", "value", "ghost", "b"), "no node \"ghost\"");
  EXPECT_EQ(connect(g, "rim", "value", "rim", "b"), "cannot link \"rim\" to itself");
  EXPECT_EQ(connect(g, "rim", "colour", "ramp", "fac"),
            "\"rim\" (math) has no output \"colour\" (outputs: value)");
  EXPECT_EQ(connect(g, "rim", "value", "ramp", "position"),
            "\"ramp\" (color_ramp) has no input \"position\" (inputs: fac)");
  EXPECT_EQ(connect(g, "surface", "closure", "rim_color", "b"),
            "cannot link closure output \"closure\" of \"surface\" to colour input \"b\" of \"rim_color\"");
  EXPECT_EQ(connect(g, "rim_color", "color", "ramp", "fac"),
            "linking \"rim_color\" to \"ramp\" would make a cycle");
  EXPECT_EQ(g, before);  // a refusal changes nothing
  EXPECT_EQ(check_link(g, "rim", "value", "rim_color", "b"), std::nullopt);
  EXPECT_EQ(g, before);  // asking changes nothing either
}

TEST(GraphEdit, ConnectReplacesTheLinkIntoThatInput) {
  GraphDesc g = toon_rim_graph();
  const size_t links = g.links.size();
  // Float to colour converts; it replaces ramp -> rim_color.a.
  EXPECT_EQ(connect(g, "fresnel", "fac", "rim_color", "a"), std::nullopt);
  EXPECT_EQ(g.links.size(), links);
  EXPECT_TRUE(has_link(g, "fresnel", "fac", "rim_color", "a"));
  EXPECT_FALSE(has_link(g, "ramp", "color", "rim_color", "a"));
  EXPECT_EQ(compile_errors(g), "");
  // Linking into a link-only input of the output node adds a link.
  EXPECT_EQ(connect(g, "rim", "value", "out", "line_width"), std::nullopt);
  EXPECT_EQ(g.links.size(), links + 1);
  EXPECT_EQ(compile_errors(g), "");
}

TEST(GraphEdit, Disconnect) {
  GraphDesc g = toon_rim_graph();
  EXPECT_TRUE(disconnect(g, "rim_color", "fac"));
  EXPECT_FALSE(link_into(g, "rim_color", "fac"));
  EXPECT_FALSE(disconnect(g, "rim_color", "fac"));
  EXPECT_EQ(compile_errors(g), "");
}

TEST(GraphEdit, MoveNodes) {
  GraphDesc g = toon_rim_graph();
  const Vec2 ramp = *node_position(g, "ramp"), rim = *node_position(g, "rim"), out = *node_position(g, "out");
  move_nodes(g, {"ramp", "rim", "ghost"}, 15.f, -5.f);
  EXPECT_EQ(*node_position(g, "ramp"), ramp + Vec2(15, -5));
  EXPECT_EQ(*node_position(g, "rim"), rim + Vec2(15, -5));
  EXPECT_EQ(*node_position(g, "out"), out);
  EXPECT_FALSE(node_position(g, "ghost"));
  set_node_position(g, "out", Vec2(1, 2));
  EXPECT_EQ(*node_position(g, "out"), Vec2(1, 2));
}

TEST(GraphEdit, DuplicateCopiesTheLinksAmongTheCopies) {
  GraphDesc g = toon_rim_graph();
  const std::vector<std::string> copies = duplicate_nodes(g, {"fresnel", "rim", "out"}, 30.f, 40.f);
  ASSERT_EQ(copies, (std::vector<std::string>{"fresnel.1", "rim.1"}));  // never a second output
  EXPECT_TRUE(has_link(g, "fresnel.1", "fac", "rim.1", "a"));
  EXPECT_FALSE(link_into(g, "rim_color", "fac")->from ==
               "rim.1");  // the links out of the set stay with the originals
  EXPECT_EQ(std::get<MathNode>(find_node(g, "rim.1")->data), std::get<MathNode>(find_node(g, "rim")->data));
  EXPECT_EQ(*node_position(g, "rim.1"), *node_position(g, "rim") + Vec2(30, 40));
  expect_unique_ids(g);
  EXPECT_EQ(compile_errors(g), "");
}

TEST(GraphEdit, CopyPasteRoundTrip) {
  const GraphDesc source = toon_rim_graph();
  std::vector<std::string> all;
  for (const GraphNodeDesc& n : source.nodes) all.push_back(n.id);
  const std::string clipboard = copy_nodes(source, all);

  // Into an empty graph at the source's own corner: the same graph.
  GraphDesc empty;
  EXPECT_EQ(paste_nodes(empty, clipboard, 0.f, 0.f), all);
  EXPECT_EQ(empty.nodes, source.nodes);
  EXPECT_EQ(empty.editor.nodes.size(), source.editor.nodes.size());
  for (const std::string& id : all) EXPECT_EQ(node_position(empty, id), node_position(source, id)) << id;
  EXPECT_EQ(std::set<std::string>(all.begin(), all.end()).size(), empty.nodes.size());
  for (const GraphLinkDesc& l : source.links) EXPECT_TRUE(has_link(empty, l.from, l.output, l.to, l.input));
  EXPECT_EQ(compile_errors(empty), "");

  // Into the graph itself: new ids, the links remapped, no second output.
  GraphDesc g = source;
  const std::vector<std::string> pasted = paste_nodes(g, clipboard, 100.f, 500.f);
  EXPECT_EQ(pasted.size(), source.nodes.size() - 1);
  EXPECT_EQ(pasted.front(), "geometry.1");
  EXPECT_TRUE(has_link(g, "geometry.1", "facing", "ramp.1", "fac"));
  EXPECT_EQ(*node_position(g, "geometry.1"), Vec2(100, 500));
  EXPECT_EQ(*node_position(g, "rim.1"), Vec2(100 + 220, 500 + 260));
  expect_unique_ids(g);
  EXPECT_EQ(compile_errors(g), "");

  // A part: only the links among the copied nodes.
  const std::string part = copy_nodes(source, {"fresnel", "rim"});
  GraphDesc h = source;
  EXPECT_EQ(paste_nodes(h, part, 0, 0), (std::vector<std::string>{"fresnel.1", "rim.1"}));
  EXPECT_EQ(h.links.size(), source.links.size() + 1);
  EXPECT_EQ(compile_errors(h), "");
}

TEST(GraphEdit, PasteRefusesWhatIsNotAGraph) {
  GraphDesc g = toon_rim_graph();
  const GraphDesc before = g;
  std::string error;
  EXPECT_TRUE(paste_nodes(g, "hello", 0, 0, &error).empty());
  EXPECT_EQ(error, "the clipboard holds no nodes (expected a graph material's JSON)");
  EXPECT_TRUE(
      paste_nodes(g, R"({"type": "graph", "nodes": [{"id": "m", "type": "math", "a": "x"}]})", 0, 0, &error)
          .empty());
  EXPECT_EQ(error, "clipboard: nodes[0].a: expected a number in [-1000000000, 1000000000], got \"x\"");
  EXPECT_EQ(g, before);
}

TEST(GraphEdit, InsertOnLinkKeepsTypesLegal) {
  GraphDesc g = toon_rim_graph();
  // A hue/saturation node between the ramp and the rim blend: colour in, colour out.
  ASSERT_EQ(add_node(g, "hue_saturation", 300, 300), "hue_saturation");
  const size_t link =
      size_t(std::find_if(g.links.begin(), g.links.end(),
                          [](const GraphLinkDesc& l) { return l.to == "rim_color" && l.input == "a"; }) -
             g.links.begin());
  EXPECT_EQ(insert_on_link(g, link, "hue_saturation"), std::nullopt);
  EXPECT_TRUE(has_link(g, "ramp", "color", "hue_saturation", "color"));  // the first colour input
  EXPECT_TRUE(has_link(g, "hue_saturation", "color", "rim_color", "a"));
  EXPECT_FALSE(has_link(g, "ramp", "color", "rim_color", "a"));
  EXPECT_EQ(compile_errors(g), "");

  // A math node on a float link takes its first free float input.
  ASSERT_EQ(add_node(g, "math", 0, 400), "math");
  const auto index_of = [&](std::string_view to, std::string_view input) {
    return size_t(std::find_if(g.links.begin(), g.links.end(),
                               [&](const GraphLinkDesc& l) { return l.to == to && l.input == input; }) -
                  g.links.begin());
  };
  EXPECT_EQ(insert_on_link(g, index_of("rim", "a"), "math"), std::nullopt);
  EXPECT_TRUE(has_link(g, "fresnel", "fac", "math", "a"));
  EXPECT_TRUE(has_link(g, "math", "value", "rim", "a"));
  EXPECT_EQ(compile_errors(g), "");

  const GraphDesc before = g;
  // A closure node fits no colour input downstream.
  ASSERT_EQ(add_node(g, "diffuse", 0, 600), "diffuse");
  const GraphDesc with_diffuse = g;
  EXPECT_EQ(insert_on_link(g, index_of("rim_color", "fac"), "diffuse"),
            "\"diffuse\" (diffuse) has no output that fits float input \"fac\" of \"rim_color\"");
  // The ramp sits upstream of rim_color: rerouting rim_color's output through it is a cycle.
  EXPECT_EQ(insert_on_link(g, index_of("surface", "color"), "ramp"),
            "linking \"rim_color\" to \"ramp\" would make a cycle");
  EXPECT_EQ(insert_on_link(g, index_of("rim", "a"), "rim"), "\"rim\" is already an end of that link");
  EXPECT_EQ(insert_on_link(g, 999, "rim"), "no link 999");
  EXPECT_EQ(g, with_diffuse);
  EXPECT_NE(g, before);
}

TEST(GraphEdit, EditsAreValuesTheCallerCanUndo) {
  // The editor keeps the graph before an edit and hands both to its undo stack.
  const GraphDesc original = toon_rim_graph();
  GraphDesc edited = original;
  add_node(edited, "value", 0, 0);
  connect(edited, "value", "value", "rim", "b");
  move_nodes(edited, {"rim"}, 5, 5);
  remove_nodes(edited, {"fresnel"});
  EXPECT_NE(edited, original);
  EXPECT_EQ(compile_errors(edited), "");
  EXPECT_EQ(toon_rim_graph(), original);  // nothing shared
}

TEST(GraphEdit, WhatTheEditsBuildIsWhatTheFileReadsBack) {
  // A plain material turned graph, every node type added, some of them linked.
  GraphDesc g = graph_from_material(ToonDesc{});
  float y = 0.f;
  for (std::string_view name : node_type_names()) add_node(g, name, 400.f, y += 60.f);
  EXPECT_EQ(connect(g, "noise_texture", "color", "hue_saturation", "color"), std::nullopt);
  EXPECT_EQ(connect(g, "geometry", "uv", "noise_texture", "vector"), std::nullopt);
  EXPECT_EQ(connect(g, "hue_saturation", "color", "surface", "color"), std::nullopt);
  duplicate_nodes(g, {"noise_texture", "hue_saturation"}, 20.f, 20.f);
  paste_nodes(g, copy_nodes(g, {"math", "map_range"}), -300.f, 0.f);
  SceneDesc scene;
  scene.materials.push_back({"built", g, {}});
  const SceneLoadResult read =
      parse_scene(scene_to_string(scene), INKRAY_SOURCE_DIR, "built", ReadFor::editing);
  ASSERT_TRUE(read.scene) << read.errors.at(0);
  EXPECT_EQ(std::get<GraphDesc>(read.scene->materials.at(0).data), g);
  EXPECT_EQ(compile_errors(g), "");
  // A new image_texture has no file yet: linked towards the output, it stops the graph
  // until one is chosen. (An empty path names the scene's folder, which compile_graph
  // alone does not refuse before reading; check_scene does, in the editor.)
  EXPECT_EQ(connect(g, "image_texture", "color", "surface", "color"), std::nullopt);
  const auto set_image = [&](const std::string& path) {
    for (GraphNodeDesc& n : g.nodes)
      if (n.id == "image_texture") std::get<ImageTextureNode>(n.data).path = path;
  };
  set_image("scenes/textures/missing.png");
  EXPECT_NE(compile_errors(g).find("\"image_texture\" (image_texture): path"), std::string::npos)
      << compile_errors(g);
  set_image("scenes/textures/tiles.png");
  EXPECT_EQ(compile_errors(g), "");
}

TEST(GraphEdit, UnplacedNodesAreLaidOutLeftOfTheirUsers) {
  GraphDesc g = toon_rim_graph();
  g.editor.nodes.clear();
  place_unplaced_nodes(g);
  ASSERT_EQ(g.editor.nodes.size(), g.nodes.size());
  for (const GraphLinkDesc& l : g.links)
    EXPECT_LT(node_position(g, l.from)->x, node_position(g, l.to)->x) << l.from << " -> " << l.to;
  const GraphDesc placed = g;
  place_unplaced_nodes(g);
  EXPECT_EQ(g, placed);  // placed nodes stay
}

}  // namespace
}  // namespace inkray
