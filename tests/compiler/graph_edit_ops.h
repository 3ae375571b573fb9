// The node editor's edits (core/document/graph_edit.h, and parameter values set the way
// ui/widgets/param_widgets.cpp sets them) driven by a stream of bytes, and what every graph they
// make must satisfy when compiled. Shared by the random-edit test
// (tests/compiler/graph_edits_test.cpp) and the graph_compile fuzzer.
#pragma once

#include "core/compiler/compile_graph.h"
#include "core/document/graph_edit.h"
#include "core/document/json_io.h"
#include "core/materials/shader_eval.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace inkray::graph_ops {

// Bytes read front to back; past the end every read is 0, so any input is a whole program.
class ByteStream {
 public:
  ByteStream(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return at_ >= size_; }
  std::uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
  // An index in [0, n); 0 when n is 0.
  std::size_t pick(std::size_t n) {
    if (n == 0) return 0;
    const std::size_t b = n > 256 ? std::size_t(byte()) << 8 | byte() : byte();
    return b % n;
  }
  // A number as a user might type one: ordinary values, range ends, and what the
  // editor must refuse (NaN, infinities) or clamp (1e30).
  float number() {
    switch (byte() % 12) {
      case 0:
        return 0.f;
      case 1:
        return 1.f;
      case 2:
        return -1.f;
      case 3:
        return 1e30f;
      case 4:
        return -1e30f;
      case 5:
        return std::numeric_limits<float>::quiet_NaN();
      case 6:
        return std::numeric_limits<float>::infinity();
      case 7:
        return float(byte()) / 255.f;
      case 8:
        return float(byte()) * 4.f - 512.f;
      case 9:
        return 1e9f;
      default: {
        std::uint32_t bits = 0;
        for (int i = 0; i < 4; ++i) bits = bits << 8 | byte();
        float f;
        std::memcpy(&f, &bits, sizeof f);
        return f;
      }
    }
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

// Image files the edits may name, relative to the graph's folder: one that exists, one that does not.
inline constexpr const char* kImagePaths[] = {"textures/checker.png", "missing.png", ""};

// Sets one parameter the way the editor's widgets do: numbers clamped to the hard range,
// non-finite values refused, choices from their names, toggles flipped, lists grown or cut.
struct SetParam {
  ByteStream* in;
  std::size_t target;  // which parameter of the list, counted in visit order
  std::size_t seen = 0;

  static double clamp_to(const Param& p, double v) {
    return std::clamp(v, std::isfinite(p.min) ? p.min : -1e30, std::isfinite(p.max) ? p.max : 1e30);
  }
  void set_number(const Param& p, float& v) {
    const float value = in->number();
    if (std::isfinite(value)) v = float(clamp_to(p, value));
  }
  void set_vec3(const Param& p, Vec3& v) {
    for (int c = 0; c < 3; ++c) set_number(p, v[c]);
  }

  template <class F>
  void operator()(const Param& p, F& field) {
    if (seen++ != target) return;
    if constexpr (std::is_same_v<F, float>) {
      set_number(p, field);
    } else if constexpr (std::is_same_v<F, int>) {
      const float value = in->number();
      if (std::isfinite(value)) field = int(clamp_to(p, std::trunc(value)));
    } else if constexpr (std::is_same_v<F, bool>) {
      field = !field;
    } else if constexpr (std::is_enum_v<F>) {
      field = F(in->pick(p.choices.size()));
    } else if constexpr (std::is_same_v<F, Vec3>) {
      set_vec3(p, field);
    } else if constexpr (std::is_same_v<F, ColorInput>) {
      switch (in->byte() % 3) {
        case 0: {
          Color c = std::holds_alternative<Color>(field) ? std::get<Color>(field) : Color(0.5f);
          set_vec3(p, c);
          field = c;
          break;
        }
        case 1:
          field = CheckerTextureDesc{};
          break;
        default:
          field = ImageTextureDesc{kImagePaths[in->pick(2)]};
          break;
      }
    } else if constexpr (std::is_same_v<F, std::string>) {
      if (p.kind == ParamKind::path) field = kImagePaths[in->pick(std::size(kImagePaths))];
    } else if constexpr (std::is_same_v<F, std::vector<Color>>) {
      if (in->byte() % 2 && !field.empty()) {
        field.pop_back();
      } else if (field.size() < 8) {
        Color c(0.5f);
        set_vec3(p, c);
        field.push_back(c);
      }
    } else if constexpr (std::is_same_v<F, std::vector<RampStopDesc>>) {
      if (in->byte() % 2 && !field.empty()) {
        field.erase(field.begin() + long(in->pick(field.size())));
      } else if (field.size() < 8) {
        RampStopDesc stop;
        SetParam position{in, 0}, color{in, 1};
        visit_params(stop, position);
        visit_params(stop, color);
        field.push_back(stop);
      }
    }
  }
};

struct ParamCounter {
  std::size_t count = 0;
  template <class F>
  void operator()(const Param&, F&) {
    ++count;
  }
};

// Graphs stay small enough to compile thousands of times a second.
inline constexpr std::size_t kMaxNodes = 48;

inline std::string pick_node(const GraphDesc& g, ByteStream& in) {
  if (g.nodes.empty()) return "nothing";
  // Now and then a name that is not there: the edits must refuse it.
  if (in.byte() % 16 == 0) return "no such node";
  return g.nodes[in.pick(g.nodes.size())].id;
}

inline std::vector<std::string> pick_nodes(const GraphDesc& g, ByteStream& in) {
  std::vector<std::string> ids;
  const std::size_t n = 1 + in.byte() % 3;
  for (std::size_t k = 0; k < n; ++k) ids.push_back(pick_node(g, in));
  return ids;
}

// One edit of the node editor, chosen and parametrised by the stream.
inline void apply_edit(GraphDesc& g, ByteStream& in) {
  const bool room = g.nodes.size() < kMaxNodes;
  const auto coordinate = [&] { return float(int(in.byte()) - 128) * 8.f; };
  switch (in.byte() % 16) {
    case 0:
    case 1: {
      if (!room) break;
      const std::vector<std::string_view> types = node_type_names();
      (void)add_node(g, types[in.pick(types.size())], coordinate(), coordinate());
      break;
    }
    case 2:
      (void)remove_nodes(g, pick_nodes(g, in));
      break;
    case 3:
    case 4:
    case 5: {  // a link dragged from an output to an input; check_link is what the editor asks first
      const std::string from = pick_node(g, in), to = pick_node(g, in);
      const GraphNodeDesc* f = find_node(g, from);
      const GraphNodeDesc* t = find_node(g, to);
      std::string output = "closure", input = "surface";
      if (f && !node_outputs(f->data).empty())
        output = std::string(node_outputs(f->data)[in.pick(node_outputs(f->data).size())].name);
      if (t && !node_inputs(t->data).empty())
        input = std::string(node_inputs(t->data)[in.pick(node_inputs(t->data).size())].name);
      if (in.byte() % 32 == 0) input = "no_such_input";
      const bool allowed = !check_link(g, from, output, to, input);
      const bool linked = !connect(g, from, output, to, input);
      if (allowed != linked)
        throw std::logic_error("check_link and connect disagree on " + from + " -> " + to);
      break;
    }
    case 6: {
      if (!g.links.empty() && in.byte() % 4) {
        const GraphLinkDesc l = g.links[in.pick(g.links.size())];
        (void)disconnect(g, l.to, l.input);
      } else {
        (void)disconnect(g, pick_node(g, in), "surface");
      }
      break;
    }
    case 7:
    case 8:
    case 9: {  // a value typed or dragged on a node
      if (g.nodes.empty()) break;
      GraphNodeDesc& n = g.nodes[in.pick(g.nodes.size())];
      std::visit(
          [&](auto& d) {
            ParamCounter counter;
            visit_params(d, counter);
            if (counter.count == 0) return;
            SetParam set{&in, in.pick(counter.count)};
            visit_params(d, set);
          },
          n.data);
      break;
    }
    case 10:
      move_nodes(g, pick_nodes(g, in), coordinate(), coordinate());
      break;
    case 11:
      if (room) (void)duplicate_nodes(g, pick_nodes(g, in), coordinate(), coordinate());
      break;
    case 12: {
      const std::string clipboard = copy_nodes(g, pick_nodes(g, in));
      if (room) (void)paste_nodes(g, clipboard, coordinate(), coordinate());
      break;
    }
    case 13: {
      if (g.links.empty()) break;
      (void)insert_on_link(g, in.pick(g.links.size() + 1), pick_node(g, in));
      break;
    }
    case 14: {  // text that is not a clipboard: refused with a message
      std::string text;
      for (std::size_t k = in.byte() % 24; k > 0; --k) text += char(in.byte());
      std::string error;
      if (!paste_nodes(g, text, 0.f, 0.f, &error).empty() && text.find("graph") == std::string::npos)
        throw std::logic_error("paste accepted text that is no graph");
      break;
    }
    default:
      if (in.byte() % 8 == 0) {
        // The editor's "make this material a graph" on a plain closure kind.
        const std::vector<std::string_view> types = node_type_names();
        const std::optional<NodeVariant> node = make_node(types[in.pick(types.size())]);
        std::visit(
            [&]<class T>(const T& d) {
              if constexpr (std::is_constructible_v<MaterialVariant, T>)
                g = graph_from_material(MaterialVariant(d));
            },
            *node);
      } else {
        place_unplaced_nodes(g);
      }
      break;
  }
}

// ---------------------------------------------------------------- the oracle
inline void texture_numbers(const Texture& t, std::vector<float>& out) {
  std::visit(
      [&](const auto& tex) {
        using T = std::decay_t<decltype(tex)>;
        const auto push = [&](const Vec3& v) { out.insert(out.end(), {v.x, v.y, v.z}); };
        if constexpr (std::is_same_v<T, ConstantTexture>) {
          push(tex.value);
        } else if constexpr (std::is_same_v<T, ImageTexture>) {
          push(tex.scale), push(tex.average);
        } else {
          push(tex.even), push(tex.odd), out.push_back(tex.scale);
        }
      },
      t);
}

// Every number a resolved surface holds, in a fixed order: for comparing two surfaces and
// checking them finite. Empty for kinds a graph never resolves to.
inline std::vector<float> material_numbers(const Material& m) {
  std::vector<float> out;
  const auto push = [&](const Vec3& v) { out.insert(out.end(), {v.x, v.y, v.z}); };
  std::visit(
      [&](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, DiffuseMaterial>) {
          texture_numbers(s.albedo, out);
        } else if constexpr (std::is_same_v<T, ConductorMaterial>) {
          texture_numbers(s.color, out), out.push_back(s.roughness);
        } else if constexpr (std::is_same_v<T, DielectricMaterial>) {
          out.insert(out.end(), {s.ior, s.roughness}), push(s.tint);
        } else if constexpr (std::is_same_v<T, EmissiveMaterial>) {
          texture_numbers(s.color, out), out.push_back(s.strength);
        } else if constexpr (std::is_same_v<T, UnlitMaterial>) {
          texture_numbers(s.color, out);
        } else if constexpr (std::is_same_v<T, TransparentMaterial>) {
          push(s.tint);
        } else if constexpr (std::is_same_v<T, ToonMaterial>) {
          texture_numbers(s.color, out);
          push(s.shadow_color);
          out.insert(out.end(), {float(s.bands), s.threshold, s.softness, s.ramp_near, s.ramp_far});
          push(s.specular_color);
          out.insert(out.end(), {s.specular_size, s.shininess});
          push(s.rim_color);
          out.insert(out.end(), {s.rim_width, s.rim_threshold, s.environment});
        }
      },
      m);
  return out;
}

// Hits a graph is run at: an ordinary one, one seen from behind far from the origin,
// and one at huge coordinates with uv outside [0, 1].
struct TestHits {
  SurfaceInteraction si[3];
  ShadingPoint sp[3];
  TestHits() {
    const Vec3 p[3] = {Vec3(0.2f, 0.5f, 1.f), Vec3(-40.f, 7.f, 3.f), Vec3(1e6f, -3e5f, 2e4f)};
    const Vec3 n[3] = {Vec3(0.f, 0.f, 1.f), Vec3(0.f, 1.f, 0.f), glm::normalize(Vec3(1.f, 1.f, 1.f))};
    const Vec2 uv[3] = {Vec2(0.25f, 0.75f), Vec2(0.f, 1.f), Vec2(-3.5f, 17.25f)};
    const Vec3 wo[3] = {glm::normalize(Vec3(0.f, 0.6f, 0.8f)), Vec3(0.f, -1.f, 0.f),
                        glm::normalize(Vec3(1.f, 0.f, 0.f))};
    for (int k = 0; k < 3; ++k) {
      si[k].p = p[k];
      si[k].ng = si[k].ns = n[k];
      si[k].uv = uv[k];
      sp[k] = shading_point(si[k], wo[k]);
      sp[k].depth = float(k) * 50.f;
      sp[k].object_id = uint32_t(k * 7);
      sp[k].material_id = uint32_t(k);
      sp[k].n_dot_l = float(k) * 0.4f;
      sp[k].shadow = float(k % 2);
      sp[k].light_color = Color(1.f, 0.5f, float(k));
    }
  }
};

// What is wrong with the program's values at the hits, or "" when nothing is: every
// register finite, every surface it picks finite and non-negative (no material
// parameter is negative), the overrides finite.
inline std::string evaluation_problem(const ShaderProgram& program) {
  static const TestHits hits;
  for (const ShadingPoint& sp : hits.sp) {
    ShaderRegisters registers;
    run_shader(program, sp, registers);
    for (int r = 0; r < program.register_count && r < kMaxShaderRegisters; ++r)
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(registers[size_t(r)][c]))
          return "register " + std::to_string(r) + " is not finite";
    for (const float u : {0.f, 0.3f, 0.7f, 0.9999f}) {
      Material scratch;
      const ResolvedMaterial picked = run_graph(program, sp, u, scratch);
      if (!std::isfinite(picked.weight) || picked.weight < 0.f) return "the closure weight is not finite";
      if (!picked.material) {
        if (!program.closures.empty()) return "a graph with a surface resolved to none";
        continue;
      }
      if (std::holds_alternative<MixMaterial>(*picked.material) ||
          std::holds_alternative<GraphMaterial>(*picked.material))
        return "a graph resolved to a mix or a graph";
      for (const float v : material_numbers(*picked.material))
        if (!std::isfinite(v) || v < 0.f)
          return "the surface picked at u " + std::to_string(u) + " holds " + std::to_string(v);
    }
    const SurfaceOverrides o = shader_overrides(program, sp);
    const auto bad = [](const Vec3& v) {
      return !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z);
    };
    if ((o.line_color && bad(*o.line_color)) || (o.stroke_color && bad(*o.stroke_color)) ||
        (o.line_width && !std::isfinite(*o.line_width)))
      return "an output override is not finite";
  }
  return {};
}

