// Every node type of material graphs evaluated at a hit against values worked
// out by hand (or, for the procedural textures, against the functions tested in
// procedural_test.cpp), through the whole path: graph -> compile -> program -> registers.
#include "support/graph_helpers.h"

#include "core/image/image_io.h"
#include "support/color_checks.h"
#include "support/file_helpers.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>

namespace inkray {
namespace {

using namespace inkray::testing;

constexpr float kTol = 1e-5f;

template <class Node>
Vec3 value_of(const Node& node, const std::string& output) {
  SurfaceInteraction si;
  const ShadingPoint sp = test_point(si);
  GraphDesc g;
  add(g, "n", node);
  return socket_value(g, "n", output, sp);
}

float math(MathOp op, float a, float b, float c = 1.f, bool clamp = false) {
  MathNode m;
  m.operation = op;
  m.a = a, m.b = b, m.c = c;
  m.clamp_result = clamp;
  return value_of(m, "value").x;
}

TEST(ShaderNodes, Constants) {
  EXPECT_TRUE(near3(value_of(ValueNode{0.25f}, "value"), Vec3(0.25f)));
  EXPECT_TRUE(near3(value_of(RgbNode{Color(0.1f, 0.2f, 0.3f)}, "color"), Vec3(0.1f, 0.2f, 0.3f)));
}

TEST(ShaderNodes, Math) {
  EXPECT_NEAR(math(MathOp::add, 2, 3), 5, kTol);
  EXPECT_NEAR(math(MathOp::subtract, 2, 3), -1, kTol);
  EXPECT_NEAR(math(MathOp::multiply, 2, 3), 6, kTol);
  EXPECT_NEAR(math(MathOp::divide, 2, 4), 0.5, kTol);
  EXPECT_EQ(math(MathOp::divide, 2, 0), 0.f) << "division by zero is 0, not inf";
  EXPECT_NEAR(math(MathOp::power, 2, 3), 8, kTol);
  EXPECT_NEAR(math(MathOp::power, -2, 3), -8, kTol);
  EXPECT_EQ(math(MathOp::power, -2, 0.5f), 0.f) << "a negative base takes integer exponents only";
  EXPECT_NEAR(math(MathOp::minimum, 2, 3), 2, kTol);
  EXPECT_NEAR(math(MathOp::maximum, 2, 3), 3, kTol);
  EXPECT_NEAR(math(MathOp::clamp, 5, 0, 1), 1, kTol);
  EXPECT_NEAR(math(MathOp::clamp, -5, 0, 1), 0, kTol);
  EXPECT_NEAR(math(MathOp::clamp, 0.5f, 1, 0), 0.5, kTol) << "bounds in either order";
  EXPECT_NEAR(math(MathOp::smoothstep, 0.5f, 0, 1), 0.5, kTol);
  EXPECT_NEAR(math(MathOp::smoothstep, 0.25f, 0, 1), 0.15625, kTol);  // 3t^2 - 2t^3
  EXPECT_NEAR(math(MathOp::smoothstep, 2, 0, 1), 1, kTol);
  EXPECT_NEAR(math(MathOp::smoothstep, 0.5f, 0.5f, 0.5f), 1, kTol) << "a zero-width edge is a step";
  EXPECT_EQ(math(MathOp::greater_than, 3, 2), 1.f);
  EXPECT_EQ(math(MathOp::greater_than, 2, 3), 0.f);
  EXPECT_EQ(math(MathOp::less_than, 2, 3), 1.f);
  EXPECT_EQ(math(MathOp::add, 2, 3, 1, true), 1.f) << "clamp_result keeps [0, 1]";
}

TEST(ShaderNodes, MapRange) {
  MapRangeNode m;
  m.value = 5, m.from_min = 0, m.from_max = 10, m.to_min = 100, m.to_max = 200;
  EXPECT_NEAR(value_of(m, "value").x, 150, 1e-3);
  m.value = 20;
  EXPECT_NEAR(value_of(m, "value").x, 200, 1e-3);
  m.clamp_result = false;
  EXPECT_NEAR(value_of(m, "value").x, 300, 1e-3);
  m.from_max = 0;  // an empty source range maps everything to to_min
  EXPECT_NEAR(value_of(m, "value").x, 100, 1e-3);
}

TEST(ShaderNodes, MixColor) {
  MixColorNode m;
  m.a = Color(1.f, 0.f, 0.f);
  m.b = Color(0.f, 0.f, 1.f);
  m.fac = 0.25f;
  EXPECT_TRUE(near3(value_of(m, "color"), Vec3(0.75f, 0.f, 0.25f)));
  m.blend = BlendOp::add;
  m.fac = 1.f;
  EXPECT_TRUE(near3(value_of(m, "color"), Vec3(1.f, 0.f, 1.f)));
  m.blend = BlendOp::multiply;
  m.a = Color(0.5f);
  m.b = Color(0.2f, 0.4f, 1.f);
  EXPECT_TRUE(near3(value_of(m, "color"), Vec3(0.1f, 0.2f, 0.5f)));
  m.blend = BlendOp::screen;  // 1 - (1 - a)(1 - b)
  EXPECT_TRUE(near3(value_of(m, "color"), Vec3(0.6f, 0.7f, 1.f)));
  m.blend = BlendOp::add;
  m.a = Color(0.8f);
  m.clamp_result = true;
  EXPECT_TRUE(near3(value_of(m, "color"), Vec3(1.f, 1.f, 1.f)));
}

TEST(ShaderNodes, VectorMath) {
  VectorMathNode v;
  v.a = Vec3(1, 2, 3), v.b = Vec3(4, 5, 6);
  v.operation = VectorOp::dot;
  EXPECT_NEAR(value_of(v, "value").x, 32, kTol);
  v.operation = VectorOp::add;
  EXPECT_TRUE(near3(value_of(v, "vector"), Vec3(5, 7, 9)));
  v.operation = VectorOp::subtract;
  EXPECT_TRUE(near3(value_of(v, "vector"), Vec3(-3)));
  v.operation = VectorOp::multiply;
  EXPECT_TRUE(near3(value_of(v, "vector"), Vec3(4, 10, 18)));
  v.operation = VectorOp::cross;
  v.a = Vec3(1, 0, 0), v.b = Vec3(0, 1, 0);
  EXPECT_TRUE(near3(value_of(v, "vector"), Vec3(0, 0, 1)));
  v.operation = VectorOp::normalize;
  v.a = Vec3(3, 0, 4);
  EXPECT_TRUE(near3(value_of(v, "vector"), Vec3(0.6f, 0, 0.8f)));
  v.operation = VectorOp::length;
  EXPECT_NEAR(value_of(v, "value").x, 5, kTol);
  v.operation = VectorOp::scale;
  v.scale = 2;
  EXPECT_TRUE(near3(value_of(v, "vector"), Vec3(6, 0, 8)));
  v.operation = VectorOp::normalize;
  v.a = Vec3(0);
  EXPECT_TRUE(near3(value_of(v, "vector"), Vec3(0))) << "the zero vector normalises to zero, not NaN";
}

TEST(ShaderNodes, ColourConversions) {
  HsvNode h;  // defaults leave the colour as it is
  h.color = Color(0.2f, 0.5f, 0.8f);
  EXPECT_TRUE(near3(value_of(h, "color"), Vec3(0.2f, 0.5f, 0.8f), 1e-4f));
  h.hue = 0.5f + 1.f / 3.f;  // red turns green
  h.color = Color(1.f, 0.f, 0.f);
  EXPECT_TRUE(near3(value_of(h, "color"), Vec3(0.f, 1.f, 0.f), 1e-4f));
  ConvertColorNode c;
  c.color = Color(1.f, 0.f, 0.f);
  EXPECT_TRUE(near3(value_of(c, "color"), Vec3(0.f, 1.f, 1.f)));
  c.color = Color(0.f, 0.f, 1.f);
  EXPECT_TRUE(near3(value_of(c, "color"), Vec3(2.f / 3.f, 1.f, 1.f), 1e-5f)) << "hue in [0, 1]";
  c.conversion = ColorConversion::hsv_to_rgb;
  c.color = Color(1.f / 3.f, 1.f, 1.f);
  EXPECT_TRUE(near3(value_of(c, "color"), Vec3(0.f, 1.f, 0.f), 1e-4f));
  SeparateNode s{Vec3(1, 2, 3)};
  EXPECT_TRUE(near3(value_of(s, "x"), Vec3(1)));
  EXPECT_TRUE(near3(value_of(s, "y"), Vec3(2)));
  EXPECT_TRUE(near3(value_of(s, "z"), Vec3(3)));
  CombineNode k{4, 5, 6};
  EXPECT_TRUE(near3(value_of(k, "vector"), Vec3(4, 5, 6)));
  EXPECT_TRUE(near3(value_of(k, "color"), Vec3(4, 5, 6)));
}

TEST(ShaderNodes, ColourRamp) {
  ColorRampNode r;
  r.fac = 0.25f;
  EXPECT_TRUE(near3(value_of(r, "color"), Vec3(0.25f)));
  r.interpolation = RampMode::constant;
  EXPECT_TRUE(near3(value_of(r, "color"), Vec3(0.f)));
  r.interpolation = RampMode::ease;
  EXPECT_TRUE(near3(value_of(r, "color"), Vec3(0.15625f)));
  // Stops in any order are sorted by position.
  r.interpolation = RampMode::linear;
  r.stops = {{1.f, Color(0.f, 0.f, 1.f)}, {0.f, Color(1.f, 0.f, 0.f)}, {0.5f, Color(0.f, 1.f, 0.f)}};
  r.fac = 0.75f;
  EXPECT_TRUE(near3(value_of(r, "color"), Vec3(0.f, 0.5f, 0.5f)));
  r.fac = -3.f;
  EXPECT_TRUE(near3(value_of(r, "color"), Vec3(1.f, 0.f, 0.f))) << "fac clamps to [0, 1]";
}

TEST(ShaderNodes, Geometry) {
  SurfaceInteraction si;
  const ShadingPoint sp = test_point(si);
  const GeometryNode geo;
  EXPECT_TRUE(near3(value_of(geo, "position"), Vec3(1, 2, 3)));
  EXPECT_TRUE(near3(value_of(geo, "object_position"), Vec3(-0.5f, 0.25f, 2.f)));
  EXPECT_TRUE(near3(value_of(geo, "normal"), Vec3(0, 0, 1)));
  EXPECT_TRUE(near3(value_of(geo, "true_normal"), Vec3(0, 0, 1)));
  EXPECT_TRUE(near3(value_of(geo, "uv"), Vec3(0.25f, 0.75f, 0.f)));
  EXPECT_TRUE(near3(value_of(geo, "incoming"), sp.wo));
  EXPECT_NEAR(value_of(geo, "facing").x, 0.8f, kTol);
  EXPECT_EQ(value_of(geo, "object_id").x, 3.f);
  EXPECT_EQ(value_of(geo, "material_id").x, 5.f);
  EXPECT_EQ(value_of(geo, "depth").x, 7.f);
  const float random = value_of(geo, "random").x;
  EXPECT_GE(random, 0.f);
  EXPECT_LT(random, 1.f);
  // Another object draws another number; the same object always the same.
  GraphDesc g;
  add(g, "geo", geo);
  ShadingPoint other = sp;
  other.object_id = 4;
  EXPECT_NE(socket_value(g, "geo", "random", other).x, random);
  EXPECT_EQ(socket_value(g, "geo", "random", sp).x, random);
}

TEST(ShaderNodes, LightInputs) {
  const LightInputNode light;
  EXPECT_NEAR(value_of(light, "n_dot_l").x, 0.4f, kTol);
  EXPECT_EQ(value_of(light, "shadow").x, 1.f);
  EXPECT_TRUE(near3(value_of(light, "color"), Vec3(1.f, 0.5f, 0.25f)));
}

TEST(ShaderNodes, FresnelAndLayerWeight) {
  SurfaceInteraction si;
  ShadingPoint sp = test_point(si);
  sp.wo = Vec3(0, 0, 1);  // normal incidence
  GraphDesc g;
  add(g, "f", FresnelNode{1.5f});
  EXPECT_NEAR(socket_value(g, "f", "fac", sp).x, 0.04f, 1e-5);
  GraphDesc lw;
  add(lw, "w", LayerWeightNode{0.5f});
  EXPECT_NEAR(socket_value(lw, "w", "fresnel", sp).x, 1.f / 9.f, 1e-5);  // ior 1 / (1 - blend) = 2
  EXPECT_NEAR(socket_value(lw, "w", "facing", sp).x, 0.f, 1e-5);         // 1 - |cos|, cos = 1
  sp.wo = glm::normalize(Vec3(0, 0.6f, 0.8f));
  EXPECT_NEAR(socket_value(lw, "w", "facing", sp).x, 0.2f, 1e-5);
  EXPECT_GT(socket_value(g, "f", "fac", sp).x, 0.04f) << "more reflection away from the normal";
}

TEST(ShaderNodes, ProceduralTextures) {
  SurfaceInteraction si;
  const ShadingPoint sp = test_point(si);
  CheckerNode checker;  // scale 10 over uv (0.25, 0.75): squares (2, 7), odd
  EXPECT_TRUE(near3(value_of(checker, "color"), checker.color2));
  EXPECT_EQ(value_of(checker, "fac").x, 1.f);
  checker.scale = 4;  // squares (1, 3): even
  EXPECT_TRUE(near3(value_of(checker, "color"), checker.color1));

  NoiseNode noise;
  noise.octaves = 3;
  noise.distortion = 0.3f;
  const NoiseResult n =
      noise_texture(sp.p_object, NoiseKind::gradient, noise.scale, 3, noise.roughness, 0.3f);
  EXPECT_NEAR(value_of(noise, "fac").x, n.fac, kTol) << "unlinked, noise reads the object-space position";
  EXPECT_TRUE(near3(value_of(noise, "color"), n.color));

  VoronoiNode voronoi;
  const VoronoiResult v = voronoi_texture(sp.p_object, voronoi.scale, voronoi.randomness);
  EXPECT_NEAR(value_of(voronoi, "distance").x, v.distance, kTol);
  EXPECT_TRUE(near3(value_of(voronoi, "color"), v.color));
  EXPECT_TRUE(near3(value_of(voronoi, "position"), v.position));

  // A linked vector replaces the implicit coordinates.
  GraphDesc g;
  add(g, "at", CombineNode{0.5f, 0.5f, 0.5f});
  add(g, "noise", noise);
  link(g, "at", "vector", "noise", "vector");
  const NoiseResult moved =
      noise_texture(Vec3(0.5f), NoiseKind::gradient, noise.scale, 3, noise.roughness, 0.3f);
  EXPECT_NEAR(socket_value(g, "noise", "fac", sp).x, moved.fac, kTol);
}

TEST(ShaderNodes, ImageTexture) {
  ScratchFolder dir;
  RgbImage img;
  img.width = 2;
  img.height = 2;
  img.pixels = {Color(1, 0, 0), Color(0, 1, 0), Color(0, 0, 1), Color(1, 1, 1)};  // row 0 at the top
  std::string error;
  ASSERT_TRUE(write_image(dir / "t.png", img, &error)) << error;
  ImageTextureNode tex;
  tex.path = "t.png";
  tex.srgb = false;
  SurfaceInteraction si;
  ShadingPoint sp = test_point(si);
  GraphDesc g;
  add(g, "tex", tex);
  si.uv = Vec2(0.25f, 0.75f);  // top-left texel's centre
  EXPECT_TRUE(near3(socket_value(g, "tex", "color", sp, dir.path()), Vec3(1, 0, 0), 1e-4f));
  si.uv = Vec2(0.75f, 0.25f);  // bottom-right
  EXPECT_TRUE(near3(socket_value(g, "tex", "color", sp, dir.path()), Vec3(1, 1, 1), 1e-4f));
  EXPECT_EQ(socket_value(g, "tex", "alpha", sp, dir.path()).x, 1.f) << "an image without alpha is opaque";

  // An RGBA PNG: alpha 0.2 on the left column, 1 on the right.
  const unsigned char rgba[16] = {255, 0, 0, 51, 0, 255, 0, 255, 0, 0, 255, 51, 255, 255, 255, 255};
  ASSERT_TRUE(stbi_write_png((dir / "a.png").c_str(), 2, 2, 4, rgba, 8));
  GraphDesc ga;
  ImageTextureNode with_alpha = tex;
  with_alpha.path = "a.png";
  add(ga, "tex", with_alpha);
  si.uv = Vec2(0.25f, 0.75f);
  EXPECT_NEAR(socket_value(ga, "tex", "alpha", sp, dir.path()).x, 0.2f, 1e-4f);
  EXPECT_TRUE(near3(socket_value(ga, "tex", "color", sp, dir.path()), Vec3(1, 0, 0), 1e-4f));
  si.uv = Vec2(0.75f, 0.25f);
  EXPECT_NEAR(socket_value(ga, "tex", "alpha", sp, dir.path()).x, 1.f, 1e-4f);
}

// Implicit conversions between socket types, as Blender makes them.
TEST(ShaderNodes, Conversions) {
  SurfaceInteraction si;
  const ShadingPoint sp = test_point(si);
  GraphDesc g;
  add(g, "c", RgbNode{Color(1.f, 0.f, 0.f)});
  add(g, "m", MathNode{MathOp::add, false, 0.f, 0.f, 1.f});
  link(g, "c", "color", "m", "a");
  EXPECT_NEAR(socket_value(g, "m", "value", sp).x, 0.2126f, 1e-5) << "colour -> float is luminance";
  GraphDesc v;
  add(v, "vec", CombineNode{1.f, 2.f, 6.f});
  add(v, "m", MathNode{MathOp::add, false, 0.f, 0.f, 1.f});
  link(v, "vec", "vector", "m", "a");
  EXPECT_NEAR(socket_value(v, "m", "value", sp).x, 3.f, 1e-5) << "vector -> float is the mean";
  GraphDesc f;
  add(f, "x", ValueNode{0.3f});
  add(f, "mix", MixColorNode{});
  link(f, "x", "value", "mix", "a");
  link(f, "x", "value", "mix", "b");
  EXPECT_TRUE(near3(socket_value(f, "mix", "color", sp), Vec3(0.3f))) << "float -> colour is grey";
}

// Closures: a mix picks b with probability fac, an add picks either side at double weight.
TEST(ShaderNodes, MixAndAddClosures) {
  GraphDesc g;
  add(g, "red", UnlitDesc{Color(1.f, 0.f, 0.f)});
  add(g, "blue", DiffuseDesc{Color(0.f, 0.f, 1.f)});
  add(g, "mix", MixClosureNode{0.3f});
  add(g, "out", OutputNode{});
  link(g, "red", "closure", "mix", "a");
  link(g, "blue", "closure", "mix", "b");
  link(g, "mix", "closure", "out", "surface");
  const CompiledGraph c = compile(g);
  ASSERT_TRUE(c.program) << c.errors.front();
  SurfaceInteraction si;
  ShaderRegisters r;
  run_shader(*c.program, test_point(si), r);
  Material scratch;
  ResolvedMaterial picked = pick_closure(*c.program, r, 0.2f, scratch);
  ASSERT_TRUE(picked.material);
  EXPECT_TRUE(std::holds_alternative<DiffuseMaterial>(*picked.material)) << "u < fac picks b";
  EXPECT_EQ(picked.weight, 1.f);
  picked = pick_closure(*c.program, r, 0.5f, scratch);
  EXPECT_TRUE(std::holds_alternative<UnlitMaterial>(*picked.material));
  EXPECT_TRUE(near3(texture_eval(std::get<UnlitMaterial>(*picked.material).color, Vec2(0.f)), Vec3(1, 0, 0)));

  GraphDesc sum = g;
  sum.nodes[2].data = AddClosureNode{};
  const CompiledGraph a = compile(sum);
  ASSERT_TRUE(a.program);
  run_shader(*a.program, test_point(si), r);
  picked = pick_closure(*a.program, r, 0.25f, scratch);
  EXPECT_TRUE(std::holds_alternative<UnlitMaterial>(*picked.material));
  EXPECT_EQ(picked.weight, 2.f);
  picked = pick_closure(*a.program, r, 0.75f, scratch);
  EXPECT_TRUE(std::holds_alternative<DiffuseMaterial>(*picked.material));
  EXPECT_EQ(picked.weight, 2.f);

  // Nested: a mix inside an add, each choice rescaling u.
  GraphDesc nested = g;
  add(nested, "glow", EmissiveDesc{});
  add(nested, "sum", AddClosureNode{});
  nested.links.pop_back();
  link(nested, "mix", "closure", "sum", "a");
  link(nested, "glow", "closure", "sum", "b");
  link(nested, "sum", "closure", "out", "surface");
  const CompiledGraph n = compile(nested);
  ASSERT_TRUE(n.program);
  run_shader(*n.program, test_point(si), r);
  picked = pick_closure(*n.program, r, 0.1f, scratch);  // sum -> a (u 0.2) -> mix -> b
  EXPECT_TRUE(std::holds_alternative<DiffuseMaterial>(*picked.material));
  EXPECT_EQ(picked.weight, 2.f);
  picked = pick_closure(*n.program, r, 0.9f, scratch);
  EXPECT_TRUE(std::holds_alternative<EmissiveMaterial>(*picked.material));
}

// A graph with no surface linked renders nothing rather than failing.
TEST(ShaderNodes, NoSurfaceIsNoMaterial) {
  GraphDesc g;
  add(g, "out", OutputNode{});
  const CompiledGraph c = compile(g);
  ASSERT_TRUE(c.program);
  SurfaceInteraction si;
  ShaderRegisters r;
  run_shader(*c.program, test_point(si), r);
  Material scratch;
  EXPECT_FALSE(pick_closure(*c.program, r, 0.5f, scratch).material);
}

// A toon node's environment weight is a socket, its environment shadows a setting
// on the node: both reach the material the path tracer shades with, linked or not.
TEST(ShaderNodes, ToonNodeCarriesTheEnvironmentWeightAndShadows) {
  ToonDesc toon;
  toon.environment = 0.6f;
  toon.environment_shadows = true;
  for (const bool linked : {false, true}) {
    GraphDesc g = closure_graph(toon);
    if (linked) {
      add(g, "weight", GeometryNode{});
      link(g, "weight", "depth", "surface", "environment");
    }
    const CompiledGraph c = compile(g);
    ASSERT_TRUE(c.program) << (c.errors.empty() ? "" : c.errors.front());
    SurfaceInteraction si;
    const ShadingPoint sp = test_point(si);
    ShaderRegisters r;
    run_shader(*c.program, sp, r);
    Material scratch;
    const ResolvedMaterial picked = pick_closure(*c.program, r, 0.5f, scratch);
    ASSERT_TRUE(picked.material);
    const auto* m = std::get_if<ToonMaterial>(picked.material);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->environment, linked ? sp.depth : 0.6f) << linked;
    EXPECT_TRUE(m->environment_shadows) << linked;
  }
}

}  // namespace
}  // namespace inkray
