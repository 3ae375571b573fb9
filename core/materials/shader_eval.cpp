// The shader interpreter: one switch per instruction over a register file on the
// stack. Closure inputs are copied into a template of the chosen kind, so the path
// loop reads a graph's surface exactly as it reads a plain material.
#include "core/materials/shader_eval.h"

#include "core/math/color_space.h"
#include "core/math/hash.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

float safe_divide(float a, float b) { return b == 0.f ? 0.f : a / b; }

float math_op(ShaderMath op, float a, float b, float c) {
  switch (op) {
    case ShaderMath::add:
      return a + b;
    case ShaderMath::subtract:
      return a - b;
    case ShaderMath::multiply:
      return a * b;
    case ShaderMath::divide:
      return safe_divide(a, b);
    case ShaderMath::power: {
      // Blender's rule: a negative base takes only integer exponents.
      if (a >= 0.f) return std::pow(a, b);
      return b == std::floor(b) ? std::pow(a, b) : 0.f;
    }
    case ShaderMath::minimum:
      return std::min(a, b);
    case ShaderMath::maximum:
      return std::max(a, b);
    case ShaderMath::clamp:
      return std::clamp(a, std::min(b, c), std::max(b, c));
    case ShaderMath::smoothstep: {
      if (b == c) return a < b ? 0.f : 1.f;
      const float t = std::clamp((a - b) / (c - b), 0.f, 1.f);
      return t * t * (3.f - 2.f * t);
    }
    case ShaderMath::greater_than:
      return a > b ? 1.f : 0.f;
    case ShaderMath::less_than:
      return a < b ? 1.f : 0.f;
  }
  return 0.f;
}

Vec3 vector_op(ShaderVector op, const Vec3& a, const Vec3& b, float scale) {
  switch (op) {
    case ShaderVector::add:
      return a + b;
    case ShaderVector::subtract:
      return a - b;
    case ShaderVector::multiply:
      return a * b;
    case ShaderVector::dot:
      return Vec3(glm::dot(a, b));
    case ShaderVector::cross:
      return glm::cross(a, b);
    case ShaderVector::normalize: {
      const float len = glm::length(a);
      return len > 0.f ? a / len : Vec3(0.f);
    }
    case ShaderVector::length:
      return Vec3(glm::length(a));
    case ShaderVector::scale:
      return a * scale;
  }
  return Vec3(0.f);
}

Color image_lookup(const RgbImage& img, const std::vector<float>* alpha, Vec3 uvw, float* alpha_out) {
  const float x = (uvw.x - std::floor(uvw.x)) * float(img.width) - 0.5f;
  const float y = (1.f - (uvw.y - std::floor(uvw.y))) * float(img.height) - 0.5f;
  const float fx = x - std::floor(x), fy = y - std::floor(y);
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  auto wrap = [](int i, int n) { return ((i % n) + n) % n; };
  const int xs[2] = {wrap(x0, img.width), wrap(x0 + 1, img.width)};
  const int ys[2] = {wrap(y0, img.height), wrap(y0 + 1, img.height)};
  const float w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
  Color c(0.f);
  float a = 0.f;
  for (int k = 0; k < 4; ++k) {
    const size_t i = size_t(ys[k / 2]) * size_t(img.width) + size_t(xs[k % 2]);
    c += w[k] * img.pixels[i];
    if (alpha) a += w[k] * (*alpha)[i];
  }
  if (alpha_out) *alpha_out = alpha ? a : 1.f;
  return c;
}

float hash_to_unit(uint32_t v) { return u32_to_unit_float(hash_u32(v)); }

// An output override colour: registers are finite; lines and strokes take no negative colour.
Color input_color(const Vec3& v) { return glm::max(v, Vec3(0.f)); }

}  // namespace

bool instr_is_pure(ShaderOp op) {
  switch (op) {
    case ShaderOp::position:
    case ShaderOp::object_position:
    case ShaderOp::normal:
    case ShaderOp::true_normal:
    case ShaderOp::uv:
    case ShaderOp::incoming:
    case ShaderOp::facing:
    case ShaderOp::object_id:
    case ShaderOp::material_id:
    case ShaderOp::depth:
    case ShaderOp::random:
    case ShaderOp::n_dot_l:
    case ShaderOp::shadow:
    case ShaderOp::light_color:
    case ShaderOp::fresnel:
    case ShaderOp::layer_weight_fresnel:
    case ShaderOp::layer_weight_facing:
      return false;
    default:
      return true;
  }
}

