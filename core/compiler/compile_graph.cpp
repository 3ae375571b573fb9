// Graph lowering, once graph_checks has passed the whole graph: the nodes that
// reach the output in dependency order, one instruction per output socket, into
// virtual registers; then constant folding, dead-code removal and register
// allocation turn them into the program.
#include "core/compiler/compile_graph.h"

#include "core/compiler/closure_inputs.h"
#include "core/compiler/graph_checks.h"
#include "core/materials/shader_eval.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace inkray {
namespace {

using VReg = uint32_t;
struct Value {
  VReg reg = 0;
  SocketType type = SocketType::float_value;
};

struct IrInstr {
  ShaderInstr instr;  // in and out hold virtual registers here
  std::array<VReg, kMaxShaderInputs> in{};
  VReg out = 0;
  int inputs = 0;
};

class Lowering {
 public:
  Lowering(const GraphDesc& g, const CheckedGraph& c, const std::filesystem::path& base, AssetCache& assets,
           std::vector<std::string>& errors)
      : g_(g), c_(c), base_(base), assets_(assets), errors_(errors) {}

  std::shared_ptr<const ShaderProgram> run();

 private:
  VReg constant(Vec3 v) {
    // Registers never hold a non-finite value (and NaN would break the map's ordering).
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(v[c])) v[c] = 0.f;
    const auto key = std::array<float, 3>{v.x, v.y, v.z};
    if (const auto it = constant_regs_.find(key); it != constant_regs_.end()) return it->second;
    const VReg r = new_reg();
    is_constant_[r] = true;
    value_[r] = v;
    constant_regs_[key] = r;
    return r;
  }
  VReg new_reg() {
    is_constant_.push_back(false);
    value_.emplace_back(0.f);
    return VReg(is_constant_.size() - 1);
  }
  VReg emit(ShaderOp op, std::initializer_list<VReg> in, uint8_t mode = 0, uint32_t aux = 0) {
    IrInstr ir;
    ir.instr.op = op;
    ir.instr.mode = mode;
    ir.instr.aux = aux;
    ir.inputs = int(in.size());
    std::copy(in.begin(), in.end(), ir.in.begin());
    ir.out = new_reg();
    code_.push_back(ir);
    return ir.out;
  }
  // The register holding v as the type an input expects (graph_sockets.h conversions).
  VReg convert(Value v, SocketType to) {
    if (v.type == to || to == SocketType::closure) return v.reg;
    if (to == SocketType::float_value && v.type == SocketType::color)
      return emit(ShaderOp::luminance, {v.reg});
    if (to == SocketType::float_value && v.type == SocketType::vector) return emit(ShaderOp::mean, {v.reg});
    return v.reg;  // floats are stored splatted; colours and vectors share a layout
  }
  VReg implicit(Implicit kind) {
    VReg& cached = kind == Implicit::uv ? uv_ : position_;
    if (cached == kNone) cached = emit(kind == Implicit::uv ? ShaderOp::uv : ShaderOp::object_position, {});
    return cached;
  }
  // The value of node i's input `index`: its link, else its parameter's constant.
  template <class T>
  VReg input(size_t node, const T& desc, size_t index);
  template <class T>
  ClosureInputBounds bounds(size_t node, const T& desc, size_t index);
  void lower_node(size_t node);
  void stand_in(size_t node);
  uint32_t black_leaf();
  std::optional<VReg> closure_input(size_t node, std::string_view name);
  bool output_linked(size_t node, std::string_view output) const {
    for (const GraphLinkDesc& l : g_.links)
      if (l.from == g_.nodes[node].id && l.output == output) return true;
    return false;
  }
  VReg color_input_texture(size_t node, const ColorInput& in);
  void fold();
  void remove_dead();
  std::shared_ptr<ShaderProgram> allocate();
  void fail(size_t node, const std::string& what) { errors_.push_back(node_label(g_, node) + ": " + what); }

  static constexpr VReg kNone = UINT32_MAX;
  const GraphDesc& g_;
  const CheckedGraph& c_;
  const std::filesystem::path& base_;
  AssetCache& assets_;
  std::vector<std::string>& errors_;

