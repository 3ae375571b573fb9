// Dropped files: kinds by extension, and images landing on what the selection can take.
#include "ui/model/document.h"
#include "ui/model/file_drop.h"
#include "ui/model/scene_edits.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace inkray {
namespace {

TEST(FileDrop, KindsByExtension) {
  EXPECT_EQ(drop_kind("a/scene.JSON"), DropKind::scene);
  EXPECT_EQ(drop_kind("bunny.obj"), DropKind::mesh);
  for (const char* f : {"t.png", "t.JPG", "t.jpeg", "sky.hdr", "t.tga"})
    EXPECT_EQ(drop_kind(f), DropKind::image) << f;
  EXPECT_EQ(drop_kind("render.pfm"), DropKind::unknown);  // written by inkray, never read as a texture
  EXPECT_EQ(drop_kind("notes.txt"), DropKind::unknown);
  EXPECT_EQ(drop_kind("noextension"), DropKind::unknown);
}

TEST(FileDrop, ImageOnAnObjectTexturesItsMaterial) {
  SceneDesc scene = Document::default_scene();
  scene.base_dir = "/scenes/shot";
  ASSERT_FALSE(scene.objects.empty());
  const Selection object{ItemKind::object, 0};
  std::string why;
  ASSERT_TRUE(drop_image_on(scene, object, "/scenes/shot/textures/wood.png", &why)) << why;
  const auto& name = scene.objects[0].material;
  const auto it =
      std::find_if(scene.materials.begin(), scene.materials.end(), [&](auto& m) { return m.name == name; });
  ASSERT_NE(it, scene.materials.end());
  bool found = false;
  std::visit(
      [&](auto& m) {
        if constexpr (requires { m.albedo; }) {
          const auto* image = std::get_if<ImageTextureDesc>(&m.albedo);
          found = image && image->path == "textures/wood.png";  // relative to the scene's folder
        }
      },
      it->data);
  EXPECT_TRUE(found);
}

TEST(FileDrop, ImageOnAnEmitterBecomesItsBrush) {
  SceneDesc scene = Document::default_scene();
  const Selection emitter = add_stroke_emitter(scene, scene.objects[0].name);
  std::string why;
  ASSERT_TRUE(drop_image_on(scene, emitter, "/brushes/dab.png", &why)) << why;
  EXPECT_EQ(scene.strokes[0].brush, BrushKind::image);
  EXPECT_EQ(scene.strokes[0].brush_image, "/brushes/dab.png");
}

TEST(FileDrop, RefusalsNameTheFileAndLeaveTheSceneAlone) {
  SceneDesc scene = Document::default_scene();
  const SceneDesc before = scene;
  std::string why;
  EXPECT_FALSE(drop_image_on(scene, Selection{}, "/x/wood.png", &why));
  EXPECT_NE(why.find("/x/wood.png"), std::string::npos) << why;
  EXPECT_NE(why.find("select"), std::string::npos) << why;
  EXPECT_FALSE(drop_image_on(scene, Selection{ItemKind::camera, -1}, "/x/wood.png", &why));
  EXPECT_EQ(scene, before);
  MaterialDesc graph;
  graph.name = "nodes";
  graph.data = GraphDesc{};
  scene.materials.push_back(graph);
  const SceneDesc with_graph = scene;
  EXPECT_FALSE(drop_image_on(scene, Selection{ItemKind::material, int(scene.materials.size()) - 1},
                             "/x/wood.png", &why));
  EXPECT_NE(why.find("node graph"), std::string::npos) << why;
  EXPECT_EQ(scene, with_graph);
}

}  // namespace
}  // namespace inkray
