// Graph checks name the material's JSON path and the node; lowering keeps only
// what reaches the output, folds constants, and reuses registers.
#include "support/graph_helpers.h"

#include "core/document/json_io.h"
#include <nlohmann/json.hpp>
#include "support/messages.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

using namespace inkray::testing;

std::string errors_of(const GraphDesc& g) {
  const CompiledGraph c = compile(g);
  EXPECT_FALSE(c.program) << "expected the graph to be refused";
  return joined(c.errors);
}

GraphDesc toon_graph() {
  GraphDesc g{.nodes = {{"geo", GeometryNode{}}, {"ramp", ColorRampNode{}}, {"toon", ToonDesc{}}},
              .links = {{"geo", "facing", "ramp", "fac"}, {"ramp", "color", "toon", "color"}}};
  add_output(g, "toon");
  return g;
}

// The facing ratio through `length` maths nodes into a diffuse's albedo: nothing folds.
template <class Op>
GraphDesc math_chain(int length, Op op_of) {
  GraphDesc g;
  add(g, "geo", GeometryNode{});
  std::string last = "geo", output = "facing";
  for (int i = 0; i < length; ++i) {
    const std::string id = "m" + std::to_string(i);
    add(g, id, MathNode{op_of(i), false, 0.5f, 1.25f, 1.f});
    link(g, last, output, id, "a");
    last = id;
    output = "value";
  }
  add(g, "d", DiffuseDesc{});
  add(g, "out", OutputNode{});
  link(g, last, output, "d", "albedo");
  link(g, "d", "closure", "out", "surface");
  return g;
}

TEST(GraphChecks, AWellFormedGraphCompiles) {
  const CompiledGraph c = compile(toon_graph());
  ASSERT_TRUE(c.program) << c.errors.front();
  EXPECT_TRUE(c.errors.empty());
  EXPECT_EQ(c.program->leaves.size(), 1u);
}

TEST(GraphChecks, EveryProblemIsNamedWithItsPath) {
  {
    GraphDesc g = toon_graph();
    g.nodes[1].id = "geo";
    EXPECT_NE(errors_of(g).find("nodes[1].id: duplicate node id \"geo\" (also nodes[0])"), std::string::npos);
  }
  {
    GraphDesc g = toon_graph();
    g.nodes.pop_back();
    g.links.pop_back();
    EXPECT_NE(errors_of(g).find("the graph has no output node"), std::string::npos);
  }
  {
    GraphDesc g = toon_graph();
    add(g, "out2", OutputNode{});
    EXPECT_NE(errors_of(g).find("nodes[4] \"out2\" (output): a second output node"), std::string::npos);
  }
  {
    GraphDesc g = toon_graph();
    link(g, "nowhere", "value", "toon", "threshold");
    EXPECT_NE(errors_of(g).find("links[3].from: no node \"nowhere\" (nodes: geo, ramp, toon, out)"),
              std::string::npos);
  }
  {
    GraphDesc g = toon_graph();
    g.links[0].output = "facingness";
    EXPECT_NE(errors_of(g).find("links[0].output: nodes[0] \"geo\" (geometry) has no output \"facingness\" "
                                "(outputs: position, normal,"),
              std::string::npos);
  }
  {
    GraphDesc g = toon_graph();
    g.links[1].input = "colour";
    EXPECT_NE(
        errors_of(g).find("links[1].input: nodes[2] \"toon\" (toon) has no input \"colour\" (inputs: color, "
                          "shadow_color,"),
        std::string::npos);
  }
  {
    GraphDesc g = toon_graph();
    link(g, "toon", "closure", "ramp", "fac");  // a closure cannot be a number
    const std::string e = errors_of(g);
    EXPECT_NE(e.find("links[3]: cannot link closure output \"closure\" of \"toon\" to float input \"fac\" of "
                     "\"ramp\""),
              std::string::npos)
        << e;
  }
  {
    GraphDesc g = toon_graph();
    link(g, "geo", "depth", "ramp", "fac");
    EXPECT_NE(errors_of(g).find("links[3].input: input \"fac\" of \"ramp\" is already linked from \"geo\""),
              std::string::npos);
  }
  {
    GraphDesc g;
    add(g, "a", MathNode{});
    add(g, "b", MathNode{});
    add(g, "out", OutputNode{});
    link(g, "a", "value", "b", "a");
    link(g, "b", "value", "a", "a");
    EXPECT_NE(errors_of(g).find("links: these nodes form or follow a cycle: a, b"), std::string::npos);
  }
}

// In a scene, a bad graph is an error naming the material; the editor's compile
// draws it as a stand-in and carries on.
TEST(GraphChecks, ABrokenGraphNamesItsMaterialAndTheEditorStillRenders) {
  SceneDesc d = testing::one_sphere_scene(8, 8);
  GraphDesc g = toon_graph();
  g.links[0].output = "nope";
  d.materials[0].data = g;
  const CompileResult strict = compile_scene(d);
  EXPECT_FALSE(strict.scene);
  ASSERT_FALSE(strict.errors.empty());
  EXPECT_EQ(strict.errors[0].rfind("materials[0] \"m\": links[0].output:", 0), 0u) << strict.errors[0];
  SceneCompiler compiler;
  CompileOptions options;
  options.stand_in_for_broken_graphs = true;
  const CompileResult lenient = compiler.compile(d, options);
  ASSERT_TRUE(lenient.scene);
  EXPECT_TRUE(lenient.errors.empty());
  ASSERT_EQ(lenient.warnings.size(), 1u);
  EXPECT_EQ(lenient.warnings[0].rfind("materials[0] \"m\": links[0].output:", 0), 0u);
}

