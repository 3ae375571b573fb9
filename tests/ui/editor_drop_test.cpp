// Files dropped on the real editor's window under Xvfb, through the callback GLFW calls
// (`inkray --drop FILE`): a mesh is imported and selected, an image then textures the
// selection's material, and a file of no known kind changes nothing.
#include "core/document/json_io.h"

#include "tests/support/editor_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace inkray {
namespace {

using namespace inkray::testing;

class EditorDrop : public EditorTest {};

TEST_F(EditorDrop, MeshThenImageLandOnTheDocument) {
  const std::filesystem::path source(INKRAY_SOURCE_DIR);
  std::filesystem::copy_file(source / "tests/data/meshes/cube.obj", dir / "cube.obj");
  std::filesystem::copy_file(source / "resources/brushes/dab.png", dir / "dab.png");
  std::ofstream(dir / "notes.txt") << "not a scene\n";
  const auto dump = dir / "after.json";
  const std::string out =
      run_command(editor_command(dir.path(), 1280, 720) + " --frames 20 --screenshot " +
                      (dir / "shot.png").string() + " --drop " + (dir / "cube.obj").string() + " --drop " +
                      (dir / "dab.png").string() + " --drop " + (dir / "notes.txt").string() +
                      " --scene-dump " + dump.string() + " " + (source / "scenes/toon.json").string(),
                  &code);
  ASSERT_EQ(code, 0) << out;

  const std::string json = read_file(dump);
  const SceneLoadResult loaded = load_scene(dump, ReadFor::editing);
  ASSERT_TRUE(loaded.scene) << json;
  const SceneDesc& scene = *loaded.scene;
  const auto cube = std::find_if(scene.objects.begin(), scene.objects.end(),
                                 [](const ObjectDesc& o) { return o.name == "cube"; });
  ASSERT_NE(cube, scene.objects.end()) << "the dropped mesh was not imported";
  const auto* mesh = std::get_if<MeshDesc>(&cube->shape);
  ASSERT_NE(mesh, nullptr);
  EXPECT_EQ(std::filesystem::path(mesh->path).filename(), "cube.obj");
  // The image went to the imported (selected) object's material.
  const auto material = std::find_if(scene.materials.begin(), scene.materials.end(),
                                     [&](const MaterialDesc& m) { return m.name == cube->material; });
  ASSERT_NE(material, scene.materials.end());
  EXPECT_NE(json.find("dab.png"), std::string::npos) << "the dropped image is not in the document";
  EXPECT_EQ(json.find("notes.txt"), std::string::npos);
}

}  // namespace
}  // namespace inkray
