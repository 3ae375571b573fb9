// A material, light or transform edit reuses the last compile's objects and top level
// (SceneCompiler::reuse_objects): each edit below, made on a scene of many objects,
// renders exactly as the same document compiled from scratch, does only its own work,
// and a long drag keeps the asset cache the size of one document.
#include "core/compiler/compile.h"
#include "core/film/resolve.h"
#include "core/render/batch_render.h"
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace inkray {
namespace {

// A grid of spheres in three materials, a box (a mesh) and a quad ground, under a
// point light, with crease lines so moved meshes get their patches again.
SceneDesc many_objects() {
  SceneDesc s = testing::sized_scene(48, 32);
  s.camera = {{.look_from = Point3(0.f, 6.f, 14.f), .look_at = Point3(0.f, 0.f, 0.f)}};
  s.outlines.crease.enabled = true;
  s.materials = {{"grey", DiffuseDesc{Color(0.6f)}, {}},
                 {"red", DiffuseDesc{Color(0.8f, 0.2f, 0.1f)}, {}},
                 {"toon", ToonDesc{}, {}}};
  ObjectDesc ground;
  ground.name = "ground";
  ground.shape = QuadDesc{Point3(-10.f, 0.f, -10.f), Vec3(20.f, 0.f, 0.f), Vec3(0.f, 0.f, 20.f)};
  ground.material = "grey";
  s.objects.push_back(ground);
  ObjectDesc box;
  box.name = "box";
  box.shape = BoxDesc{Point3(-0.5f), Point3(0.5f)};
  box.material = "toon";
  box.transform.translate = Vec3(0.f, 0.5f, 3.f);
  s.objects.push_back(box);
  for (int i = 0; i < 150; ++i) {
    ObjectDesc sphere;
    sphere.name = "sphere " + std::to_string(i);
    sphere.shape = SphereDesc{Point3(0.f), 0.3f};
    sphere.material = i % 3 == 0 ? "red" : i % 3 == 1 ? "toon" : "grey";
    sphere.transform.translate = Vec3(float(i % 15) - 7.f, 0.3f, float(i / 15) - 6.f);
    s.objects.push_back(sphere);
  }
  LightDesc light;
  light.name = "light";
  light.data = PointLightDesc{Point3(2.f, 8.f, 4.f), Color(1.f), 60.f};
  s.lights.push_back(light);
  return s;
}

using testing::differing_pixels;
using testing::render_one_pass;

void move(SceneDesc& s, size_t object, float dx) { s.objects[object].transform.translate.x += dx; }

struct Edit {
  std::string what;
  std::function<void(SceneDesc&)> apply;
  int top_levels;  // expected; -1: not checked (the whole pass)
  int shape_bvhs;  // expected; -1: not checked
};

TEST(ReusedObjects, EditsRenderAsACompileFromScratch) {
  const std::vector<Edit> edits = {
      {"one sphere moved", [](SceneDesc& s) { move(s, 10, 0.4f); }, 1, 1},
      {"the box moved", [](SceneDesc& s) { move(s, 1, -0.7f); }, 1, 0},
      {"the box turned",
       [](SceneDesc& s) {
         s.objects[1].transform.rotate.push_back({Vec3(0.f, 1.f, 0.f), 30.f});
       },
       1, 0},
      {"five spheres moved",
       [](SceneDesc& s) {
         for (size_t o : {2u, 40u, 41u, 99u, 150u}) move(s, o, 0.25f);
       },
       1, 5},
      {"seventy spheres moved (the whole pass)",
       [](SceneDesc& s) {
         for (size_t o = 2; o < 72; ++o) move(s, o, 0.1f);
       },
       1, -1},
      {"a material's colour",
       [](SceneDesc& s) { std::get<DiffuseDesc>(s.materials[1].data).albedo = Color(0.1f, 0.9f, 0.2f); }, 0,
       0},
      {"a material's line override", [](SceneDesc& s) { s.materials[2].lines.width_scale = 3.f; }, 0, 0},
      {"a material and a move",
       [](SceneDesc& s) {
         std::get<DiffuseDesc>(s.materials[0].data).albedo = Color(0.3f);
         move(s, 20, 0.5f);
       },
       1, 1},
      {"an object's line override", [](SceneDesc& s) { s.objects[30].lines.exclude = true; }, 0, 0},
      {"the light", [](SceneDesc& s) { std::get<PointLightDesc>(s.lights[0].data).intensity = 20.f; }, 0, 0},
      {"a sphere hidden (the whole pass)", [](SceneDesc& s) { s.objects[50].visible = false; }, -1, -1},
      {"a sphere given another material (the whole pass)",
       [](SceneDesc& s) { s.objects[60].material = "grey"; }, -1, -1},
      {"a sphere flattened to nothing (the whole pass)",
       [](SceneDesc& s) { s.objects[70].transform.scale = Vec3(1.f, 0.f, 1.f); }, -1, -1},
      {"the crease threshold", [](SceneDesc& s) { s.outlines.crease.threshold = 60.f; }, 0, 0},
  };
  const SceneDesc original = many_objects();
  for (const Edit& edit : edits) {
    SCOPED_TRACE(edit.what);
    SceneCompiler compiler;
    ASSERT_TRUE(compiler.compile(original).scene);
    SceneDesc edited = original;
    edit.apply(edited);
    const CompileCounters before = compiler.counters();
    const CompileResult incremental = compiler.compile(edited);
    ASSERT_TRUE(incremental.scene) << (incremental.errors.empty() ? "" : incremental.errors[0]);
    const CompileCounters& after = compiler.counters();
    if (edit.top_levels >= 0) {
      EXPECT_EQ(after.top_levels - before.top_levels, uint64_t(edit.top_levels));
    }
    if (edit.shape_bvhs >= 0) {
      EXPECT_EQ(after.shape_bvhs - before.shape_bvhs, uint64_t(edit.shape_bvhs));
    }
    EXPECT_EQ(after.files_read, before.files_read);
    const CompileResult fresh = compile_scene(edited);
    ASSERT_TRUE(fresh.scene);
    EXPECT_EQ(differing_pixels(render_one_pass(incremental.scene), render_one_pass(fresh.scene)), 0u);
    // And back: the edit undone renders as the original.
    const CompileResult undone = compiler.compile(original);
    ASSERT_TRUE(undone.scene);
    EXPECT_EQ(differing_pixels(render_one_pass(undone.scene), render_one_pass(compile_scene(original).scene)),
              0u);
  }
}

TEST(ReusedObjects, ADragKeepsTheCacheTheSizeOfOneDocument) {
  SceneDesc s = many_objects();
  SceneCompiler compiler;
  ASSERT_TRUE(compiler.compile(s).scene);
  const size_t entries = compiler.assets().entries();
  for (int step = 0; step < 40; ++step) {
    move(s, 1, 0.05f);   // the box: a placement with a world-space copy of its mesh
    move(s, 12, 0.05f);  // a sphere
    ASSERT_TRUE(compiler.compile(s).scene);
  }
  EXPECT_LE(compiler.assets().entries(), entries + 2) << "each step's placements should replace the last's";
  const CompileResult fresh = compile_scene(s);
  EXPECT_EQ(differing_pixels(render_one_pass(compiler.compile(s).scene), render_one_pass(fresh.scene)), 0u);
}

}  // namespace
}  // namespace inkray
