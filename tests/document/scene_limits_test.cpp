// Inputs that are legal JSON but would crash the ray engine or exhaust the machine:
// each is refused with a message naming the key or file, before any large allocation.
#include "core/geometry/embree_scene.h"
#include "core/image/image_header.h"
#include "core/image/image_io.h"
#include "core/compiler/compile.h"
#include "core/document/json_io.h"
#include "core/document/memory_budget.h"
#include "core/document/scene_checks.h"

#include "tests/support/file_helpers.h"
#include "tests/support/render_helpers.h"
#include "tests/support/messages.h"
#include "tests/support/png_header.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace inkray {
namespace {

namespace fs = std::filesystem;

using testing::joined;

SceneDesc one_sphere() { return testing::one_sphere_scene(8, 8); }

// [1e19, 1, 5] used to reach Embree, whose assertions abort the process (exit 134).
TEST(SceneLimits, CameraBeyondTheRayEngineRangeIsAnError) {
  const char* text = R"({"format": "inkray-scene", "version": 1, "camera": {"look_from": [1e19, 1, 5]}})";
  SceneLoadResult r = parse_scene(text, {}, "far.json");
  ASSERT_FALSE(r);
  EXPECT_NE(
      joined(r.errors).find(
          "far.json: camera.look_from: expected an array of 3 numbers, each in [-1000000000, 1000000000]"),
      std::string::npos)
      << joined(r.errors);
  // Every position and offset has the same bound.
  r = parse_scene(R"({"format": "inkray-scene", "version": 1, "materials": [{"name": "m"}],
      "objects": [{"material": "m", "shape": {"type": "sphere"}, "transform": {"translate": [0, -2e9, 0]}}]})",
                  {}, "t.json");
  ASSERT_FALSE(r);
  EXPECT_NE(joined(r.errors).find("objects[0].transform.translate"), std::string::npos) << joined(r.errors);
}

// Each factor is in range; together they put the sphere beyond what rays can start from.
TEST(SceneLimits, TransformedGeometryBeyondTheWorldLimitIsACompileError) {
  SceneDesc s = one_sphere();
  std::get<SphereDesc>(s.objects[0].shape).radius = 1e12f;
  s.objects[0].transform.scale = Vec3(1e9f);
  const CompileResult c = compile_scene(s);
  EXPECT_FALSE(c.scene);
  EXPECT_NE(joined(c.errors).find("objects[0] \"ball\": after its transform the shape reaches"),
            std::string::npos)
      << joined(c.errors);
}

// The last line of defence: a ray from a huge or non-finite origin is a miss, not an abort.
TEST(SceneLimits, RaysFromUntraceableOriginsMissInsteadOfAborting) {
  EmbreeScene scene;
  scene.add(Sphere{Point3(0.f), 1.f, Transform{}});
  scene.commit();
  Hit hit;
  EXPECT_TRUE(scene.intersect(Ray{Point3(0.f, 0.f, 5.f), Vec3(0.f, 0.f, -1.f)}, 1e30f, &hit));
  for (const Point3 origin : {Point3(1e19f, 1.f, 5.f), Point3(std::numeric_limits<float>::infinity()),
                              Point3(std::numeric_limits<float>::quiet_NaN())}) {
    EXPECT_FALSE(scene.intersect(Ray{origin, Vec3(0.f, 0.f, -1.f)}, 1e30f, &hit));
    EXPECT_FALSE(scene.occluded(Ray{origin, Vec3(0.f, 0.f, -1.f)}, 1e30f));
  }
}

TEST(SceneLimits, StrokeVerticesHaveOneBudgetAcrossEmitters) {
  SceneDesc s = one_sphere();
  const StrokeEmitterDesc huge{.name = "huge", .object = "ball", .count = 10000000, .segments = 64};
  s.strokes = {huge};
  ErrorLog log("s.json");
  check_scene(s, {}, log);
  std::string text = joined(log.take());
  EXPECT_NE(text.find("s.json: strokes[0].count: the strokes up to this emitter need 1300000000 vertices"),
            std::string::npos)
      << text;

  // Each emitter alone fits; the third one tips the total over.
  StrokeEmitterDesc big = huge;
  big.count = 1500000;
  big.segments = 8;  // 27 million vertices each
  s.strokes = {big, big, big};
  for (int i = 0; i < 3; ++i) s.strokes[size_t(i)].name = "e" + std::to_string(i);
  EXPECT_LT(stroke_vertex_count(big), kMaxStrokeVertices);
  check_scene(s, {}, log);
  text = joined(log.take());
  EXPECT_EQ(text.find("strokes[0].count"), std::string::npos) << text;
  EXPECT_NE(text.find("strokes[1].count: the strokes up to this emitter need"), std::string::npos) << text;
}