TEST(GraphLowering, NodesThatDoNotReachTheOutputNeverRun) {
  GraphDesc g = toon_graph();
  for (int i = 0; i < 20; ++i) {
    const std::string id = "unused" + std::to_string(i);
    add(g, id, NoiseNode{});
    if (i > 0) link(g, "unused" + std::to_string(i - 1), "fac", id, "scale");
  }
  const CompiledGraph c = compile(g);
  ASSERT_TRUE(c.program);
  EXPECT_EQ(c.program->nodes_in_graph, 24u);
  EXPECT_EQ(c.program->nodes_run, 4u);
  for (const ShaderInstr& i : c.program->code) EXPECT_NE(i.op, ShaderOp::noise_fac);
}

TEST(GraphLowering, ConstantsFoldAway) {
  // (2 + 3) * 0.1 through a ramp: nothing depends on the hit, so no instruction is left.
  GraphDesc g{
      .nodes = {{"a", MathNode{MathOp::add, false, 2.f, 3.f, 1.f}},
                {"b", MathNode{MathOp::multiply, false, 0.f, 0.1f, 1.f}},
                {"ramp", ColorRampNode{}},
                {"d", DiffuseDesc{}}},
      .links = {{"a", "value", "b", "a"}, {"b", "value", "ramp", "fac"}, {"ramp", "color", "d", "albedo"}}};
  add_output(g, "d");
  const CompiledGraph c = compile(g);
  ASSERT_TRUE(c.program);
  EXPECT_TRUE(c.program->code.empty()) << c.program->code.size() << " instructions left";
  SurfaceInteraction si;
  ShaderRegisters r;
  run_shader(*c.program, test_point(si), r);
  EXPECT_NEAR(r[c.program->leaves[0].inputs[0].reg].x, 0.5f, 1e-6f);
  // One input that reads the hit keeps exactly the work that depends on it.
  add(g, "geo", GeometryNode{});
  link(g, "geo", "facing", "b", "b");
  const CompiledGraph live = compile(g);
  ASSERT_TRUE(live.program);
  EXPECT_EQ(live.program->code.size(), 3u);  // facing, multiply, ramp
}

TEST(GraphLowering, RegistersAreReusedOnceDead) {
  // A chain of 200 math nodes needs a handful of registers, not 200.
  const CompiledGraph c = compile(math_chain(200, [](int i) { return MathOp(i % 7); }));
  ASSERT_TRUE(c.program) << c.errors.front();
  EXPECT_EQ(c.program->code.size(), 201u);
  EXPECT_LE(c.program->register_count - int(c.program->constants.size()), 2);
}

// Checks and lowering walk graphs without recursion: a very long chain is no stack risk,
// and a graph with more closures than the tree's indices hold is refused with a message.
TEST(GraphLowering, HugeGraphsAreHandledOrRefusedCleanly) {
  const CompiledGraph c = compile(math_chain(20000, [](int) { return MathOp::multiply; }));
  ASSERT_TRUE(c.program) << c.errors.front();
  EXPECT_EQ(c.program->code.size(), 20001u);

  GraphDesc wide;
  add(wide, "out", OutputNode{});
  std::string below = "leaf";
  add(wide, below, DiffuseDesc{});
  for (size_t i = 0; i < kMaxClosures; ++i) {
    const std::string id = "mix" + std::to_string(i);
    add(wide, id, MixClosureNode{});
    link(wide, below, "closure", id, "a");
    below = id;
  }
  link(wide, below, "closure", "out", "surface");
  const std::string e = errors_of(wide);
  EXPECT_NE(e.find("closures reaching its output"), std::string::npos) << e;
}

TEST(GraphJson, RoundTripKeepsNodesLinksAndLayout) {
  SceneDesc d = testing::one_sphere_scene(8, 8);
  GraphDesc g = toon_graph();
  std::get<ToonDesc>(g.nodes[2].data).bands = 3;
  std::get<ColorRampNode>(g.nodes[1].data).stops = {{0.2f, Color(0.1f, 0.2f, 0.3f)}, {0.9f, Color(1.f)}};
  g.editor.nodes = {{"geo", 10.f, 20.f}, {"out", 400.f, -35.5f}};
  g.editor.zoom = 1.5f;
  g.editor.pan_x = -12.f;
  d.materials[0].data = g;
  const std::string text = scene_to_json(d).dump(2);
  const SceneLoadResult back = parse_scene(text, ".", "round trip");
  ASSERT_TRUE(back) << back.errors.front();
  EXPECT_EQ(std::get<GraphDesc>(back.scene->materials[0].data), g);
}

TEST(GraphJson, ReaderNamesBadNodes) {
  const std::string text = R"({"format": "inkray-scene", "version": 1,
    "materials": [{"name": "m", "type": "graph",
      "nodes": [{"id": "a", "type": "sparkle"}, {"type": "math"}, {"id": "c", "type": "math", "operation": "modulo"}],
      "links": [{"from": "a", "output": "x"}]}]})";
  const SceneLoadResult r = parse_scene(text, ".", "bad.json");
  std::string all;
  for (const auto& e : r.errors) all += e + "\n";
  EXPECT_NE(all.find("materials[0].nodes[0].type: unknown node type \"sparkle\""), std::string::npos) << all;
  EXPECT_NE(all.find("materials[0].nodes[1]: missing required key \"id\""), std::string::npos) << all;
  EXPECT_NE(all.find("materials[0].nodes[2].operation: expected one of"), std::string::npos) << all;
  EXPECT_NE(all.find("materials[0].links[0]: missing required key \"to\""), std::string::npos) << all;
}

}  // namespace
}  // namespace inkray
