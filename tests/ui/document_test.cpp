// Document files: save and reopen, a failed open keeps the document, and an
// interrupted save (the process killed mid-write) leaves the old file intact.
#include "core/document/asset_paths.h"
#include "core/document/json_io.h"
#include "ui/model/autosave.h"
#include "ui/model/document.h"

#include "tests/support/file_helpers.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace inkray {
namespace {

class DocumentFiles : public ::testing::Test {
 protected:
  testing::ScratchFolder scratch_;  // removed with the fixture
  const std::filesystem::path dir_ = scratch_.path();
};

TEST_F(DocumentFiles, SaveThenOpenRoundTrips) {
  Document doc;
  SceneDesc s = doc.scene();
  s.camera.vfov = 33.f;
  doc.edit(s, "fov");
  std::string error;
  ASSERT_TRUE(doc.save_as(dir_ / "a.json", &error)) << error;
  EXPECT_FALSE(doc.dirty());
  EXPECT_EQ(doc.display_name(), "a.json");

  Document other;
  std::vector<std::string> errors;
  ASSERT_TRUE(other.open(dir_ / "a.json", &errors));
  EXPECT_FLOAT_EQ(other.scene().camera.vfov, 33.f);
  EXPECT_EQ(other.scene().objects.size(), doc.scene().objects.size());
  EXPECT_FALSE(other.dirty());
  EXPECT_FALSE(other.history().can_undo());
}

TEST_F(DocumentFiles, SaveAsToAnotherFolderKeepsAssetsFound) {
  // A scene in a/ with a mesh at a/meshes/x.obj and a texture at a/tex.png.
  std::filesystem::create_directories(dir_ / "a" / "meshes");
  std::filesystem::copy_file(std::filesystem::path(INKRAY_SOURCE_DIR) / "tests/data/meshes/cube.obj",
                             dir_ / "a" / "meshes" / "x.obj");
  std::ofstream(dir_ / "a" / "tex.png") << "not read by the loader";
  SceneDesc s = Document::default_scene();
  ObjectDesc mesh;
  mesh.name = "x";
  mesh.shape = MeshDesc{"meshes/x.obj"};
  mesh.material = s.materials.front().name;
  s.objects.push_back(mesh);
  s.materials.push_back({"textured", DiffuseDesc{ImageTextureDesc{"tex.png"}}, {}});
  s.base_dir = dir_ / "a";
  std::string error;
  ASSERT_TRUE(save_scene(s, dir_ / "a" / "scene.json", &error)) << error;

  Document doc;
  std::vector<std::string> errors;
  ASSERT_TRUE(doc.open(dir_ / "a" / "scene.json", &errors)) << (errors.empty() ? "" : errors.front());
  std::filesystem::create_directories(dir_ / "b" / "deeper");
  ASSERT_TRUE(doc.save_as(dir_ / "b" / "deeper" / "scene.json", &error)) << error;
  // The open document still resolves against a/.
  EXPECT_EQ(std::get<MeshDesc>(doc.scene().objects.back().shape).path, "meshes/x.obj");

  const SceneLoadResult moved = load_scene(dir_ / "b" / "deeper" / "scene.json");
  ASSERT_TRUE(moved.scene) << (moved.errors.empty() ? "" : moved.errors.front());
  EXPECT_EQ(std::get<MeshDesc>(moved.scene->objects.back().shape).path, "../../a/meshes/x.obj");
  const auto& diffuse = std::get<DiffuseDesc>(moved.scene->materials.back().data);
  EXPECT_EQ(std::get<ImageTextureDesc>(diffuse.albedo).path, "../../a/tex.png");

  // Saving back into a/ gives the original paths.
  ASSERT_TRUE(doc.save_as(dir_ / "a" / "again.json", &error)) << error;
  const SceneLoadResult back = load_scene(dir_ / "a" / "again.json");
  ASSERT_TRUE(back.scene) << (back.errors.empty() ? "" : back.errors.front());
  EXPECT_EQ(std::get<MeshDesc>(back.scene->objects.back().shape).path, "meshes/x.obj");
}

TEST(AssetPaths, AbsoluteAndEmptyPathsAreKept) {
  SceneDesc s;
  ObjectDesc a, b;
  a.shape = MeshDesc{"/abs/x.obj"};
  b.shape = MeshDesc{""};
  s.objects = {a, b};
  rebase_asset_paths(s, "/one/two", "/three");
  EXPECT_EQ(std::get<MeshDesc>(s.objects[0].shape).path, "/abs/x.obj");
  EXPECT_EQ(std::get<MeshDesc>(s.objects[1].shape).path, "");
}

TEST_F(DocumentFiles, FailedOpenKeepsTheDocument) {
  Document doc;
  SceneDesc s = doc.scene();
  s.camera.vfov = 21.f;
  doc.edit(s, "fov");
  std::ofstream(dir_ / "bad.json") << "{ \"format\": \"inkray-scene\", \"objects\": [ {";
  std::vector<std::string> errors;
  EXPECT_FALSE(doc.open(dir_ / "bad.json", &errors));
  EXPECT_FALSE(errors.empty());
  EXPECT_FLOAT_EQ(doc.scene().camera.vfov, 21.f);
  EXPECT_TRUE(doc.dirty());
  EXPECT_TRUE(doc.history().can_undo());
}

TEST_F(DocumentFiles, SaveWithoutFileAsksForOne) {
  Document doc;
  std::string error;
  EXPECT_FALSE(doc.save(&error));
  EXPECT_FALSE(error.empty());
}

// A child process saves a large document over and over and is killed at a
// random moment; whatever is on disk must still load, old or new.
TEST_F(DocumentFiles, KilledSaveLeavesAWholeFile) {
  const auto file = dir_ / "scene.json";
  SceneDesc original = Document::default_scene();
  std::string error;
  ASSERT_TRUE(save_scene(original, file, &error)) << error;
  SceneDesc big = original;
  for (int i = 0; i < 3000; ++i) {
    ObjectDesc o = big.objects.back();
    o.name = "copy" + std::to_string(i);
    big.objects.push_back(o);
  }
  for (int attempt = 0; attempt < 3; ++attempt) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      std::string e;
      for (;;) save_scene(big, file, &e);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(30 + 17 * attempt));
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
    const SceneLoadResult loaded = load_scene(file);
    ASSERT_TRUE(loaded) << (loaded.errors.empty() ? "" : loaded.errors.front());
    const size_t n = loaded.scene->objects.size();
    EXPECT_TRUE(n == original.objects.size() || n == big.objects.size()) << n;
  }
}