  std::vector<bool> is_constant_;
  std::vector<Vec3> value_;
  std::map<std::array<float, 3>, VReg> constant_regs_;
  std::vector<IrInstr> code_;
  VReg uv_ = kNone, position_ = kNone;
  std::map<std::pair<size_t, size_t>, Value> outputs_;  // (node, output socket) -> value
  std::map<size_t, uint32_t> closure_of_;               // closure node index -> ClosureNode index
  std::vector<ClosureNode> closures_;
  std::vector<ClosureLeaf> leaves_;
  std::vector<std::vector<VReg>> leaf_inputs_;
  std::vector<VReg> mix_fac_;  // per ClosureNode: its fac register, or kNone
  std::shared_ptr<ShaderProgram> program_ = std::make_shared<ShaderProgram>();
  VReg line_color_ = kNone, line_width_ = kNone, stroke_color_ = kNone;
  size_t run_nodes_ = 0;
};

// The valued parameters of a node in list order: each one's constant, and the
// texture a closure node's colour input holds instead of a constant, if any.
struct ValuedInputs {
  std::vector<Vec3> constants;
  std::vector<const ColorInput*> textures;
  std::vector<Param> params;
  template <class F>
  void operator()(const Param& p, const F& field) {
    if (!socket_type_of(p.kind)) return;
    params.push_back(p);
    const ColorInput* texture = nullptr;
    Vec3 value(0.f);
    if constexpr (std::is_same_v<F, float>) {
      value = Vec3(field);
    } else if constexpr (std::is_same_v<F, Vec3>) {
      value = field;
    } else if constexpr (std::is_same_v<F, ColorInput>) {
      if (const Color* c = std::get_if<Color>(&field)) {
        value = *c;
      } else {
        texture = &field;
      }
    }
    constants.push_back(value);
    textures.push_back(texture);
  }
};

// A parameter's hard range as floats (an infinite bound stays finite: registers hold finite values).
std::pair<float, float> float_range(const Param& p) {
  constexpr double kMax = std::numeric_limits<float>::max();
  return {float(std::clamp(p.min, -kMax, kMax)), float(std::clamp(p.max, -kMax, kMax))};
}

// A value within the parameter's hard range, channel by channel (a number's three
// channels are one splatted value); a channel that is not finite takes the default's.
Vec3 within_range(const Param& p, const Vec3& v, const Vec3& fallback) {
  const auto [lo, hi] = float_range(p);
  Vec3 out;
  for (int c = 0; c < 3; ++c) out[c] = std::isfinite(v[c]) ? std::clamp(v[c], lo, hi) : fallback[c];
  return out;
}

template <class T>
ValuedInputs valued_inputs_of(const T& desc) {
  ValuedInputs valued;
  visit_params(desc, valued);
  return valued;
}

template <class T>
VReg Lowering::input(size_t node, const T& desc, size_t index) {
  const SocketInfo& socket = c_.inputs[node][index];
  if (const auto& e = c_.incoming[node][index]) {
    const auto it = outputs_.find({e->from, e->output});
    if (it == outputs_.end()) return constant(Vec3(0.f));  // stand_in gives every output a value
    return convert(it->second, socket.type);
  }
  if (!socket.has_value) {
    if (socket.implicit != Implicit::none) return implicit(socket.implicit);
    return constant(Vec3(socket.type == SocketType::float_value ? 1.f : 0.f));
  }
  // Unlinked: the node's own value, kept to the parameter's range like a typed value
  // in the editor (a description built in code may hold anything).
  const ValuedInputs valued = valued_inputs_of(desc);
  if (valued.textures[index]) return color_input_texture(node, *valued.textures[index]);
  const ValuedInputs defaults = valued_inputs_of(T{});
  return constant(within_range(valued.params[index], valued.constants[index], defaults.constants[index]));
}

// A closure's input `index`: linked, or a constant, it is kept to the parameter's hard
// range; an unlinked texture only non-negative (an HDR texel may exceed a colour's range).
template <class T>
ClosureInputBounds Lowering::bounds(size_t node, const T& desc, size_t index) {
  const ValuedInputs defaults = valued_inputs_of(T{});
  const Param& p = defaults.params[index];
  const auto [lo, hi] = float_range(p);
  ClosureInputBounds b{lo, hi, within_range(p, defaults.constants[index], Vec3(std::max(lo, 0.f)))};
  if (!c_.incoming[node][index] && valued_inputs_of(desc).textures[index])
    b.min = 0.f, b.max = std::numeric_limits<float>::max();
  return b;
}

