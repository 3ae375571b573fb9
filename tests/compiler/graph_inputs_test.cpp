// Every node type compiles with any input unlinked (to its documented default) or
// linked from any output the graph lets it take, and its values stay finite; a
// closure's linked inputs are kept to their parameters' hard ranges
// (docs/architecture.md, "Material graphs"). Node types are enumerated from
// NodeVariant, so a new one is covered without touching this file.
#include "core/compiler/compile.h"
#include "core/document/tagged_variant.h"
#include "support/graph_helpers.h"
#include "support/messages.h"
#include "support/render_helpers.h"
#include "tests/compiler/graph_edit_ops.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace inkray {
namespace {

using namespace inkray::testing;
using graph_ops::compile_and_check;
using graph_ops::material_numbers;

const std::filesystem::path kBase =
    std::filesystem::path(INKRAY_SOURCE_DIR) / "tests" / "data" / "scenes" / "valid";

template <class T>
constexpr bool kIsClosure = std::is_constructible_v<MaterialVariant, T>;  // a plain material's description

// A node of the type as the editor adds it, with a file where it needs one to compile.
template <class T>
NodeVariant usable_node() {
  T node{};
  if constexpr (std::is_same_v<T, ImageTextureNode>) node.path = "textures/checker.png";
  return node;
}

std::vector<NodeVariant> all_node_types() {
  std::vector<NodeVariant> nodes;
  for_each_alternative<NodeVariant>(
      [&]<class T>(std::type_identity<T>) { nodes.push_back(usable_node<T>()); });
  return nodes;
}

// The smallest graph in which node "n" (of `node`'s type) reaches the output: a closure
// node feeds the surface, any other node's output `output` feeds an unlit surface's
// colour, and the output node itself gets a diffuse surface unless `input` is its surface.
GraphDesc reaching_output(const NodeVariant& node, size_t output, std::string_view input) {
  GraphDesc g;
  if (std::holds_alternative<OutputNode>(node)) {
    add(g, "n", node);
    if (input != "surface") {
      add(g, "d", DiffuseDesc{});
      link(g, "d", "closure", "n", "surface");
    }
    return g;
  }
  add(g, "n", node);
  add(g, "out", OutputNode{});
  const auto outs = node_outputs(node);
  if (outs[output].type == SocketType::closure) {
    link(g, "n", std::string(outs[output].name), "out", "surface");
  } else {
    add(g, "probe", UnlitDesc{});
    link(g, "n", std::string(outs[output].name), "probe", "color");
    link(g, "probe", "closure", "out", "surface");
  }
  return g;
}

std::string describe(const NodeVariant& node, std::string_view input) {
  return std::string(node_type_name(node)) + "." + std::string(input);
}

TEST(GraphInputs, EveryInputOfEveryNodeCompilesUnlinked) {
  AssetCache assets;
  size_t cases = 0;
  for (const NodeVariant& node : all_node_types()) {
    const size_t outputs = std::max<size_t>(node_outputs(node).size(), 1);
    std::vector<SocketInfo> inputs = node_inputs(node);
    if (inputs.empty())
      inputs.push_back(SocketInfo{.name = "(none)",
                                  .type = SocketType::float_value,
                                  .doc = {},
                                  .implicit = Implicit::none,
                                  .has_value = false,
                                  .param = {}});  // a node without inputs still compiles
    for (const SocketInfo& input : inputs) {
      for (size_t o = 0; o < outputs; ++o) {
        const GraphDesc g = reaching_output(node, o, input.name);
        const graph_ops::CompileOutcome c = compile_and_check(g, kBase, assets);
        ++cases;
        EXPECT_TRUE(c.program) << describe(node, input.name) << " unlinked does not compile";
        EXPECT_EQ(c.problem, "") << describe(node, input.name) << " unlinked";
      }
    }
  }
  EXPECT_GT(cases, 100u);
}

TEST(GraphInputs, EveryInputOfEveryNodeCompilesFromEveryOutputThatFits) {
  AssetCache assets;
  const std::vector<NodeVariant> nodes = all_node_types();
  size_t cases = 0;
  for (const NodeVariant& node : nodes) {
    for (const SocketInfo& input : node_inputs(node)) {
      for (const NodeVariant& source : nodes) {
        for (const SocketDecl& output : node_outputs(source)) {
          GraphDesc g = reaching_output(node, 0, input.name);
          add(g, "src", source);
          link(g, "src", std::string(output.name), "n", std::string(input.name));
          const graph_ops::CompileOutcome c = compile_and_check(g, kBase, assets);
          const std::string what = std::string(node_type_name(source)) + "." + std::string(output.name) +
                                   " -> " + describe(node, input.name);
          ++cases;
          if (socket_converts(output.type, input.type)) {
            EXPECT_TRUE(c.program) << what << " does not compile";
          } else {
            // A link the editor refuses is named by the compiler, never lowered.
            EXPECT_FALSE(c.program) << what << " compiled across types";
            EXPECT_TRUE(check_link(g, "src", output.name, "n", input.name).has_value()) << what;
          }
          EXPECT_EQ(c.problem, "") << what;
        }
      }
    }
  }
  EXPECT_GT(cases, 1000u);
}

// The surface a one-closure graph resolves to at an ordinary hit.
std::vector<float> resolved_numbers(const ShaderProgram& program, float u = 0.5f) {
  static const graph_ops::TestHits hits;
  Material scratch;
  const ResolvedMaterial r = run_graph(program, hits.sp[0], u, scratch);
  return r.material ? material_numbers(*r.material) : std::vector<float>{};
}

// Every closure node left with all its inputs unlinked is the plain material of the
// same description: its documented defaults.
TEST(GraphInputs, AnUnlinkedClosureInputIsTheNodesOwnValue) {
  for_each_alternative<NodeVariant>([&]<class T>(std::type_identity<T>) {
    if constexpr (kIsClosure<T>) {
      const CompiledGraph c = compile(closure_graph(T{}), kBase);
      ASSERT_TRUE(c.program) << T::type_name;
      SceneDesc plain = one_sphere_scene(4, 4);
      plain.materials[0].data = T{};
      const CompileResult compiled = compile_scene(plain);
      ASSERT_TRUE(compiled.scene) << T::type_name;
      EXPECT_EQ(resolved_numbers(*c.program), material_numbers(compiled.scene->world->materials.at(0)))
          << T::type_name;
    }
  });
}

// The reported crash: a mix or add with one side unlinked. That side is black.
TEST(GraphInputs, AnUnlinkedSideOfAMixOrAddIsBlack) {
  for (const bool mix : {true, false}) {
    for (const char* linked : {"a", "b"}) {
      GraphDesc g;
      add(g, "d", DiffuseDesc{Color(0.5f)});
      add(g, "m", mix ? NodeVariant(MixClosureNode{}) : NodeVariant(AddClosureNode{}));
      add(g, "out", OutputNode{});
      link(g, "d", "closure", "m", linked);
      link(g, "m", "closure", "out", "surface");
      const CompiledGraph c = compile(g);
      ASSERT_TRUE(c.program) << c.errors.front();
      static const graph_ops::TestHits hits;
      bool saw_black = false, saw_diffuse = false;
      for (const float u : {0.1f, 0.9f}) {
        Material scratch;
        const ResolvedMaterial r = run_graph(*c.program, hits.sp[0], u, scratch);
        ASSERT_TRUE(r.material);
        if (const auto* unlit = std::get_if<UnlitMaterial>(r.material)) {
          EXPECT_EQ(std::get<ConstantTexture>(unlit->color).value, Color(0.f));
          saw_black = true;
        }
        saw_diffuse |= std::holds_alternative<DiffuseMaterial>(*r.material);
      }
      EXPECT_TRUE(saw_black && saw_diffuse) << (mix ? "mix" : "add") << " with " << linked << " linked";
    }
  }
  // Both sides unlinked: black whatever the sample.
  GraphDesc g;
  add(g, "m", MixClosureNode{});
  add(g, "out", OutputNode{});
  link(g, "m", "closure", "out", "surface");
  const CompiledGraph c = compile(g);
  ASSERT_TRUE(c.program) << c.errors.front();
  EXPECT_EQ(resolved_numbers(*c.program), std::vector<float>({0.f, 0.f, 0.f}));
}

// Sets the closure's valued input `index` (in parameter order) to `value`, splatted for colours.
struct SetValued {
  size_t index;
  float value;
  size_t seen = 0;
  template <class F>
  void operator()(const Param& p, F& field) {
    if (!socket_type_of(p.kind) || seen++ != index) return;
    if constexpr (std::is_same_v<F, float>) field = value;
    if constexpr (std::is_same_v<F, Vec3> || std::is_same_v<F, ColorInput>) field = Color(value);
  }
};

// Reads the first channel of the valued input `index` (in parameter order).
struct ReadValued {
  size_t index;
  size_t seen = 0;
  float value = 0.f;
  template <class F>
  void operator()(const Param& p, F& field) {
    if (!socket_type_of(p.kind) || seen++ != index) return;
    if constexpr (std::is_same_v<F, float>) value = field;
    if constexpr (std::is_same_v<F, Vec3>) value = field.x;
    if constexpr (std::is_same_v<F, ColorInput>) value = std::get<Color>(field).x;
  }
};

float clamped(const Param& p, float v, float fallback) {
  return std::isfinite(v) ? std::clamp(v, float(p.min), float(p.max)) : fallback;
}

// Every closure's valued inputs with their parameters and defaults, for the tests below.
template <class T>
void for_each_closure_input(auto&& f) {
  const std::vector<SocketInfo> inputs = node_inputs_of<T>();
  size_t valued = 0;
  for (const SocketInfo& s : inputs) {
    if (!s.has_value) continue;
    f(s, valued++);
  }
}

// A value node of 1e30, -1e30 or NaN linked into a closure's input gives the surface the
// closure has with that input set to the value kept to the ranges on the way (the value
// node's own, then the closure parameter's).
TEST(GraphInputs, LinkedClosureInputsAreClampedToTheirParameters) {
  const float kNan = std::numeric_limits<float>::quiet_NaN();
  const Param value_param = node_inputs_of<ValueNode>().at(0).param;
  size_t cases = 0;
  for_each_alternative<NodeVariant>([&]<class T>(std::type_identity<T>) {
    if constexpr (kIsClosure<T>) {
      for_each_closure_input<T>([&](const SocketInfo& s, size_t index) {
        for (const float v : {1e30f, -1e30f, kNan}) {
          GraphDesc linked = closure_graph(T{});
          add(linked, "v", ValueNode{v});
          link(linked, "v", "value", "surface", std::string(s.name));
          const CompiledGraph a = compile(linked, kBase);
          ASSERT_TRUE(a.program) << a.errors.front();
          const float through_value = clamped(value_param, v, ValueNode{}.value);
          T expected{};
          SetValued set{index, clamped(s.param, through_value, 0.f)};
          visit_params(expected, set);
          const CompiledGraph b = compile(closure_graph(expected), kBase);
          ASSERT_TRUE(b.program) << b.errors.front();
          const std::vector<float> got = resolved_numbers(*a.program);
          for (float x : got) EXPECT_TRUE(std::isfinite(x)) << T::type_name << "." << s.name << " from " << v;
          EXPECT_EQ(got, resolved_numbers(*b.program)) << T::type_name << "." << s.name << " from " << v;
          ++cases;
        }
      });
    }
  });
  EXPECT_GT(cases, 60u);
}

// At run time (a register fed by the hit), a value beyond the range is clamped and one
// that is not finite becomes the parameter's default, whatever arithmetic upstream made it.
TEST(GraphInputs, MaterialiseClampsRunTimeValuesAndReplacesNonFiniteOnesWithTheDefault) {
  const float kNan = std::numeric_limits<float>::quiet_NaN();
  const float kInf = std::numeric_limits<float>::infinity();
  static const graph_ops::TestHits hits;
  size_t cases = 0;
  for_each_alternative<NodeVariant>([&]<class T>(std::type_identity<T>) {
    if constexpr (kIsClosure<T>) {
      for_each_closure_input<T>([&](const SocketInfo& s, size_t index) {
        GraphDesc g = closure_graph(T{});
        add(g, "geo", GeometryNode{});
        link(g, "geo", "facing", "surface", std::string(s.name));
        const CompiledGraph c = compile(g, kBase);
        ASSERT_TRUE(c.program) << c.errors.front();
        ASSERT_EQ(c.program->leaves.size(), 1u);
        const uint16_t reg = c.program->leaves[0].inputs.at(index).reg;
        for (const float v : {1e30f, -1e30f, kNan, kInf, -kInf}) {
          ShaderRegisters registers;
          run_shader(*c.program, hits.sp[0], registers);
          registers[reg] = Vec3(v);
          Material scratch;
          const ResolvedMaterial r = pick_closure(*c.program, registers, 0.5f, scratch);
          ASSERT_TRUE(r.material);
          // The default is the node's documented one (a default-constructed node's input).
          T defaults{};
          ReadValued read{index};
          visit_params(defaults, read);
          const float fallback = read.value;
          T expected{};
          SetValued set{index, clamped(s.param, v, fallback)};
          visit_params(expected, set);
          const CompiledGraph e = compile(closure_graph(expected), kBase);
          ASSERT_TRUE(e.program);
          EXPECT_EQ(material_numbers(*r.material), resolved_numbers(*e.program))
              << T::type_name << "." << s.name << " at " << v;
          ++cases;
        }
      });
    }
  });
  EXPECT_GT(cases, 100u);
}

// Rendered: every closure with each valued input fed 1e30 gives finite pixels no brighter
// than its parameters allow (the reported images held values near 2e27).
TEST(GraphInputs, HugeLinkedValuesRenderFinite) {
  for_each_alternative<NodeVariant>([&]<class T>(std::type_identity<T>) {
    if constexpr (kIsClosure<T>) {
      GraphDesc g = closure_graph(T{});
      add(g, "v", ValueNode{1e30f});
      for_each_closure_input<T>(
          [&](const SocketInfo& s, size_t) { link(g, "v", "value", "surface", std::string(s.name)); });
      SceneDesc d = one_sphere_scene(8, 8);
      d.camera.look_from = Point3(0.f, 0.f, 4.f);
      d.materials[0].data = g;
      d.lights = {{"sun", DirectionalLightDesc{Vec3(0.f, 0.f, -1.f), Color(1.f), 3.f}}};
      const RgbImage img = render_scene(d, 2);
      ASSERT_EQ(img.pixels.size(), 64u) << T::type_name;
      if constexpr (std::is_same_v<T, EmissiveDesc>) {
        EXPECT_GT(img.at(4, 4).x, 1e6f) << "the sphere is seen, at the largest strength its parameter allows";
      }
      for (const Color& p : img.pixels)
        for (int k = 0; k < 3; ++k) {
          EXPECT_TRUE(std::isfinite(p[k])) << T::type_name;
          EXPECT_LE(p[k], 1e8f) << T::type_name << ": emission is at most 1e7 (strength) times 1 (colour)";
        }
    }
  });
}

// A node that cannot be lowered (a missing image) is reported, and nodes downstream of
// it (a closure reading it, a mix reading that closure) are still checked, never crash.
TEST(GraphInputs, AFailedNodeIsReportedAndItsUsersStillLower) {
  GraphDesc g;
  add(g, "img", ImageTextureNode{"missing.png"});
  add(g, "d", DiffuseDesc{ImageTextureDesc{"also_missing.png"}});
  add(g, "t", ToonDesc{});
  add(g, "m", MixClosureNode{});
  link(g, "img", "color", "t", "color");
  link(g, "d", "closure", "m", "a");
  link(g, "t", "closure", "m", "b");
  add_output(g, "m");
  const CompiledGraph c = compile(g, kBase);
  EXPECT_FALSE(c.program);
  const std::string all = joined(c.errors);
  EXPECT_NE(all.find("\"img\""), std::string::npos) << all;
  EXPECT_NE(all.find("\"d\""), std::string::npos) << all;
}

// A value or rgb node's own input can be linked like any other: it passes the value on.
TEST(GraphInputs, ValueAndRgbNodesPassALinkedInputOn) {
  GraphDesc g;
  add(g, "geo", GeometryNode{});
  add(g, "v", ValueNode{0.25f});
  link(g, "geo", "depth", "v", "value");
  SurfaceInteraction si;
  const ShadingPoint sp = test_point(si);
  EXPECT_EQ(socket_value(g, "v", "value", sp).x, sp.depth);
  GraphDesc h;
  add(h, "geo", GeometryNode{});
  add(h, "c", RgbNode{});
  link(h, "geo", "facing", "c", "color");
  EXPECT_NEAR(socket_value(h, "c", "color", sp).y, glm::dot(sp.ns, sp.wo), 1e-6f);
}

}  // namespace
}  // namespace inkray
