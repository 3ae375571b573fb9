// The promise behind every Save: what the writer writes, the reader reads back to the
// same document and the same picture. Held over every scene the project ships and
// every file in tests/data/scenes/valid, through the editor's own Save As.
#include "core/document/json_io.h"

#include "tests/support/messages.h"
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace inkray {
namespace {

namespace fs = std::filesystem;

using testing::joined;

std::vector<fs::path> shipped_scenes() {
  std::vector<fs::path> files;
  for (const fs::path& dir : {fs::path(INKRAY_SOURCE_DIR) / "scenes",
                              fs::path(INKRAY_SOURCE_DIR) / "tests" / "data" / "scenes" / "valid"}) {
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.path().extension() == ".json") files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Small and cheap, but every feature still runs: strokes are built, lines traced.
RgbImage thumbnail(SceneDesc scene) {
  scene.render.width = 24;
  scene.render.height = 16;
  return testing::render_scene(scene, 2, 1);
}

bool identical(const RgbImage& a, const RgbImage& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

TEST(SceneRoundTrip, EveryShippedSceneSavesReopensAndRendersTheSame) {
  const fs::path out_dir = fs::temp_directory_path() / ("inkray_round_trip_" + std::to_string(::getpid()));
  fs::create_directories(out_dir);
  const std::vector<fs::path> files = shipped_scenes();
  ASSERT_GE(files.size(), 15u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    SceneLoadResult first = load_scene(file);
    ASSERT_TRUE(first) << joined(first.errors);

    // Saved into another folder, as Save As does: asset paths must follow.
    const fs::path saved = out_dir / file.filename();
    std::string error;
    ASSERT_TRUE(save_scene_as(*first.scene, saved, &error)) << error;
    SceneLoadResult second = load_scene(saved);
    ASSERT_TRUE(second) << joined(second.errors);

    // Written again from where it now lives, the text is a fixed point.
    const fs::path again = out_dir / ("again_" + file.filename().string());
    ASSERT_TRUE(save_scene_as(*second.scene, again, &error)) << error;
    SceneLoadResult third = load_scene(again);
    ASSERT_TRUE(third) << joined(third.errors);
    EXPECT_EQ(scene_to_string(*third.scene), scene_to_string(*second.scene));

    // Same document in memory, whatever folder the paths are relative to.
    SceneDesc rebased = *second.scene;
    EXPECT_TRUE(identical(thumbnail(*first.scene), thumbnail(rebased)))
        << "the reopened scene renders differently";
  }
  fs::remove_all(out_dir);
}

// Unset optional paths used to be written as "", which the reader refused: every toon
// material and stroke emitter without an image made its scene unloadable once saved.
TEST(SceneRoundTrip, UnsetOptionalPathsAreLeftOutAndEmptyOnesStillOpen) {
  const fs::path legacy =
      fs::path(INKRAY_SOURCE_DIR) / "tests" / "data" / "scenes" / "valid" / "legacy_empty_paths.json";
  SceneLoadResult loaded = load_scene(legacy);
  ASSERT_TRUE(loaded) << joined(loaded.errors);
  ASSERT_EQ(loaded.scene->materials.size(), 1u);
  EXPECT_TRUE(std::get<ToonDesc>(loaded.scene->materials[0].data).ramp_image.empty());
  EXPECT_EQ(loaded.scene->objects[0].name, "object_0");

  const std::string text = scene_to_string(*loaded.scene);
  EXPECT_EQ(text.find("\"ramp_image\""), std::string::npos) << text;
  EXPECT_EQ(text.find("\"brush_image\""), std::string::npos) << text;
  EXPECT_EQ(text.find("\"\""), std::string::npos) << "no empty strings are written:\n" << text;
  SceneLoadResult reread = parse_scene(text, loaded.scene->base_dir, "re-saved");
  ASSERT_TRUE(reread) << joined(reread.errors);
  EXPECT_EQ(scene_to_string(*reread.scene), text);
}

// A required path stays required: "" is still refused with the key named.
TEST(SceneRoundTrip, EmptyRequiredPathIsStillAnError) {
  const char* text = R"({"format": "inkray-scene", "version": 1,
    "materials": [{"name": "m", "type": "diffuse", "albedo": {"type": "image", "path": ""}}]})";
  SceneLoadResult r = parse_scene(text, {}, "t.json");
  ASSERT_FALSE(r);
  EXPECT_NE(joined(r.errors).find("materials[0].albedo.path: no file given"), std::string::npos)
      << joined(r.errors);
}

}  // namespace
}  // namespace inkray