// An unlinked side of a mix or add: a black surface that ends the path. It has no
// inputs, so materialise leaves its template as it is.
uint32_t Lowering::black_leaf() {
  leaves_.push_back({UnlitMaterial{ConstantTexture{Color(0.f)}}, {}, true});
  leaf_inputs_.emplace_back();
  closures_.push_back({ClosureNode::Kind::leaf, uint16_t(leaves_.size() - 1)});
  mix_fac_.push_back(kNone);
  return uint32_t(closures_.size() - 1);
}

// A node that failed (its message is out) still gives its outputs values, so the nodes
// downstream are lowered and report their own problems: zeros, and a black surface.
void Lowering::stand_in(size_t node) {
  const auto outs = node_outputs(g_.nodes[node].data);
  for (size_t k = 0; k < outs.size(); ++k) {
    if (outs[k].type == SocketType::closure) {
      if (!closure_of_.count(node)) closure_of_[node] = black_leaf();
    } else if (!outputs_.count({node, k})) {
      outputs_[{node, k}] = Value{constant(Vec3(0.f)), outs[k].type};
    }
  }
}

VReg Lowering::color_input_texture(size_t node, const ColorInput& in) {
  if (const auto* ch = std::get_if<CheckerTextureDesc>(&in))
    return emit(ShaderOp::checker_color,
                {implicit(Implicit::uv), constant(ch->even), constant(ch->odd), constant(Vec3(ch->scale))});
  const auto& img = std::get<ImageTextureDesc>(in);
  std::string error;
  auto image = assets_.image(base_ / img.path, img.srgb, &error);
  if (!image) {
    fail(node, error);
    return constant(Vec3(0.f));
  }
  program_->images.push_back({std::move(image), nullptr});
  const VReg texel =
      emit(ShaderOp::image_color, {implicit(Implicit::uv)}, 0, uint32_t(program_->images.size() - 1));
  if (img.scale == Color(1.f)) return texel;
  return emit(ShaderOp::vector_math, {texel, constant(img.scale), constant(Vec3(1.f))},
              uint8_t(ShaderVector::multiply));
}

std::optional<VReg> Lowering::closure_input(size_t node, std::string_view name) {
  const auto& ins = c_.inputs[node];
  for (size_t i = 0; i < ins.size(); ++i) {
    if (ins[i].name != name) continue;
    if (const auto& e = c_.incoming[node][i]) {
      const auto it = closure_of_.find(e->from);
      if (it != closure_of_.end()) return it->second;
    }
    return std::nullopt;
  }
  return std::nullopt;
}