TEST_F(DocumentFiles, AutosaveWritesFindsAndClears) {
  Autosave autosave(dir_ / "recovery.json", std::chrono::seconds(60));
  EXPECT_FALSE(autosave.find());
  SceneDesc s = Document::default_scene();
  s.camera.vfov = 12.f;
  s.base_dir = dir_;
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_FALSE(autosave.tick(s, dir_ / "mine.json", 5, true, t0));  // the interval starts now
  EXPECT_FALSE(autosave.tick(s, dir_ / "mine.json", 5, true, t0 + std::chrono::seconds(30)));
  EXPECT_FALSE(autosave.tick(s, dir_ / "mine.json", 5, false,
                             t0 + std::chrono::seconds(61)));  // saved: nothing to keep
  EXPECT_TRUE(autosave.tick(s, dir_ / "mine.json", 5, true, t0 + std::chrono::seconds(62)));
  EXPECT_FALSE(
      autosave.tick(s, dir_ / "mine.json", 5, true, t0 + std::chrono::seconds(200)));  // unchanged since
  const auto recovered = autosave.find();
  ASSERT_TRUE(recovered);
  EXPECT_FLOAT_EQ(recovered->scene.camera.vfov, 12.f);
  EXPECT_EQ(recovered->original, dir_ / "mine.json");
  autosave.clear();
  EXPECT_FALSE(autosave.find());
}

}  // namespace
}  // namespace inkray