// A 1 KB file claiming 18000 x 18000 pixels is refused from its header.
TEST(SceneLimits, ImageSizeIsCheckedFromTheHeaderBeforeDecoding) {
  testing::ScratchFolder dir;
  const fs::path big = dir.path() / "big.png";
  testing::write_png_header(big, 18000, 18000);
  RgbImage image;
  std::string error;
  EXPECT_FALSE(read_image(big, true, &image, &error));
  EXPECT_NE(
      error.find("big.png: the image is 18000 x 18000 pixels; inkray reads images of at most 8192 x 8192"),
      std::string::npos)
      << error;
  EXPECT_TRUE(image.pixels.empty());

  // The same file as a texture: compile names the material.
  SceneDesc s = one_sphere();
  s.base_dir = dir.path();
  s.materials[0].data = DiffuseDesc{ImageTextureDesc{"big.png", Color(1.f), true}};
  const CompileResult c = compile_scene(s);
  EXPECT_FALSE(c.scene);
  EXPECT_NE(joined(c.errors).find("big.png: the image is 18000 x 18000"), std::string::npos)
      << joined(c.errors);

  // And as a brush image.
  s = one_sphere();
  s.base_dir = dir.path();
  s.strokes = {StrokeEmitterDesc{
      .name = "paint", .object = "ball", .count = 10, .brush = BrushKind::image, .brush_image = "big.png"}};
  const CompileResult b = compile_scene(s);
  EXPECT_FALSE(b.scene);
  EXPECT_NE(joined(b.errors).find("strokes[0] \"paint\": "), std::string::npos) << joined(b.errors);
  EXPECT_NE(joined(b.errors).find("18000 x 18000"), std::string::npos) << joined(b.errors);
}

// Five images, each allowed alone, are more than a scene may decode together.
TEST(SceneLimits, ImagesHaveABudgetPerScene) {
  testing::ScratchFolder dir;
  SceneDesc s = one_sphere();
  s.base_dir = dir.path();
  s.materials.clear();
  for (int i = 0; i < 5; ++i) {
    const std::string name = "t" + std::to_string(i) + ".png";
    testing::write_png_header(dir.path() / name, 8192, 8192, 16384);  // as long as a real 1-bit PNG could be
    s.materials.push_back(
        {"m" + std::to_string(i), DiffuseDesc{ImageTextureDesc{name, Color(1.f), true}}, {}});
  }
  s.objects[0].material = "m0";
  std::vector<std::string> errors;
  check_memory_budget(s, std::uint64_t(1) << 50, errors);
  ASSERT_EQ(errors.size(), 1u) << joined(errors);
  EXPECT_NE(errors[0].find("the scene's images have 335544320 texels together"), std::string::npos)
      << errors[0];
}

TEST(SceneLimits, MemoryEstimateIsCheckedBeforeBuilding) {
  SceneDesc s = one_sphere();
  s.render.width = 1920;
  s.render.height = 1080;
  s.strokes = {StrokeEmitterDesc{.name = "paint", .object = "ball", .count = 1000000}};
  const MemoryEstimate estimate = estimate_memory(s);
  ASSERT_GE(estimate.items.size(), 3u);
  EXPECT_EQ(estimate.items[0].what, "strokes[0] (1000000 strokes)");  // largest first
  EXPECT_GT(estimate.total, std::uint64_t(1) << 30);

  CompileOptions options;
  options.memory_limit = std::uint64_t(256) << 20;
  const CompileResult c = compile_scene(s, options);
  EXPECT_FALSE(c.scene);
  ASSERT_EQ(c.errors.size(), 1u) << joined(c.errors);
  EXPECT_NE(c.errors[0].find("the scene would need about"), std::string::npos) << c.errors[0];
  EXPECT_NE(c.errors[0].find("strokes[0] (1000000 strokes): "), std::string::npos) << c.errors[0];
  EXPECT_NE(c.errors[0].find("more than the limit of 256 MiB"), std::string::npos) << c.errors[0];

  // The default limit is half the machine's memory.
  EXPECT_EQ(default_memory_limit(), physical_memory_bytes() / 2);
}

}  // namespace
}  // namespace inkray
