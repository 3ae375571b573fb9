// inkray-bench-graphs: what a material graph costs. Renders each material kind
// as a plain material and as the equivalent one-node graph (same pixels, see
// tests/integrator/graph_render_test.cpp) and prints their times; then a
// facing-ratio ramp graph against the plain toon it stands beside; then how long
// compiling a 200-node graph takes. Medians of interleaved runs.
#include "core/compiler/compile.h"
#include "core/compiler/compile_graph.h"
#include "core/render/batch_render.h"
#include "bench/bench_stats.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using namespace inkray;
using Clock = std::chrono::steady_clock;

using bench::median;

SceneDesc stage(const MaterialVariant& ball) {
  SceneDesc d;
  d.render.width = 320;
  d.render.height = 240;
  d.render.max_depth = 8;
  d.camera.look_from = Point3(0.f, 1.2f, 5.f);
  d.camera.look_at = Point3(0.f, 0.8f, 0.f);
  d.materials = {{"floor", DiffuseDesc{Color(0.6f)}, {}}, {"ball", ball, {}}};
  ObjectDesc floor;
  floor.name = "floor";
  floor.material = "floor";
  floor.shape = QuadDesc{Point3(-6.f, 0.f, -6.f), Vec3(0.f, 0.f, 12.f), Vec3(12.f, 0.f, 0.f)};
  ObjectDesc ball_object;
  ball_object.name = "ball";
  ball_object.material = "ball";
  ball_object.shape = SphereDesc{Point3(0.f, 1.f, 0.f), 1.f};
  d.objects = {floor, ball_object};
  d.lights = {{"sun", DirectionalLightDesc{Vec3(-0.5f, -1.f, -0.4f), Color(1.f), 3.f}},
              {"lamp", PointLightDesc{Point3(-3.f, 3.f, 3.f), Color(1.f), 20.f}}};
  d.environment = GradientEnvironmentDesc{};
  return d;
}

template <class Closure>
GraphDesc one_node_graph(const Closure& c) {
  GraphDesc g;
  g.nodes = {{"surface", c}, {"out", OutputNode{}}};
  g.links = {{"surface", "closure", "out", "surface"}};
  return g;
}

double render_seconds(const SceneDesc& d, int spp, int threads) {
  const CompileResult c = compile_scene(d);
  if (!c.scene) {
    std::fprintf(stderr, "inkray-bench-graphs: %s\n", c.errors.front().c_str());
    std::exit(1);
  }
  RenderSession session(threads);
  session.set_scene(c.scene);
  const auto t0 = Clock::now();
  render_batch(session, {spp, 0.0});
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

void row(const char* name, const SceneDesc& plain, const SceneDesc& graph, int spp, int runs, int threads) {
  std::vector<double> a, b, ratio;
  for (int r = 0; r < runs; ++r) {  // interleaved, so drifts in the machine's speed hit both
    a.push_back(render_seconds(plain, spp, threads));
    b.push_back(render_seconds(graph, spp, threads));
    ratio.push_back(b.back() / a.back());
  }
  std::printf("%-28s %10.3f %10.3f %9.3f\n", name, median(a), median(b), median(ratio));
}

GraphDesc chain_graph(int nodes) {
  GraphDesc g;
  g.nodes.push_back({"geo", GeometryNode{}});
  std::string last = "geo", output = "facing";
  for (int i = 0; i < nodes - 4; ++i) {
    const std::string id = "n" + std::to_string(i);
    // Alternate maths and colour work; every node depends on the hit, so none folds away.
    if (i % 4 == 3) {
      g.nodes.push_back({id, ColorRampNode{}});
      g.links.push_back({last, output, id, "fac"});
      output = "color";
    } else {
      g.nodes.push_back({id, MathNode{MathOp(i % 9), false, 0.5f, 0.7f, 1.f}});
      g.links.push_back({last, output, id, "a"});
      output = "value";
    }
    last = id;
  }
  g.nodes.push_back({"toon", ToonDesc{}});
  g.nodes.push_back({"noise", NoiseNode{}});
  g.nodes.push_back({"out", OutputNode{}});
  g.links.push_back({last, output, "toon", "color"});
  g.links.push_back({"noise", "fac", "toon", "threshold"});
  g.links.push_back({"toon", "closure", "out", "surface"});
  return g;
}

}  // namespace

int main(int argc, char** argv) {
  const int spp = argc > 1 ? std::atoi(argv[1]) : 16;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
  const int threads = 2;
  std::printf("320x240, %d spp, %d threads, median of %d interleaved runs\n", spp, threads, runs);
  std::printf("%-28s %10s %10s %9s\n", "material", "plain s", "graph s", "graph/plain");
  ToonDesc toon;
  toon.rim = true;
  const std::vector<std::pair<const char*, MaterialVariant>> kinds = {
      {"diffuse", DiffuseDesc{}},         {"conductor (rough 0.3)", ConductorDesc{Color(0.9f), 0.3f}},
      {"dielectric", DielectricDesc{}},   {"unlit", UnlitDesc{}},
      {"transparent", TransparentDesc{}}, {"toon (bands, rim)", toon}};
  for (const auto& [name, plain] : kinds) {
    SceneDesc a = stage(plain), b = a;
    std::visit(
        [&]<class T>(const T& m) {
          if constexpr (std::is_constructible_v<NodeVariant, T>) b.materials[1].data = one_node_graph(m);
        },
        plain);
    row(name, a, b, spp, runs, threads);
  }
  // A real look: colour from a facing-ratio ramp, against the plain toon of one colour.
  GraphDesc look = one_node_graph(ToonDesc{});
  look.nodes.push_back({"geo", GeometryNode{}});
  look.nodes.push_back({"ramp", ColorRampNode{}});
  look.links.push_back({"geo", "facing", "ramp", "fac"});
  look.links.push_back({"ramp", "color", "surface", "color"});
  row("toon + facing ramp (4 nodes)", stage(ToonDesc{}), stage(look), spp, runs, threads);
  // The same with the light inputs read (one more shadow ray per hit).
  GraphDesc lit = look;
  lit.nodes.push_back({"light", LightInputNode{}});
  lit.links[1] = {"light", "n_dot_l", "ramp", "fac"};
  row("toon + light-input ramp", stage(ToonDesc{}), stage(lit), spp, runs, threads);

  // Compiling: a 200-node graph, all of it live.
  const GraphDesc big = chain_graph(200);
  std::vector<double> times;
  size_t instructions = 0;
  int registers = 0;
  for (int r = 0; r < 200; ++r) {
    AssetCache assets;
    std::vector<std::string> errors;
    const auto t0 = Clock::now();
    const auto program = compile_graph(big, ".", assets, errors);
    times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    if (!program) {
      std::fprintf(stderr, "inkray-bench-graphs: %s\n", errors.front().c_str());
      return 1;
    }
    instructions = program->code.size();
    registers = program->register_count;
  }
  std::printf(
      "\ncompile a %zu-node graph: median %.3f ms, max %.3f ms over %zu runs (%zu instructions, %d "
      "registers)\n",
      big.nodes.size(), median(times), *std::max_element(times.begin(), times.end()), times.size(),
      instructions, registers);
  return 0;
}
