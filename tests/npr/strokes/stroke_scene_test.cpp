// Stroke emitters through compile_scene: the example stroke scenes render
// without a non-finite value, strokes change the image, and emitter errors
// name the emitter.
#include "core/document/json_io.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace inkray {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(INKRAY_SOURCE_DIR) / "scenes";

SceneDesc load(const std::string& name, int height) {
  const auto loaded = load_scene(kScenes / name);
  EXPECT_TRUE(loaded.scene) << (loaded.errors.empty() ? "" : loaded.errors.front());
  SceneDesc d = loaded.scene ? *loaded.scene : SceneDesc{};
  d.render.width = height * d.render.width / std::max(1, d.render.height);
  d.render.height = height;
  return d;
}

void expect_finite(const SceneDesc& d, int spp) {
  RenderStats stats;
  const RgbImage img = testing::render_scene(d, spp, 2, &stats);
  EXPECT_EQ(stats.nonfinite_samples, 0u);
  for (const Color& c : img.pixels) ASSERT_TRUE(is_finite(c));
}

TEST(StrokeScenes, StrokeScenesRenderFinite) {
  for (const char* name : {"strokes_150.json", "strokes_mesh.json"}) {
    SCOPED_TRACE(name);
    expect_finite(load(name, 72), 8);
  }
}

TEST(StrokeScenes, StrokesChangeWhatTheCameraSees) {
  SceneDesc d = load("strokes_150.json", 48);
  const RgbImage painted = testing::render_scene(d, 4);
  d.strokes.clear();
  const RgbImage bare = testing::render_scene(d, 4);
  ASSERT_EQ(painted.pixels.size(), bare.pixels.size());
  double diff = 0.0;
  for (size_t i = 0; i < bare.pixels.size(); ++i) diff += glm::length(painted.pixels[i] - bare.pixels[i]);
  EXPECT_GT(diff / double(bare.pixels.size()), 0.01);
}

TEST(StrokeScenes, EmitterErrorsNameTheEmitter) {
  SceneDesc d = load("strokes_150.json", 16);
  d.strokes[0].brush = BrushKind::image;
  d.strokes[0].brush_image = "no_such_brush.png";
  CompileResult c = compile_scene(d);
  EXPECT_FALSE(c.scene);
  ASSERT_FALSE(c.errors.empty());
  // The JSON path names the emitter (compile_scene checks the document first).
  EXPECT_NE(c.errors.front().find("strokes[0].brush_image: file not found: no_such_brush.png"),
            std::string::npos)
      << c.errors.front();
}

TEST(StrokeScenes, HiddenObjectGrowsNoStrokes) {
  SceneDesc d = load("strokes_150.json", 16);
  for (ObjectDesc& o : d.objects)
    if (o.name == d.strokes[0].object) o.visible = false;
  CompileResult c = compile_scene(d);
  ASSERT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
  for (uint32_t i = 0; i < c.scene->world->geometry.shape_count(); ++i)
    EXPECT_FALSE(c.scene->world->geometry.alpha_mask(i));
}

}  // namespace
}  // namespace inkray
