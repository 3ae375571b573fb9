// The operations of the math and vector math nodes, declared once: the document's
// MathNode and VectorMathNode hold them (JSON names in graph_nodes.h, in this order)
// and the compiled program carries them as an instruction's mode (shader_program.h).
#pragma once

namespace inkray {

enum class ShaderMath {
  add,
  subtract,
  multiply,
  divide,
  power,
  minimum,
  maximum,
  clamp,
  smoothstep,
  greater_than,
  less_than
};
enum class ShaderVector { add, subtract, multiply, dot, cross, normalize, length, scale };

}  // namespace inkray
