// Every document the editor can build is one it can save and open again: each kind
// of item added through the editor's own edits, each material, light, environment
// and colour-input type chosen from its type menu (defaults, as the menu sets
// them, with files not chosen yet), saved, reopened, autosaved and recovered, and
// walked back and forth through undo. A document that cannot render yet still opens
// for editing, with the reasons as warnings.
#include "core/document/json_io.h"
#include "core/document/tagged_variant.h"
#include "ui/model/autosave.h"
#include "ui/model/document.h"
#include "ui/model/scene_edits.h"

#include "tests/support/messages.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace inkray {
namespace {

namespace fs = std::filesystem;

using testing::joined;

// What the type menu does: the alternative, default-constructed (param_widgets.h).
template <class Variant>
std::vector<Variant> every_alternative() {
  std::vector<Variant> out;
  for_each_alternative<Variant>([&]<class T>(std::type_identity<T>) { out.push_back(T{}); });
  return out;
}

// Each step is one Document::edit, as the panels make them; returns the steps' texts.
std::vector<std::string> build_everything(Document& doc, const fs::path& mesh) {
  std::vector<std::string> states = {scene_to_string(doc.scene())};
  const auto step = [&](const auto& change) {
    SceneDesc s = doc.scene();
    change(s);
    doc.edit(std::move(s), "step");
    states.push_back(scene_to_string(doc.scene()));
  };
  for (NewShape shape : {NewShape::sphere, NewShape::quad, NewShape::box})
    step([&](SceneDesc& s) { add_shape(s, shape); });
  step([&](SceneDesc& s) { add_mesh(s, mesh.string()); });
  step([&](SceneDesc& s) { add_point_light(s); });
  step([&](SceneDesc& s) { add_stroke_emitter(s, s.objects.front().name); });
  for (const MaterialVariant& type : every_alternative<MaterialVariant>()) {
    step([&](SceneDesc& s) {
      const Selection added = add_material(s);
      s.materials[size_t(added.index)].data = type;
    });
  }
  // A colour input switched to each texture type, the image one before a file is chosen.
  for (const ColorInput& input : every_alternative<ColorInput>()) {
    step([&](SceneDesc& s) {
      const Selection added = add_material(s);
      s.materials[size_t(added.index)].data = DiffuseDesc{input};
    });
  }
  for (const LightVariant& type : every_alternative<LightVariant>()) {
    step([&](SceneDesc& s) {
      const Selection added = add_point_light(s);
      s.lights[size_t(added.index)].data = type;
    });
  }
  for (const EnvironmentDesc& type : every_alternative<EnvironmentDesc>())
    step([&](SceneDesc& s) { s.environment = type; });
  step([&](SceneDesc& s) {
    s.outlines.enabled = true;
    s.outlines.crease.enabled = true;
    s.render.painterly = PainterlyFilter::anisotropic;
  });
  // A stroke emitter switched to an image brush before its image is chosen.
  step([&](SceneDesc& s) { s.strokes.front().brush = BrushKind::image; });
  return states;
}

class EditorDocuments : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("inkray_editor_documents_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "saved");
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  const fs::path mesh_ = fs::path(INKRAY_SOURCE_DIR) / "tests" / "data" / "meshes" / "cube.obj";
};

TEST_F(EditorDocuments, EverythingTheEditorBuildsSavesAndOpensAgain) {
  Document doc;
  const std::vector<std::string> states = build_everything(doc, mesh_);
  ASSERT_GE(states.size(), 25u);

  std::string error;
  const fs::path file = dir_ / "saved" / "everything.json";
  ASSERT_TRUE(doc.save_as(file, &error)) << error;
  Document reopened;
  std::vector<std::string> errors, warnings;
  ASSERT_TRUE(reopened.open(file, &errors, &warnings)) << joined(errors);
  EXPECT_EQ(scene_to_string(reopened.scene()), scene_to_string(doc.scene()));
  ASSERT_TRUE(reopened.save_as(dir_ / "saved" / "again.json", &error)) << error;
  Document third;
  ASSERT_TRUE(third.open(dir_ / "saved" / "again.json", &errors)) << joined(errors);
  EXPECT_EQ(scene_to_string(third.scene()), scene_to_string(reopened.scene()));

  // What is not chosen yet is named, and only that; rendering refuses the file.
  const std::string w = joined(warnings);
  EXPECT_NE(w.find(".albedo.path: no file given"), std::string::npos) << w;
  EXPECT_NE(w.find(".a: expected a non-empty string"), std::string::npos) << w;  // a mix's inputs
  EXPECT_NE(w.find("strokes[0].brush_image: required when brush is \"image\""), std::string::npos) << w;
  EXPECT_EQ(warnings.size(), 4u) << w;  // the image path, the mix's a and b, the brush image
  const SceneLoadResult strict = load_scene(file);
  EXPECT_FALSE(strict);
  EXPECT_EQ(strict.errors.size(), warnings.size()) << joined(strict.errors);
}

TEST_F(EditorDocuments, UndoAndRedoWalkThroughEveryState) {
  Document doc;
  const std::vector<std::string> states = build_everything(doc, mesh_);
  for (size_t i = states.size() - 1; i > 0; --i) {
    ASSERT_TRUE(doc.undo());
    ASSERT_EQ(scene_to_string(doc.scene()), states[i - 1]) << "undo to step " << i - 1;
  }
  EXPECT_FALSE(doc.undo());
  for (size_t i = 1; i < states.size(); ++i) {
    ASSERT_TRUE(doc.redo());
    ASSERT_EQ(scene_to_string(doc.scene()), states[i]) << "redo to step " << i;
  }
}

TEST_F(EditorDocuments, AutosaveRecoversEverythingTheEditorBuilds) {
  Document doc;
  build_everything(doc, mesh_);
  Autosave autosave(dir_ / "recovery" / "recovery.json", std::chrono::seconds(60));
  std::string error;
  ASSERT_TRUE(autosave.write(doc.scene(), {}, &error)) << error;
  std::vector<std::string> errors;
  const std::optional<Recovery> recovered = autosave.find(&errors);
  ASSERT_TRUE(recovered) << joined(errors);
  EXPECT_EQ(scene_to_string(recovered->scene), scene_to_string(doc.scene()));
}

TEST(MissingFilesDocument, OpensAndListsThemApart) {
  const fs::path folder =
      fs::temp_directory_path() / ("inkray_missing_files_open_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  fs::copy_file(fs::path(INKRAY_SOURCE_DIR) / "scenes/mesh.json",
                folder / "mesh.json");  // alone: its files are missing
  Document document;
  std::vector<std::string> errors, warnings, missing;
  ASSERT_TRUE(document.open(folder / "mesh.json", &errors, &warnings, &missing)) << joined(errors);
  EXPECT_TRUE(warnings.empty()) << joined(warnings);
  ASSERT_EQ(missing.size(), 3u);
  EXPECT_NE(missing[1].find("meshes/torus_knot.obj"), std::string::npos) << missing[1];
  EXPECT_NE(missing[1].find("object \"knot\""), std::string::npos) << missing[1];
  EXPECT_EQ(std::get<MeshDesc>(document.scene().objects[1].shape).path,
            "meshes/torus_knot.obj");  // kept as written
  fs::remove_all(folder);
}

}  // namespace
}  // namespace inkray