void Lowering::lower_node(size_t node) {
  const NodeVariant& data = g_.nodes[node].data;
  const auto out_count = node_outputs(data).size();
  std::visit(
      [&]<class T>(const T& d) {
        // The valued inputs in order, as registers; an output socket's value, for the nodes downstream.
        const auto in = [&](size_t i) { return input(node, d, i); };
        const auto out = [&](size_t socket, VReg reg, SocketType type) {
          outputs_[{node, socket}] = Value{reg, type};
        };
        // A math or mix result, kept to [0, 1] when the node's clamp is on.
        const auto clamped_if = [&](bool clamp, VReg reg) {
          return clamp ? emit(ShaderOp::clamp01, {reg}) : reg;
        };
        if constexpr (std::is_same_v<T, OutputNode>) {
          // The root is the last closure made (allocate() puts it first).
          if (auto root = closure_input(node, "surface")) {
            closures_.push_back(closures_[*root]);
            mix_fac_.push_back(mix_fac_[*root]);
          }
          for (size_t i = 1; i < 4; ++i) {
            if (!c_.incoming[node][i]) continue;
            const VReg r = in(i);
            (i == 1 ? line_color_ : i == 2 ? line_width_ : stroke_color_) = r;
          }
        } else if constexpr (std::is_same_v<T, ValueNode>) {
          out(0, in(0), SocketType::float_value);
        } else if constexpr (std::is_same_v<T, RgbNode>) {
          out(0, in(0), SocketType::color);
        } else if constexpr (std::is_same_v<T, ImageTextureNode>) {
          std::string error;
          auto image = assets_.image(base_ / d.path, d.srgb, &error);
          if (!image) return fail(node, "path: " + error);
          // The alpha channel is decoded only for graphs that read it.
          std::shared_ptr<const std::vector<float>> alpha;
          if (output_linked(node, "alpha")) {
            alpha = assets_.image_alpha(base_ / d.path, &error);
            if (!alpha) return fail(node, "path: " + error);
            if (alpha->size() != image->pixels.size()) alpha = nullptr;  // none: opaque
          }
          program_->images.push_back({std::move(image), std::move(alpha)});
          const uint32_t aux = uint32_t(program_->images.size() - 1);
          const VReg uv = in(0);
          out(0, emit(ShaderOp::image_color, {uv}, 0, aux), SocketType::color);
          out(1, emit(ShaderOp::image_alpha, {uv}, 0, aux), SocketType::float_value);
        } else if constexpr (std::is_same_v<T, CheckerNode>) {
          const VReg c1 = in(0), c2 = in(1), scale = in(2), uv = in(3);
          out(0, emit(ShaderOp::checker_color, {uv, c1, c2, scale}), SocketType::color);
          out(1, emit(ShaderOp::checker_fac, {uv, c1, c2, scale}), SocketType::float_value);
        } else if constexpr (std::is_same_v<T, NoiseNode>) {
          const VReg scale = in(0), rough = in(1), distortion = in(2), p = in(3);
          const auto mode = uint8_t(d.noise);
          const auto oct = uint32_t(std::clamp(d.octaves, 1, 16));  // the parameter's range
          out(0, emit(ShaderOp::noise_fac, {p, scale, rough, distortion}, mode, oct),
              SocketType::float_value);
          out(1, emit(ShaderOp::noise_color, {p, scale, rough, distortion}, mode, oct), SocketType::color);
        } else if constexpr (std::is_same_v<T, VoronoiNode>) {
          const VReg scale = in(0), randomness = in(1), p = in(2);
          out(0, emit(ShaderOp::voronoi_distance, {p, scale, randomness}), SocketType::float_value);
          out(1, emit(ShaderOp::voronoi_color, {p, scale, randomness}), SocketType::color);
          out(2, emit(ShaderOp::voronoi_position, {p, scale, randomness}), SocketType::vector);
        } else if constexpr (std::is_same_v<T, ColorRampNode>) {
          std::vector<RampStop> stops;
          // Stops kept to their parameters' ranges, so the sort below sees no NaN.
          for (const RampStopDesc& s : d.stops)
            stops.push_back({std::isfinite(s.position) ? std::clamp(s.position, 0.f, 1.f) : 0.f,
                             glm::clamp(Vec3(std::isfinite(s.color.x) ? s.color.x : 0.f,
                                             std::isfinite(s.color.y) ? s.color.y : 0.f,
                                             std::isfinite(s.color.z) ? s.color.z : 0.f),
                                        Vec3(0.f), Vec3(1e6f))});
          std::stable_sort(stops.begin(), stops.end(),
                           [](const RampStop& a, const RampStop& b) { return a.position < b.position; });
          program_->ramps.push_back(std::move(stops));
          out(0,
              emit(ShaderOp::ramp, {in(0)}, uint8_t(d.interpolation), uint32_t(program_->ramps.size() - 1)),
              SocketType::color);
        } else if constexpr (std::is_same_v<T, MathNode>) {
          const VReg r = emit(ShaderOp::math, {in(0), in(1), in(2)}, uint8_t(d.operation));
          out(0, clamped_if(d.clamp_result, r), SocketType::float_value);
        } else if constexpr (std::is_same_v<T, MapRangeNode>) {
          out(0, emit(ShaderOp::map_range, {in(0), in(1), in(2), in(3), in(4)}, uint8_t(d.clamp_result)),
              SocketType::float_value);
        } else if constexpr (std::is_same_v<T, MixColorNode>) {
          const VReg r = emit(ShaderOp::mix_color, {in(0), in(1), in(2)}, uint8_t(d.blend));
          out(0, clamped_if(d.clamp_result, r), SocketType::color);
        } else if constexpr (std::is_same_v<T, VectorMathNode>) {
          const VReg a = in(0), b = in(1), s = in(2);
          out(0, emit(ShaderOp::vector_math, {a, b, s}, uint8_t(d.operation)), SocketType::vector);
          out(1, emit(ShaderOp::vector_value, {a, b, s}, uint8_t(d.operation)), SocketType::float_value);
        } else if constexpr (std::is_same_v<T, HsvNode>) {
          out(0, emit(ShaderOp::hsv_adjust, {in(0), in(1), in(2), in(3), in(4)}), SocketType::color);
        } else if constexpr (std::is_same_v<T, ConvertColorNode>) {
          const ShaderOp op =
              d.conversion == ColorConversion::rgb_to_hsv ? ShaderOp::rgb_to_hsv : ShaderOp::hsv_to_rgb;
          out(0, emit(op, {in(0)}), SocketType::color);
        } else if constexpr (std::is_same_v<T, SeparateNode>) {
          const VReg v = in(0);
          out(0, emit(ShaderOp::separate_x, {v}), SocketType::float_value);
          out(1, emit(ShaderOp::separate_y, {v}), SocketType::float_value);
          out(2, emit(ShaderOp::separate_z, {v}), SocketType::float_value);
        } else if constexpr (std::is_same_v<T, CombineNode>) {
          const VReg v = emit(ShaderOp::combine, {in(0), in(1), in(2)});
          out(0, v, SocketType::vector);
          out(1, v, SocketType::color);
        } else if constexpr (std::is_same_v<T, GeometryNode>) {
          constexpr ShaderOp ops[] = {ShaderOp::position,  ShaderOp::normal,         ShaderOp::true_normal,
                                      ShaderOp::uv,        ShaderOp::incoming,       ShaderOp::facing,
                                      ShaderOp::object_id, ShaderOp::material_id,    ShaderOp::depth,
                                      ShaderOp::random,    ShaderOp::object_position};
          static_assert(std::size(ops) == T::outputs.size());
          for (size_t k = 0; k < out_count; ++k)
            out(k, k == 3 ? implicit(Implicit::uv) : emit(ops[k], {}), T::outputs[k].type);
        } else if constexpr (std::is_same_v<T, LightInputNode>) {
          out(0, emit(ShaderOp::n_dot_l, {}), SocketType::float_value);
          out(1, emit(ShaderOp::shadow, {}), SocketType::float_value);
          out(2, emit(ShaderOp::light_color, {}), SocketType::color);
        } else if constexpr (std::is_same_v<T, FresnelNode>) {
          out(0, emit(ShaderOp::fresnel, {in(0)}), SocketType::float_value);
        } else if constexpr (std::is_same_v<T, LayerWeightNode>) {
          const VReg blend = in(0);
          out(0, emit(ShaderOp::layer_weight_fresnel, {blend}), SocketType::float_value);
          out(1, emit(ShaderOp::layer_weight_facing, {blend}), SocketType::float_value);
        } else if constexpr (std::is_same_v<T, MixClosureNode> || std::is_same_v<T, AddClosureNode>) {
          const auto side = [&](std::string_view name) -> uint32_t {
            if (auto c = closure_input(node, name)) return *c;
            return black_leaf();
          };
          ClosureNode cn;
          cn.a = uint16_t(side("a"));
          cn.b = uint16_t(side("b"));
          VReg fac = kNone;
          if constexpr (std::is_same_v<T, MixClosureNode>) {
            cn.kind = ClosureNode::Kind::mix;
            fac = in(0);
          } else {
            cn.kind = ClosureNode::Kind::add;
          }
          closures_.push_back(cn);
          mix_fac_.push_back(fac);
          closure_of_[node] = uint32_t(closures_.size() - 1);
        } else {
          // A closure node: a plain material's description.
          std::string error;
          auto tmpl = compile_closure_template(MaterialVariant(d), base_, assets_, &error);
          if (!tmpl) return fail(node, error);
          std::vector<VReg> regs;
          std::vector<ClosureInput> inputs;
          for (size_t i = 0; i < c_.inputs[node].size(); ++i) {
            const SocketInfo& socket = c_.inputs[node][i];
            if (!socket.has_value) continue;
            const ClosureSetter set = closure_input_setter(T::type_name, socket.name);
            if (!set)
              return fail(node, "input \"" + std::string(socket.name) + "\" of a " +
                                    std::string(T::type_name) + " node has no place in its material");
            regs.push_back(in(i));
            inputs.push_back({0, bounds(node, d, i), set});
          }
          leaves_.push_back({std::move(*tmpl), std::move(inputs)});
          leaf_inputs_.push_back(std::move(regs));
          closures_.push_back({ClosureNode::Kind::leaf, uint16_t(leaves_.size() - 1)});
          mix_fac_.push_back(kNone);
          closure_of_[node] = uint32_t(closures_.size() - 1);
        }
      },
      data);
}

