// An edit of a stroke emitter's brush (its kind, pressure, image, or the image changed on
// disk, missing or found again) gives the strokes a new texture for their alpha test and
// nothing else: the same ribbons in the same BVH under the last compile's top level, and
// the image the edited document gives compiled from scratch.
#include "core/compiler/compile.h"
#include "core/document/json_io.h"
#include "tests/support/file_helpers.h"
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace inkray {
namespace {

namespace fs = std::filesystem;
const fs::path kScenes = INKRAY_SOURCE_DIR "/scenes";
const fs::path kBrushes = INKRAY_SOURCE_DIR "/resources/brushes";

// strokes_150.json, small, in `folder` with the shipped brush images beside it.
SceneDesc painted_ball(const fs::path& folder) {
  const SceneLoadResult loaded = load_scene(kScenes / "strokes_150.json");
  EXPECT_TRUE(loaded) << (loaded.errors.empty() ? "" : loaded.errors.front());
  SceneDesc scene = loaded ? *loaded.scene : SceneDesc{};
  scene.render.width = 64;
  scene.render.height = 48;
  scene.base_dir = folder;
  for (const char* brush : {"dab.png", "dry_bristle.png", "palette_knife.png"})
    fs::copy_file(kBrushes / brush, folder / brush);
  return scene;
}

CompileOptions with_stand_ins() {
  CompileOptions options;
  options.stand_in_for_missing_assets = true;
  return options;
}

uint32_t compiled_object(const RenderScene& scene, const std::string& name) {
  for (uint32_t o = 0; o < scene.world->objects.size(); ++o)
    if (scene.world->objects[o].name == name) return o;
  ADD_FAILURE() << "no compiled object " << name;
  return 0;
}

struct BrushEdit {
  std::string what;
  std::function<void(SceneDesc&)> apply;
};

TEST(BrushEdits, KeepTheStrokesBvhAndTopLevelAndRenderAsFromScratch) {
  testing::ScratchFolder folder;
  SceneDesc scene = painted_ball(folder.path());
  const fs::path image = folder / "dry_bristle.png";
  const auto brush = [](SceneDesc& s) -> StrokeEmitterDesc& { return s.strokes[0]; };
  const std::vector<BrushEdit> edits = {
      {"bristle to flat", [&](SceneDesc& s) { brush(s).brush = BrushKind::flat; }},
      {"the flat brush's pressure", [&](SceneDesc& s) { brush(s).pressure = 0.2f; }},
      {"flat to an image",
       [&](SceneDesc& s) {
         brush(s).brush = BrushKind::image;
         brush(s).brush_image = "dab.png";
       }},
      {"another image", [&](SceneDesc& s) { brush(s).brush_image = "dry_bristle.png"; }},
      {"the image changed on disk",
       [&](SceneDesc&) {
         fs::copy_file(kBrushes / "palette_knife.png", image, fs::copy_options::overwrite_existing);
       }},
      {"the image missing (the stand-in checker)", [&](SceneDesc&) { fs::remove(image); }},
      {"the image found again", [&](SceneDesc&) { fs::copy_file(kBrushes / "dab.png", image); }},
      {"image to bristle",
       [&](SceneDesc& s) {
         brush(s).brush = BrushKind::bristle;
         brush(s).bristles = 5.f;
       }},
  };

  SceneCompiler compiler;
  CompileResult last = compiler.compile(scene, with_stand_ins());
  ASSERT_TRUE(last.scene) << (last.errors.empty() ? "" : last.errors.front());
  const uint32_t strokes = compiled_object(*last.scene, "ball_strokes");
  const ShapeBvh* ribbons = &last.scene->world->geometry.bvh(strokes);
  for (const BrushEdit& edit : edits) {
    SCOPED_TRACE(edit.what);
    edit.apply(scene);
    const CompileCounters before = compiler.counters();
    const CompileResult c = compiler.compile(scene, with_stand_ins());
    ASSERT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
    const CompileCounters& after = compiler.counters();
    EXPECT_EQ(after.stroke_sets, before.stroke_sets) << "the strokes grew again";
    EXPECT_EQ(after.shape_bvhs, before.shape_bvhs) << "a BVH was built";
    ASSERT_EQ(compiled_object(*c.scene, "ball_strokes"), strokes);
    EXPECT_EQ(&c.scene->world->geometry.bvh(strokes), ribbons);
    EXPECT_TRUE(c.scene->world->geometry.shares_top_level(last.scene->world->geometry))
        << "a new brush is placed in the last top level, not in a new one";
    EXPECT_NE(c.scene->world->geometry.alpha_texture(strokes),
              last.scene->world->geometry.alpha_texture(strokes));

    const RgbImage edited = testing::render_one_pass(c.scene);
    const CompileResult fresh = SceneCompiler().compile(scene, with_stand_ins());
    ASSERT_TRUE(fresh.scene);
    EXPECT_EQ(testing::differing_pixels(edited, testing::render_one_pass(fresh.scene)), 0u)
        << "the edited scene renders otherwise than one compiled from scratch";
    EXPECT_GT(testing::differing_pixels(edited, testing::render_one_pass(last.scene)), 0u)
        << "the new brush is not seen";
    last = c;
  }
}

}  // namespace
}  // namespace inkray