Vec3 eval_instr(const ShaderProgram& program, const ShaderInstr& instr, const Vec3* r,
                const ShadingPoint& sp) {
  const auto in = [&](int i) -> const Vec3& { return r[instr.in[size_t(i)]]; };
  const auto x = [&](int i) { return r[instr.in[size_t(i)]].x; };
  switch (instr.op) {
    case ShaderOp::luminance:
      return Vec3(luminance(in(0)));
    case ShaderOp::mean:
      return Vec3((in(0).x + in(0).y + in(0).z) / 3.f);
    case ShaderOp::clamp01:
      return glm::clamp(in(0), Vec3(0.f), Vec3(1.f));
    case ShaderOp::math:
      return Vec3(math_op(ShaderMath(instr.mode), x(0), x(1), x(2)));
    case ShaderOp::map_range: {
      float t = safe_divide(x(0) - x(1), x(2) - x(1));
      if (instr.mode) t = std::clamp(t, 0.f, 1.f);
      return Vec3(x(3) + t * (x(4) - x(3)));
    }
    case ShaderOp::mix_color:
      return blend_colors(BlendMode(instr.mode), x(0), in(1), in(2));
    case ShaderOp::hsv_adjust:
      return hsv_adjust(in(4), x(0), x(1), x(2), x(3));
    // Graphs speak of hue in [0, 1], as Blender's nodes do; color_space.h in degrees.
    case ShaderOp::rgb_to_hsv: {
      const Color hsv = rgb_to_hsv(in(0));
      return Vec3(hsv.x / 360.f, hsv.y, hsv.z);
    }
    case ShaderOp::hsv_to_rgb: {
      const Vec3 h = in(0);
      return hsv_to_rgb(
          Color((h.x - std::floor(h.x)) * 360.f, std::clamp(h.y, 0.f, 1.f), std::max(h.z, 0.f)));
    }
    case ShaderOp::ramp:
      return ramp_eval(program.ramps[instr.aux], x(0), RampInterpolation(instr.mode));
    case ShaderOp::separate_x:
      return Vec3(in(0).x);
    case ShaderOp::separate_y:
      return Vec3(in(0).y);
    case ShaderOp::separate_z:
      return Vec3(in(0).z);
    case ShaderOp::combine:
      return Vec3(x(0), x(1), x(2));
    case ShaderOp::vector_math:
    case ShaderOp::vector_value:
      return vector_op(ShaderVector(instr.mode), in(0), in(1), x(2));
    case ShaderOp::position:
      return sp.si->p;
    case ShaderOp::object_position:
      return sp.p_object;
    case ShaderOp::normal:
      return sp.ns;
    case ShaderOp::true_normal:
      return sp.ng;
    case ShaderOp::uv:
      return Vec3(sp.si->uv, 0.f);
    case ShaderOp::incoming:
      return sp.wo;
    case ShaderOp::facing:
      return Vec3(std::max(0.f, glm::dot(sp.ns, sp.wo)));
    case ShaderOp::object_id:
      return Vec3(float(sp.object_id));
    case ShaderOp::material_id:
      return Vec3(float(sp.material_id));
    case ShaderOp::depth:
      return Vec3(sp.depth);
    case ShaderOp::random:
      return Vec3(hash_to_unit(sp.object_id * 0x9e3779b9u + 0x5bd1e995u));
    case ShaderOp::n_dot_l:
      return Vec3(sp.n_dot_l);
    case ShaderOp::shadow:
      return Vec3(sp.shadow);
    case ShaderOp::light_color:
      return sp.light_color;
    case ShaderOp::fresnel:
      return Vec3(fresnel_factor(x(0), glm::dot(sp.ns, sp.wo)));
    case ShaderOp::layer_weight_fresnel:
      return Vec3(layer_weight(x(0), glm::dot(sp.ns, sp.wo)).fresnel);
    case ShaderOp::layer_weight_facing:
      return Vec3(layer_weight(x(0), glm::dot(sp.ns, sp.wo)).facing);
    case ShaderOp::image_color:
    case ShaderOp::image_alpha: {
      const ImageChannels& image = program.images[instr.aux];
      float alpha = 1.f;
      const Color c = image_lookup(*image.color, image.alpha.get(), in(0), &alpha);
      return instr.op == ShaderOp::image_color ? c : Vec3(alpha);
    }
    case ShaderOp::checker_color:
    case ShaderOp::checker_fac: {
      const Vec3 p = in(0) * x(3);
      // A small offset keeps faces at integer coordinates (uv 0 and 1) off the square edges.
      const int parity =
          int(std::floor(p.x + 1e-5f)) + int(std::floor(p.y + 1e-5f)) + int(std::floor(p.z + 1e-5f));
      const bool odd = parity & 1;
      if (instr.op == ShaderOp::checker_fac) return Vec3(odd ? 1.f : 0.f);
      return odd ? in(2) : in(1);
    }
    case ShaderOp::noise_fac:
    case ShaderOp::noise_color: {
      const NoiseResult n = noise_texture(in(0), NoiseKind(instr.mode), x(1), int(instr.aux), x(2), x(3));
      return instr.op == ShaderOp::noise_fac ? Vec3(n.fac) : n.color;
    }
    case ShaderOp::voronoi_distance:
    case ShaderOp::voronoi_color:
    case ShaderOp::voronoi_position: {
      const VoronoiResult v = voronoi_texture(in(0), x(1), x(2));
      if (instr.op == ShaderOp::voronoi_distance) return Vec3(v.distance);
      return instr.op == ShaderOp::voronoi_color ? v.color : v.position;
    }
  }
  return Vec3(0.f);
}