// Instructions whose inputs are all constants and that read nothing of the hit become constants.
void Lowering::fold() {
  std::vector<IrInstr> kept;
  for (const IrInstr& ir : code_) {
    bool constant_inputs = instr_is_pure(ir.instr.op);
    for (int i = 0; i < ir.inputs && constant_inputs; ++i) constant_inputs = is_constant_[ir.in[size_t(i)]];
    if (!constant_inputs) {
      kept.push_back(ir);
      continue;
    }
    Vec3 registers[kMaxShaderInputs];
    ShaderInstr local = ir.instr;
    for (int i = 0; i < ir.inputs; ++i) {
      registers[i] = value_[ir.in[size_t(i)]];
      local.in[size_t(i)] = uint16_t(i);
    }
    const Vec3 v = eval_instr(*program_, local, registers, ShadingPoint{});
    is_constant_[ir.out] = true;
    value_[ir.out] =
        Vec3(std::isfinite(v.x) ? v.x : 0.f, std::isfinite(v.y) ? v.y : 0.f, std::isfinite(v.z) ? v.z : 0.f);
  }
  code_ = std::move(kept);
}

// Instructions nothing reads: outputs of a node that no link takes (a geometry
// node's other nine), or inputs of folded instructions.
void Lowering::remove_dead() {
  std::vector<bool> live(is_constant_.size(), false);
  const auto root = [&](VReg r) {
    if (r != kNone) live[r] = true;
  };
  for (const auto& regs : leaf_inputs_)
    for (VReg r : regs) root(r);
  for (VReg r : mix_fac_) root(r);
  root(line_color_), root(line_width_), root(stroke_color_);
  std::vector<IrInstr> kept;
  for (auto it = code_.rbegin(); it != code_.rend(); ++it) {
    if (!live[it->out]) continue;
    for (int k = 0; k < it->inputs; ++k) live[it->in[size_t(k)]] = true;
    kept.push_back(*it);
  }
  code_.assign(kept.rbegin(), kept.rend());
}

