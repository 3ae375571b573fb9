// Building material graphs in tests: nodes by id, links by socket name, and a
// harness that compiles a graph and reads the value a socket carries at a hit.
#pragma once

#include "core/compiler/compile_graph.h"
#include "core/materials/shader_eval.h"

#include <gtest/gtest.h>

#include <string>

namespace inkray::testing {

inline void add(GraphDesc& g, std::string id, NodeVariant node) {
  g.nodes.push_back({std::move(id), std::move(node)});
}
inline void link(GraphDesc& g, std::string from, std::string output, std::string to, std::string input) {
  g.links.push_back({std::move(from), std::move(output), std::move(to), std::move(input)});
}

// The output node "out", with the closure node `surface` wired to it as the material.
inline void add_output(GraphDesc& g, const std::string& surface) {
  add(g, "out", OutputNode{});
  link(g, surface, "closure", "out", "surface");
}

// A plain closure as a graph: the closure node wired to an output.
template <class Closure>
GraphDesc closure_graph(const Closure& closure) {
  GraphDesc g;
  add(g, "surface", closure);
  add_output(g, "surface");
  return g;
}

struct CompiledGraph {
  std::shared_ptr<const ShaderProgram> program;
  std::vector<std::string> errors;
};
inline CompiledGraph compile(const GraphDesc& g, const std::filesystem::path& base = ".") {
  AssetCache assets;
  CompiledGraph c;
  c.program = compile_graph(g, base, assets, c.errors);
  return c;
}

// The raw value (before any closure clamps it) of `node`'s output `output` at sp:
// the socket is wired into an unlit surface's colour and its register read back.
inline Vec3 socket_value(GraphDesc g, const std::string& node, const std::string& output,
                         const ShadingPoint& sp, const std::filesystem::path& base = ".") {
  add(g, "probe_surface", UnlitDesc{});
  add(g, "probe_out", OutputNode{});
  link(g, node, output, "probe_surface", "color");
  link(g, "probe_surface", "closure", "probe_out", "surface");
  const CompiledGraph c = compile(g, base);
  EXPECT_TRUE(c.program) << (c.errors.empty() ? "" : c.errors.front());
  if (!c.program) return Vec3(-999.f);
  ShaderRegisters registers;
  run_shader(*c.program, sp, registers);
  return registers[c.program->leaves.at(0).inputs.at(0).reg];
}

// A hit for node tests: a point facing +z seen from +z.
inline ShadingPoint test_point(SurfaceInteraction& si) {
  si.p = Point3(1.f, 2.f, 3.f);
  si.ng = si.ns = Normal3(0.f, 0.f, 1.f);
  si.uv = Vec2(0.25f, 0.75f);
  ShadingPoint sp = shading_point(si, glm::normalize(Vec3(0.f, 0.6f, 0.8f)));
  sp.p_object = Point3(-0.5f, 0.25f, 2.f);  // the object moved: textures read this
  sp.depth = 7.f;
  sp.object_id = 3;
  sp.material_id = 5;
  sp.n_dot_l = 0.4f;
  sp.shadow = 1.f;
  sp.light_color = Color(1.f, 0.5f, 0.25f);
  return sp;
}

}  // namespace inkray::testing