struct CompileOutcome {
  std::shared_ptr<const ShaderProgram> program;
  std::string problem;  // "" when the oracle holds
};

// Compiles the graph: either a program whose values are finite, or no program and
// messages; never an exception, never an empty message.
inline CompileOutcome compile_and_check(const GraphDesc& g, const std::filesystem::path& base,
                                        AssetCache& assets) {
  CompileOutcome out;
  std::vector<std::string> errors;
  try {
    out.program = compile_graph(g, base, assets, errors);
  } catch (const std::exception& e) {
    out.problem = std::string("compile_graph threw: ") + e.what();
    return out;
  }
  if (!out.program) {
    if (errors.empty()) out.problem = "compile_graph refused the graph without a message";
    for (const std::string& e : errors)
      if (e.empty()) out.problem = "compile_graph gave an empty message";
    return out;
  }
  if (!errors.empty()) {
    out.problem = "compile_graph returned a program and errors: " + errors.front();
    return out;
  }
  out.problem = evaluation_problem(*out.program);
  return out;
}

// A graph material written, read back for editing and written again must read and
// give the same text: what the editor saves, it opens again unchanged. The text is the
// compact dump of what scene_to_string lays out (one JSON value, one text: the same
// check, without the layout's cost in the fuzzer).
inline std::string round_trip_problem(const GraphDesc& g, const std::filesystem::path& base) {
  SceneDesc scene;
  scene.materials.push_back({"graph", g, {}});
  const std::string first = scene_to_json(scene).dump();
  const SceneLoadResult read = parse_scene(first, base, "graph.json", ReadFor::editing);
  if (!read.scene)
    return "a compiled graph does not read back: " + (read.errors.empty() ? "" : read.errors.front());
  const std::string second = scene_to_json(*read.scene).dump();
  if (second != first) return "a compiled graph is written differently after reading it back";
  return {};
}

// The graph materials of the example scenes (scenes/graph_*.json): valid starting points.
inline std::vector<GraphDesc> example_graphs(const std::filesystem::path& source_dir) {
  std::vector<GraphDesc> graphs;
  const std::filesystem::path scenes = source_dir / "scenes";
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(scenes))
    if (entry.path().filename().string().rfind("graph_", 0) == 0 && entry.path().extension() == ".json")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const std::filesystem::path& file : files) {
    const SceneLoadResult loaded = load_scene(file, ReadFor::editing);
    if (!loaded.scene) continue;
    for (const MaterialDesc& m : loaded.scene->materials)
      if (const auto* g = std::get_if<GraphDesc>(&m.data)) graphs.push_back(*g);
  }
  if (graphs.empty()) graphs.push_back(graph_from_material(ToonDesc{}));
  return graphs;
}

}  // namespace inkray::graph_ops