// Constants first, then temporaries by linear scan: a register is free again after
// its value's last reader. What the closures and outputs read lives to the end.
std::shared_ptr<ShaderProgram> Lowering::allocate() {
  const size_t n = is_constant_.size();
  constexpr size_t kForever = SIZE_MAX;
  std::vector<size_t> last_use(n, 0);
  std::vector<bool> used(n, false);
  for (size_t i = 0; i < code_.size(); ++i)
    for (int k = 0; k < code_[i].inputs; ++k)
      last_use[code_[i].in[size_t(k)]] = i, used[code_[i].in[size_t(k)]] = true;
  auto keep = [&](VReg r) {
    if (r != kNone) last_use[r] = kForever, used[r] = true;
  };
  for (const auto& regs : leaf_inputs_)
    for (VReg r : regs) keep(r);
  for (VReg r : mix_fac_) keep(r);
  keep(line_color_), keep(line_width_), keep(stroke_color_);

  std::vector<uint16_t> phys(n, kNoRegister);
  ShaderProgram& p = *program_;
  for (VReg r = 0; r < n; ++r) {
    if (!is_constant_[r] || !used[r]) continue;
    phys[r] = uint16_t(p.constants.size());
    p.constants.push_back(value_[r]);
  }
  const size_t first_temp = p.constants.size();
  std::vector<uint16_t> free_regs;
  size_t next = first_temp;
  std::vector<std::vector<VReg>> dying(code_.size());
  for (VReg r = 0; r < n; ++r)
    if (!is_constant_[r] && used[r] && last_use[r] != kForever) dying[last_use[r]].push_back(r);
  for (size_t i = 0; i < code_.size(); ++i) {
    IrInstr& ir = code_[i];
    for (int k = 0; k < ir.inputs; ++k) ir.instr.in[size_t(k)] = phys[ir.in[size_t(k)]];
    for (VReg r : dying[i]) free_regs.push_back(phys[r]);  // read before the output is written
    if (!free_regs.empty()) {
      phys[ir.out] = free_regs.back();
      free_regs.pop_back();
    } else {
      phys[ir.out] = uint16_t(std::min<size_t>(next++, kNoRegister - 1));
    }
    ir.instr.out = phys[ir.out];
    // A value nobody reads (an output of a multi-output node) frees its register at once.
    if (!used[ir.out]) free_regs.push_back(phys[ir.out]);
    p.code.push_back(ir.instr);
  }
  p.register_count = int(next);
  if (next > size_t(kMaxShaderRegisters)) {
    errors_.push_back("the graph needs " + std::to_string(next) + " registers; at most " +
                      std::to_string(kMaxShaderRegisters) + " fit (simplify the graph)");
    return nullptr;
  }
  for (size_t l = 0; l < leaves_.size(); ++l) {
    ClosureLeaf& leaf = leaves_[l];
    leaf.constant = true;
    for (size_t k = 0; k < leaf.inputs.size(); ++k) {
      const VReg r = leaf_inputs_[l][k];
      leaf.inputs[k].reg = uint16_t(phys[r]);
      leaf.constant = leaf.constant && is_constant_[r];
    }
    // Known now: set once here rather than per hit.
    if (leaf.constant) {
      Material filled;
      materialise(leaf, p.constants.data(), filled);
      leaf.tmpl = std::move(filled);
    }
    std::visit(
        [&]<class M>(const M&) {
          p.lines_pass_through |= std::is_same_v<M, ConductorMaterial> ||
                                  std::is_same_v<M, DielectricMaterial> ||
                                  std::is_same_v<M, TransparentMaterial>;
        },
        leaf.tmpl);
  }
  // The root is the last closure made; reversing puts it first and children after parents.
  const size_t count = closures_.size();
  for (size_t k = 0; k < count; ++k) {
    ClosureNode cn = closures_[count - 1 - k];
    if (cn.kind != ClosureNode::Kind::leaf) {
      cn.a = uint16_t(count - 1 - cn.a);
      cn.b = uint16_t(count - 1 - cn.b);
      if (cn.kind == ClosureNode::Kind::mix) cn.fac = phys[mix_fac_[count - 1 - k]];
    }
    p.closures.push_back(cn);
  }
  p.leaves = std::move(leaves_);
  const auto out = [&](VReg r) { return r == kNone ? kNoRegister : phys[r]; };
  p.line_color = out(line_color_);
  p.line_width = out(line_width_);
  p.stroke_color = out(stroke_color_);
  return program_;
}

