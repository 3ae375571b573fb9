// The document's file references and "Locate...": every path field is listed with
// who uses it and whether it is on disk; relinking one missing file moves every
// other missing file of its folder that is found beside the chosen one, and nothing else.
#include "core/document/asset_relink.h"
#include "core/document/json_io.h"

#include "tests/support/file_helpers.h"
#include "tests/support/scene_copies.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace inkray {
namespace {

namespace fs = std::filesystem;
const fs::path kScenes = INKRAY_SOURCE_DIR "/scenes";

SceneDesc loaded_copy(const fs::path& folder, const std::string& name) {
  return testing::example_scene_alone(folder, name);
}

MaterialDesc textured(const std::string& name, const std::string& path) {
  return {name, DiffuseDesc{ImageTextureDesc{path}}, {}};
}

ObjectDesc mesh_object(const std::string& name, const std::string& path) {
  ObjectDesc o;
  o.name = name;
  o.material = "m";
  o.shape = MeshDesc{path};
  return o;
}

const std::string& texture_path(const SceneDesc& scene, size_t material) {
  return std::get<ImageTextureDesc>(std::get<DiffuseDesc>(scene.materials[material].data).albedo).path;
}

const std::string& mesh_path(const SceneDesc& scene, size_t object) {
  return std::get<MeshDesc>(scene.objects[object].shape).path;
}

TEST(AssetRelink, ListsEveryReferenceWithItsUserAndWhetherItIsThere) {
  testing::ScratchFolder folder;
  SceneDesc scene = loaded_copy(folder.path(), "mesh.json");
  fs::create_directory(folder / "textures");
  fs::copy_file(kScenes / "textures/tiles.png", folder / "textures/tiles.png");

  const auto refs = list_asset_references(scene);
  ASSERT_EQ(refs.size(), 3u);
  EXPECT_EQ(refs[0].site.at, "materials[0].albedo.path");
  EXPECT_EQ(refs[0].site.user, "material \"tiles\"");
  EXPECT_EQ(refs[0].site.type, FileType::image);
  EXPECT_TRUE(refs[0].exists);
  EXPECT_EQ(refs[1].site.at, "objects[1].shape.path");
  EXPECT_EQ(refs[1].site.user, "object \"knot\"");
  EXPECT_EQ(refs[1].site.type, FileType::mesh);
  EXPECT_FALSE(refs[1].exists);
  EXPECT_EQ(refs[1].resolved, folder / "meshes/torus_knot.obj");

  const auto missing = missing_assets(scene);
  ASSERT_EQ(missing.size(), 2u);
  EXPECT_EQ(missing[0].written, "meshes/torus_knot.obj");
  EXPECT_EQ(missing[0].users, std::vector<std::string>{"object \"knot\""});
}

TEST(AssetRelink, FindsPathsInGraphsRampsAndBrushesInUse) {
  SceneDesc scene;
  ToonDesc toon;
  toon.ramp_image = "ramp.png";
  scene.materials.push_back({"toon", toon, {}});
  GraphDesc graph;
  GraphNodeDesc node;
  node.id = "img";
  node.data = ImageTextureNode{};
  std::get<ImageTextureNode>(node.data).path = "node.png";
  graph.nodes.push_back(node);
  scene.materials.push_back({"graph", graph, {}});
  StrokeEmitterDesc painted, bristles;
  painted.name = "painted";
  painted.brush = BrushKind::image;
  painted.brush_image = "brush.png";
  bristles.name = "bristles";
  bristles.brush_image = "unused.png";  // kept while another brush is chosen
  scene.strokes = {painted, bristles};

  std::vector<std::string> found;
  for (const AssetReference& r : list_asset_references(scene)) found.push_back(r.site.at + " " + r.site.user);
  EXPECT_EQ(found, (std::vector<std::string>{"materials[0].ramp_image material \"toon\"",
                                             "materials[1].nodes[0].path material \"graph\"",
                                             "strokes[0].brush_image stroke emitter \"painted\""}));
}

// A scene whose files lived in lost/: a.png (two materials, written two ways),
// b.obj and c.png; d.png lived elsewhere, and here.png is where it should be.
struct Moved {
  testing::ScratchFolder folder;
  SceneDesc scene;
  Moved() {
    scene.base_dir = folder.path();
    scene.materials = {textured("a", "lost/a.png"), textured("a again", "./lost/../lost/a.png"),
                       textured("c", "lost/c.png"), textured("d", "elsewhere/d.png"),
                       textured("here", "here.png")};
    scene.objects = {mesh_object("b", "lost/b.obj")};
    fs::create_directory(folder / "found");
    for (const char* name : {"a.png", "b.obj", "d.png"}) testing::write_file(folder / "found" / name, "x");
    testing::write_file(folder / "here.png", "x");
  }
};

TEST(AssetRelink, RelinksTheFileAndItsMissingNeighboursFoundBesideIt) {
  Moved m;
  EXPECT_EQ(relink(m.scene, "lost/a.png", m.folder / "found" / "a.png"), 3u);
  EXPECT_EQ(texture_path(m.scene, 0), "found/a.png");
  EXPECT_EQ(texture_path(m.scene, 1), "found/a.png") << "the same file, written another way";
  EXPECT_EQ(mesh_path(m.scene, 0), "found/b.obj");
  EXPECT_EQ(texture_path(m.scene, 2), "lost/c.png") << "not beside the chosen file: still missing";
  EXPECT_EQ(texture_path(m.scene, 3), "elsewhere/d.png") << "another folder: not moved with them";
  EXPECT_EQ(texture_path(m.scene, 4), "here.png");
  EXPECT_EQ(missing_assets(m.scene).size(), 2u);
}

TEST(AssetRelink, PathsStayRelativeToTheScenesFolder) {
  Moved m;
  const fs::path outside = m.folder.path().parent_path() / (m.folder.path().filename().string() + "_outside");
  fs::create_directory(outside);
  testing::write_file(outside / "c.png", "x");
  EXPECT_EQ(relink(m.scene, "lost/c.png", outside / "c.png"), 1u);
  EXPECT_EQ(texture_path(m.scene, 2), "../" + outside.filename().string() + "/c.png");
  fs::remove_all(outside);
}

TEST(AssetRelink, APathWithNoFileChangesNothing) {
  Moved m;
  const SceneDesc before = m.scene;
  EXPECT_EQ(relink(m.scene, "nowhere/x.png", m.folder / "found" / "a.png"), 0u);
  EXPECT_EQ(m.scene, before);
}

TEST(AssetRelink, SavingKeepsMissingPathsAsWritten) {
  testing::ScratchFolder folder;
  const SceneDesc scene = loaded_copy(folder.path(), "mesh.json");
  std::string error;
  ASSERT_TRUE(save_scene_as(scene, folder / "saved.json", &error)) << error;
  const std::string text = testing::read_file(folder / "saved.json");
  EXPECT_NE(text.find("\"meshes/torus_knot.obj\""), std::string::npos);
  EXPECT_NE(text.find("\"textures/tiles.png\""), std::string::npos);
}

}  // namespace
}  // namespace inkray
