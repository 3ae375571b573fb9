// The compiler's asset cache: an edit opens no file unless a path or the file
// itself changed, and what a cancelled compile did not finish is not lost.
#include "core/compiler/compile.h"

#include "support/file_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace inkray {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = INKRAY_SOURCE_DIR;

// A textured cube (an OBJ mesh), a toon ramp image, a ball and strokes with an
// image brush on it, each file copied into `folder` so a test can change it.
SceneDesc scene_with_files(const fs::path& folder) {
  fs::copy_file(kSource / "tests/data/scenes/valid/meshes/cube.obj", folder / "cube.obj");
  fs::copy_file(kSource / "tests/data/scenes/valid/textures/checker.png", folder / "checker.png");
  fs::copy_file(kSource / "resources/brushes/dab.png", folder / "dab.png");
  SceneDesc d;
  d.base_dir = folder;
  d.render.width = 24;
  d.render.height = 16;
  d.camera.look_from = Point3(0.f, 2.f, 8.f);
  d.materials.push_back({"tex", DiffuseDesc{ImageTextureDesc{"checker.png"}}, {}});
  ToonDesc toon;
  toon.ramp_image = "checker.png";
  d.materials.push_back({"toon", toon, {}});
  ObjectDesc cube;
  cube.name = "cube";
  cube.shape = MeshDesc{"cube.obj"};
  cube.material = "tex";
  d.objects.push_back(cube);
  ObjectDesc ball;
  ball.name = "ball";
  ball.material = "toon";
  ball.transform.translate = Vec3(2.5f, 0.f, 0.f);
  d.objects.push_back(ball);
  d.strokes.push_back(StrokeEmitterDesc{
      .name = "paint", .object = "ball", .count = 60, .brush = BrushKind::image, .brush_image = "dab.png"});
  d.lights.push_back({"sun", DirectionalLightDesc{}});
  return d;
}

// A compiler that has compiled scene_with_files() once, and the files it opened since.
struct Compiled {
  testing::ScratchFolder folder;
  SceneDesc scene = scene_with_files(folder.path());
  SceneCompiler compiler;
  std::vector<fs::path> opened;

  Compiled() {
    compiler.assets().on_file_read = [this](const fs::path& file) { opened.push_back(file); };
    EXPECT_TRUE(compiler.compile(scene).scene);
  }
};

TEST(AssetCache, EditsOpenNoFile) {
  Compiled c;
  SceneDesc& d = c.scene;
  EXPECT_EQ(c.opened.size(), 5u)
      << "the first compile reads the mesh, the image (size and pixels) and the brush";
  c.opened.clear();

  std::vector<std::pair<std::string, std::function<void(SceneDesc&)>>> edits = {
      {"camera", [](SceneDesc& s) { s.camera.look_from.x += 0.3f; }},
      {"material", [](SceneDesc& s) { std::get<ToonDesc>(s.materials[1].data).threshold = 0.3f; }},
      {"light", [](SceneDesc& s) { std::get<DirectionalLightDesc>(s.lights[0].data).intensity = 2.f; }},
      {"transform", [](SceneDesc& s) { s.objects[0].transform.translate.y = 0.5f; }},
      {"moved ball (strokes regrow)", [](SceneDesc& s) { s.objects[1].transform.translate.y = 0.5f; }},
      {"line colour", [](SceneDesc& s) { s.outlines.silhouette.color = Color(1.f, 0.f, 0.f); }},
      {"stroke colour jitter", [](SceneDesc& s) { s.strokes[0].hue_jitter = 30.f; }},
      {"stroke count", [](SceneDesc& s) { s.strokes[0].count = 80; }},
  };
  for (const auto& [name, edit] : edits) {
    edit(d);
    const CompileResult result = c.compiler.compile(d);
    ASSERT_TRUE(result.scene) << name << ": " << (result.errors.empty() ? "" : result.errors.front());
    EXPECT_TRUE(c.opened.empty()) << name << " opened " << c.opened.front();
    c.opened.clear();
  }
}

TEST(AssetCache, AFileChangedOnDiskIsReadAgain) {
  Compiled c;
  c.opened.clear();
  // A new mesh under the same name: one triangle instead of a cube.
  testing::write_file(c.folder / "cube.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const CompileResult result = c.compiler.compile(c.scene);
  ASSERT_TRUE(result.scene);
  ASSERT_EQ(c.opened.size(), 1u);
  EXPECT_EQ(c.opened[0].filename(), "cube.obj");
  EXPECT_EQ(std::get<TriangleMesh>(result.scene->world->geometry.shape(0)).triangle_count(), 1u);
}

TEST(AssetCache, ACancelledCompileKeepsWhatTheLastOneRead) {
  Compiled c;
  c.opened.clear();
  std::atomic<bool> stop{true};
  CompileOptions cancelled;
  cancelled.cancel = Cancel(&stop);
  c.scene.objects[0].transform.translate.x = 1.f;
  EXPECT_TRUE(c.compiler.compile(c.scene, cancelled).cancelled);
  ASSERT_TRUE(c.compiler.compile(c.scene).scene);
  EXPECT_TRUE(c.opened.empty());
}

TEST(AssetCache, HoldsOneDocumentsAssets) {
  Compiled c;
  c.scene.objects[0].transform.translate.x = -1.f;
  ASSERT_TRUE(c.compiler.compile(c.scene).scene);  // the mesh as read is dropped: its BVH stays
  const size_t entries = c.compiler.assets().entries();
  // Forty moves of the cube: each placement replaces the last one in the cache.
  for (int i = 0; i < 40; ++i) {
    c.scene.objects[0].transform.translate.x = 0.1f * float(i);
    ASSERT_TRUE(c.compiler.compile(c.scene).scene);
  }
  EXPECT_EQ(c.compiler.assets().entries(), entries);
}

}  // namespace
}  // namespace inkray