std::shared_ptr<const ShaderProgram> Lowering::run() {
  const size_t before = errors_.size();
  for (size_t node : c_.order) {
    const size_t errors_before = errors_.size();
    lower_node(node);
    if (errors_.size() > errors_before) stand_in(node);
    if (closures_.size() > kMaxClosures) {
      errors_.push_back("the graph has more than " + std::to_string(kMaxClosures) +
                        " closures reaching its output (simplify the graph)");
      return nullptr;
    }
  }
  if (errors_.size() > before) return nullptr;
  fold();
  remove_dead();
  // Only light inputs that something still reads cost the shadow ray.
  for (const IrInstr& ir : code_) {
    const ShaderOp op = ir.instr.op;
    program_->uses_light |= op == ShaderOp::n_dot_l || op == ShaderOp::shadow || op == ShaderOp::light_color;
  }
  program_->nodes_in_graph = g_.nodes.size();
  program_->nodes_run = c_.order.size();
  return allocate();
}

}  // namespace

std::shared_ptr<const ShaderProgram> compile_graph(const GraphDesc& graph,
                                                   const std::filesystem::path& base_dir, AssetCache& assets,
                                                   std::vector<std::string>& errors) {
  CheckedGraph checked;
  if (!check_graph(graph, checked, errors)) return nullptr;
  if (graph.nodes.size() > 65535) {
    errors.push_back("nodes: more than 65535 nodes");
    return nullptr;
  }
  return Lowering(graph, checked, base_dir, assets, errors).run();
}

}  // namespace inkray
