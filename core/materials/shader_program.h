// A material graph compiled to a flat program (docs/architecture.md, "Material
// graphs"): straight-line instructions over a register file of three floats each,
// run once per shading point with no allocation and no virtual call, then a small
// closure tree that picks the surface for the sample. Built by
// compiler/compile_graph; run by resolve_material (material.h).
#pragma once

#include "core/image/rgb_image.h"
#include "core/materials/procedural.h"
#include "core/materials/shader_ops.h"

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace inkray {

struct ClosureLeaf;  // material.h: a closure's compiled template and where its inputs are

// What a closure accepts at one valued input (docs/architecture.md, "Material graphs"):
// a linked value is clamped to the parameter's hard range per channel, and a value
// that is not finite becomes the parameter's default.
struct ClosureInputBounds {
  float min = 0.f, max = 0.f;
  Vec3 fallback{0.f};
};

enum class ShaderOp : uint8_t {
  // conversions between socket types
  luminance,
  mean,
  clamp01,
  // math (mode: ShaderMath), map_range (mode 1: clamped)
  math,
  map_range,
  // colour
  mix_color,
  hsv_adjust,
  rgb_to_hsv,
  hsv_to_rgb,
  ramp,
  separate_x,
  separate_y,
  separate_z,
  combine,
  // vectors (mode: ShaderVector); vector_value is the float result of dot and length
  vector_math,
  vector_value,
  // the hit
  position,
  object_position,
  normal,
  true_normal,
  uv,
  incoming,
  facing,
  object_id,
  material_id,
  depth,
  random,
  n_dot_l,
  shadow,
  light_color,
  fresnel,
  layer_weight_fresnel,
  layer_weight_facing,
  // textures (aux: the image, ramp or none; mode: noise kind)
  image_color,
  image_alpha,
  checker_color,
  checker_fac,
  noise_fac,
  noise_color,
  voronoi_distance,
  voronoi_color,
  voronoi_position,
};

inline constexpr int kMaxShaderInputs = 5;
inline constexpr int kMaxShaderRegisters = 256;  // 3 KB of stack per evaluation
inline constexpr uint16_t kNoRegister = UINT16_MAX;
inline constexpr size_t kMaxClosures = 4096;  // closure-tree nodes (indices are 16-bit)

struct ShaderInstr {
  ShaderOp op;
  uint8_t mode = 0;                             // the node's choice (operation, blend, noise kind)
  uint16_t out = 0;                             // register written
  std::array<uint16_t, kMaxShaderInputs> in{};  // registers read
  uint32_t aux = 0;                             // index into the program's images or ramps; octaves for noise
};

// Mixes and adds over leaves; node 0 is the root. Children precede their parents' use.
struct ClosureNode {
  enum class Kind : uint8_t { leaf, mix, add } kind = Kind::leaf;
  uint16_t leaf = 0;           // for leaf
  uint16_t fac = kNoRegister;  // for mix: the register of b's weight
  uint16_t a = 0, b = 0;       // for mix and add: child nodes
};

struct ImageChannels {
  std::shared_ptr<const RgbImage> color;
  std::shared_ptr<const std::vector<float>> alpha;  // null: alpha 1
};

struct ShaderProgram {
  std::vector<Vec3> constants;  // registers [0, constants.size()) start with these
  std::vector<ShaderInstr> code;
  int register_count = 0;
  std::vector<ClosureLeaf> leaves;
  std::vector<ClosureNode> closures;  // empty: the graph has no surface (renders black)
  std::vector<ImageChannels> images;
  std::vector<std::vector<RampStop>> ramps;  // sorted by position
  uint16_t line_color = kNoRegister;         // output overrides, kNoRegister when unlinked
  uint16_t line_width = kNoRegister;
  uint16_t stroke_color = kNoRegister;
  bool uses_light = false;  // the light inputs must be gathered before running
  // Some surface may let outline-finding rays through (a mirror, glass, transparency):
  // without one, outlines see the graph's surface without running it.
  bool lines_pass_through = false;
  size_t nodes_in_graph = 0, nodes_run = 0;  // for tests and the compile bench: pruning and folding
};

}  // namespace inkray
