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
// Walks the closure tree with u (rescaled at each choice) and writes the chosen
// surface, its inputs taken from the registers, to `scratch`.
ResolvedMaterial pick_closure(const ShaderProgram& program, const ShaderRegisters& registers, float u,
                              Material& scratch);
// The output node's line and stroke overrides at a hit.
SurfaceOverrides shader_overrides(const ShaderProgram& program, const ShadingPoint& sp);

// The order of each closure kind's valued inputs, as the graph compiler stores
// them in ClosureLeaf::inputs: the names of the description's parameter list that
// are sockets. Checked against material_desc.h by tests/materials/shader_eval_test.
inline constexpr std::array<std::string_view, 12> kToonClosureInputs = {
    "color",        "shadow_color", "threshold", "softness",  "ramp_near",  "ramp_far",
    "specular_color", "specular_size", "shininess", "rim_color", "rim_width", "rim_threshold"};

}  // namespace inkray
