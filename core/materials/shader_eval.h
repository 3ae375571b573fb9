// Running a compiled material graph (shader_program.h) at a shading point, and
// turning the closure it picks into the Material the path loop reads.
#pragma once

#include "core/materials/material.h"

#include <array>
#include <string_view>

namespace inkray {

using ShaderRegisters = std::array<Vec3, kMaxShaderRegisters>;

// One instruction's value from the registers it reads. Pure instructions (all but
// those that read the hit) ignore sp, which lets the compiler fold constants with it.
Vec3 eval_instr(const ShaderProgram& program, const ShaderInstr& instr, const Vec3* registers,
                const ShadingPoint& sp);
// Whether an instruction's value depends on nothing but its inputs.
bool instr_is_pure(ShaderOp op);

// Fills the registers: constants, then every instruction in order.
void run_shader(const ShaderProgram& program, const ShadingPoint& sp, ShaderRegisters& registers);
// Walks the closure tree with u (rescaled at each choice) and returns the chosen
// surface: a constant leaf's template itself, else the template written to
// `scratch` with its inputs taken from the registers.
ResolvedMaterial pick_closure(const ShaderProgram& program, const Vec3* registers, float u,
                              Material& scratch);
inline ResolvedMaterial pick_closure(const ShaderProgram& program, const ShaderRegisters& registers, float u,
                                     Material& scratch) {
  return pick_closure(program, registers.data(), u, scratch);
}
// Copies the leaf's template into `out` and sets its inputs from the registers through
// their setters, each clamped to its parameter's hard range and a non-finite one
// replaced by the default (ClosureInputBounds); a leaf without inputs is its template.
// The compiler uses it to fill constant leaves.
void materialise(const ClosureLeaf& leaf, const Vec3* registers, Material& out);
// Runs the program if it has code and picks the closure: what resolve_material does for a graph.
ResolvedMaterial run_graph(const ShaderProgram& program, const ShadingPoint& sp, float u, Material& scratch);
// The output node's line and stroke overrides at a hit.
SurfaceOverrides shader_overrides(const ShaderProgram& program, const ShadingPoint& sp);

}  // namespace inkray
