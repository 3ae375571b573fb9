// Graph materials in the tracer: a plain material and the one-node graph of it
// render the same pixels with the same rays; graphs reading the light inputs see
// the analytic n.l and shadow, and only they trace the extra shadow ray.
#include "support/graph_helpers.h"
#include "support/render_helpers.h"

#include "core/document/json_io.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

using namespace inkray::testing;

const std::filesystem::path kScenes = INKRAY_SOURCE_DIR "/scenes";

// Every plain material of the scene that has a closure node, as that node's graph.
SceneDesc as_graphs(SceneDesc d, int* converted) {
  for (MaterialDesc& m : d.materials) {
    std::visit(
        [&]<class T>(const T& plain) {
          if constexpr (std::is_constructible_v<NodeVariant, T>) {
            m.data = closure_graph(plain);
            ++*converted;
          }
        },
        m.data);
  }
  return d;
}

class GraphEqualsPlain : public ::testing::TestWithParam<std::string> {};

TEST_P(GraphEqualsPlain, SamePixelsSameRays) {
  SceneLoadResult loaded = load_scene(kScenes / GetParam());
  ASSERT_TRUE(loaded.scene) << loaded.errors.front();
  SceneDesc plain = *loaded.scene;
  plain.render.width = 64;
  plain.render.height = 40;
  // Emitters stay plain: a graph's emission is found by BSDF sampling only (docs/scene-format.md).
  int converted = 0;
  SceneDesc graph = as_graphs(plain, &converted);
  for (size_t i = 0; i < plain.materials.size(); ++i)
    if (std::holds_alternative<EmissiveDesc>(plain.materials[i].data))
      graph.materials[i] = plain.materials[i];
  ASSERT_GT(converted, 0);
  RenderStats plain_stats, graph_stats;
  const RgbImage a = render_scene(plain, 4, 2, &plain_stats);
  const RgbImage b = render_scene(graph, 4, 2, &graph_stats);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    differing += glm::any(glm::greaterThan(glm::abs(a.pixels[i] - b.pixels[i]), Vec3(1e-5f)));
  EXPECT_EQ(differing, 0u) << "of " << a.pixels.size() << " pixels";
  EXPECT_EQ(plain_stats.rays, graph_stats.rays) << "a graph without light inputs traces no extra ray";
}

INSTANTIATE_TEST_SUITE_P(ExampleScenes, GraphEqualsPlain,
                         ::testing::Values("materials.json", "toon.json", "cornell.json",
                                           "glass_outlines.json"),
                         [](const auto& scene) { return scene.param.substr(0, scene.param.find('.')); });

// A unit sphere seen from +z, lit along -z by a directional light; its colour is a light input.
SceneDesc light_input_scene(const std::string& output, bool blocker) {
  SceneDesc d = one_sphere_scene(33, 33);
  d.camera.look_from = Point3(0.f, 0.f, 6.f);
  d.camera.vfov = 25.f;
  GraphDesc g;
  add(g, "light", LightInputNode{});
  add(g, "surface", UnlitDesc{});
  add(g, "out", OutputNode{});
  link(g, "light", output, "surface", "color");
  link(g, "surface", "closure", "out", "surface");
  d.materials[0].data = g;
  d.lights = {{"sun", DirectionalLightDesc{Vec3(0.f, 0.f, -1.f), Color(2.f, 1.f, 0.5f), 3.f}}};
  if (blocker) {
    // Behind the camera, so it shades the sphere without hiding it.
    ObjectDesc wall;
    wall.name = "wall";
    wall.material = "dark";
    wall.shape = QuadDesc{Point3(-3.f, -3.f, 8.f), Vec3(0.f, 6.f, 0.f), Vec3(6.f, 0.f, 0.f)};
    d.objects.push_back(wall);
    d.materials.push_back({"dark", DiffuseDesc{Color(0.f)}, {}});
  }
  return d;
}

TEST(GraphLightInputs, MatchTheAnalyticLight) {
  const RgbImage ndotl = render_scene(light_input_scene("n_dot_l", false), 4);
  EXPECT_NEAR(ndotl.at(16, 16).x, 1.f, 0.01f) << "the normal faces the light at the centre";
  // Towards the rim the normal turns away: n.l falls with the cosine.
  EXPECT_LT(ndotl.at(16, 4).x, ndotl.at(16, 10).x);
  EXPECT_GT(ndotl.at(16, 10).x, 0.f);
  const RgbImage color = render_scene(light_input_scene("color", false), 4);
  EXPECT_NEAR(color.at(16, 16).x, 1.f, 1e-4f);
  EXPECT_NEAR(color.at(16, 16).y, 0.5f, 1e-4f);
  EXPECT_NEAR(color.at(16, 16).z, 0.25f, 1e-4f);
  const RgbImage lit = render_scene(light_input_scene("shadow", false), 4);
  const RgbImage shadowed = render_scene(light_input_scene("shadow", true), 4);
  EXPECT_EQ(lit.at(16, 16).x, 1.f);
  EXPECT_EQ(shadowed.at(16, 16).x, 0.f);
}

TEST(GraphLightInputs, OnlyGraphsThatReadThemTraceShadowRays) {
  SceneDesc reads = light_input_scene("n_dot_l", false);
  SceneDesc ignores = reads;
  GraphDesc& g = std::get<GraphDesc>(ignores.materials[0].data);
  g.links[0] = {"light", "n_dot_l", "surface", "nothing"};
  g.links.erase(g.links.begin());  // the light node is left unlinked
  RenderStats with, without;
  render_scene(reads, 2, 2, &with);
  render_scene(ignores, 2, 2, &without);
  EXPECT_GT(with.rays, without.rays);
  EXPECT_EQ(without.rays, without.paths) << "camera rays only: an unlit graph traces nothing else";
}

// Textures read the object-space position: moving the object and the camera together
// leaves the image as it was (the texture does not slide over the surface).
TEST(GraphTextures, StayOnAMovingObject) {
  SceneDesc d = one_sphere_scene(32, 32);
  GraphDesc g;
  add(g, "noise", NoiseNode{NoiseType::gradient, 3, 4.f, 0.5f, 0.f});
  add(g, "surface", UnlitDesc{});
  add(g, "out", OutputNode{});
  link(g, "noise", "color", "surface", "color");
  link(g, "surface", "closure", "out", "surface");
  d.materials[0].data = g;
  SceneDesc moved = d;
  const Vec3 offset(5.f, -2.f, 1.f);
  moved.objects[0].transform.translate = offset;
  moved.camera.look_from += offset;
  moved.camera.look_at += offset;
  const RgbImage a = render_scene(d, 2), b = render_scene(moved, 2);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  double diff = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) diff += glm::length(a.pixels[i] - b.pixels[i]);
  EXPECT_LT(diff / double(a.pixels.size()), 1e-3) << "mean colour difference per pixel";
}

}  // namespace
}  // namespace inkray