void run_shader(const ShaderProgram& program, const ShadingPoint& sp, ShaderRegisters& registers) {
  std::copy(program.constants.begin(), program.constants.end(), registers.begin());
  for (const ShaderInstr& instr : program.code) {
    const Vec3 v = eval_instr(program, instr, registers.data(), sp);
    // Non-finite values (a division by a tiny number, a huge power) become 0 rather than NaN pixels.
    registers[instr.out] =
        Vec3(std::isfinite(v.x) ? v.x : 0.f, std::isfinite(v.y) ? v.y : 0.f, std::isfinite(v.z) ? v.z : 0.f);
  }
}

// Each input is set by its own setter, found by socket name when the graph was
// compiled; the black stand-in of an unlinked closure input has none and is its
// template as it is.
void materialise(const ClosureLeaf& leaf, const Vec3* r, Material& scratch) {
  scratch = leaf.tmpl;
  for (const ClosureInput& in : leaf.inputs) {
    const ClosureInputBounds& b = in.bounds;
    const Vec3& v = r[in.reg];
    Vec3 value;
    for (int c = 0; c < 3; ++c)
      value[c] = std::isfinite(v[c]) ? std::clamp(v[c], b.min, b.max) : b.fallback[c];
    in.set(scratch, value);
  }
}

ResolvedMaterial run_graph(const ShaderProgram& program, const ShadingPoint& sp, float u, Material& scratch) {
  // A graph with no instruction left (all folded) reads its constants where they are.
  if (program.code.empty()) return pick_closure(program, program.constants.data(), u, scratch);
  ShaderRegisters registers;
  run_shader(program, sp, registers);
  return pick_closure(program, registers, u, scratch);
}

ResolvedMaterial pick_closure(const ShaderProgram& program, const Vec3* registers, float u,
                              Material& scratch) {
  if (program.closures.empty()) return {};
  float weight = 1.f;
  const ClosureNode* node = &program.closures[0];
  // Children have larger indices than their parents, so the walk ends.
  for (size_t steps = 0; steps < program.closures.size(); ++steps) {
    switch (node->kind) {
      case ClosureNode::Kind::leaf: {
        const ClosureLeaf& leaf = program.leaves[node->leaf];
        if (leaf.constant) return {&leaf.tmpl, weight};
        materialise(leaf, registers, scratch);
        return {&scratch, weight};
      }
      case ClosureNode::Kind::mix: {
        const float p = std::clamp(registers[node->fac].x, 0.f, 1.f);
        if (u < p) {
          u = std::min(u / p, kOneMinusEpsilon);
          node = &program.closures[node->b];
        } else {
          u = std::min((u - p) / (1.f - p), kOneMinusEpsilon);
          node = &program.closures[node->a];
        }
        break;
      }
      case ClosureNode::Kind::add:
        weight *= 2.f;
        if (u < 0.5f) {
          u = std::min(2.f * u, kOneMinusEpsilon);
          node = &program.closures[node->a];
        } else {
          u = std::min(2.f * u - 1.f, kOneMinusEpsilon);
          node = &program.closures[node->b];
        }
        break;
    }
  }
  return {};
}

SurfaceOverrides shader_overrides(const ShaderProgram& program, const ShadingPoint& sp) {
  SurfaceOverrides out;
  if (program.line_color == kNoRegister && program.line_width == kNoRegister &&
      program.stroke_color == kNoRegister)
    return out;
  ShaderRegisters registers;
  run_shader(program, sp, registers);
  if (program.line_color != kNoRegister) out.line_color = input_color(registers[program.line_color]);
  if (program.line_width != kNoRegister) out.line_width = std::max(registers[program.line_width].x, 0.f);
  if (program.stroke_color != kNoRegister) out.stroke_color = input_color(registers[program.stroke_color]);
  return out;
}

}  // namespace inkray
