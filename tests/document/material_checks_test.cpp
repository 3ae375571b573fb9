// Document checks for toon and mix materials and stroke emitters, run on
// SceneDesc values directly (the broken-file table in json_io_test covers the
// same messages through the reader), and compiling toon ramps and long mix chains.
#include "core/image/image_io.h"
#include "core/compiler/compile.h"
#include "core/document/json_io.h"
#include "core/document/scene_checks.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace inkray {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> problems(const SceneDesc& scene,
                                  const fs::path& base_dir = fs::temp_directory_path()) {
  ErrorLog log("scene");
  check_scene(scene, base_dir, log);
  return log.take();
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

SceneDesc with_ground() {
  SceneDesc d;
  d.materials.push_back({"white", DiffuseDesc{}, {}});
  d.objects.push_back({"ground", QuadDesc{}, {}, "white", true, {}});
  return d;
}

MaterialDesc mix(std::string name, std::string a, std::string b) {
  return {std::move(name), MixDesc{std::move(a), std::move(b), Color(0.5f)}, {}};
}

TEST(SceneJsonMaterialChecks, MixesThatShareSidesAreNoCycle) {
  SceneDesc d = with_ground();
  d.materials.push_back(mix("top", "left", "right"));  // refers forward
  d.materials.push_back(mix("left", "white", "bottom"));
  d.materials.push_back(mix("right", "bottom", "bottom"));
  d.materials.push_back(mix("bottom", "white", "white"));
  EXPECT_TRUE(problems(d).empty()) << joined(problems(d));
  d.objects[0].material = "top";
  EXPECT_TRUE(compile_scene(d).scene);
}

TEST(SceneJsonMaterialChecks, EachCycleIsReportedOnceWithItsChain) {
  SceneDesc d = with_ground();
  d.materials.push_back(mix("a", "b", "white"));
  d.materials.push_back(mix("b", "c", "white"));
  d.materials.push_back(mix("c", "white", "a"));
  d.materials.push_back(mix("after", "a", "white"));  // behind the cycle, not on it
  const std::vector<std::string> p = problems(d);
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_EQ(p[0],
            "scene: materials[3].b: mixes refer to each other in a cycle: \"a\" -> \"b\" -> \"c\" -> \"a\"");
}

TEST(SceneJsonMaterialChecks, LongMixChainsNeedNoRecursion) {
  constexpr int kChain = 50000;
  SceneDesc d = with_ground();
  auto name = [](int i) { return std::string("m").append(std::to_string(i)); };
  for (int i = 0; i < kChain; ++i)
    d.materials.push_back(mix(name(i), "white", i + 1 < kChain ? name(i + 1) : "white"));
  d.objects[0].material = "m0";
  EXPECT_TRUE(problems(d).empty());
  const CompileResult compiled = compile_scene(d);
  ASSERT_TRUE(compiled.scene);
  // Closing the chain into a loop: one report, and compilation ends with errors.
  std::get<MixDesc>(d.materials.back().data).b = "m0";
  const std::vector<std::string> p = problems(d);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("materials[50000].b: mixes refer to each other in a cycle: \"m0\" -> \"m1\""),
            std::string::npos)
      << p[0].substr(0, 200);
  EXPECT_FALSE(compile_scene(d).scene);
}

TEST(SceneJsonMaterialChecks, MixSidesMustExist) {
  SceneDesc d = with_ground();
  d.materials.push_back(mix("worn", "paint", "rust"));
  const std::vector<std::string> p = problems(d);
  ASSERT_EQ(p.size(), 2u) << joined(p);
  EXPECT_EQ(p[0], "scene: materials[1].a: no material named \"paint\" (defined: white, worn)");
  EXPECT_EQ(p[1], "scene: materials[1].b: no material named \"rust\" (defined: white, worn)");
}

// A fresh directory per test, removed afterwards.
struct ScratchDir {
  fs::path path = fs::temp_directory_path() /
                  ("inkray_material_checks_" +
                   std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
                   std::to_string(::getpid()));
  ScratchDir() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

TEST(SceneJsonMaterialChecks, ToonRampImageIsCheckedAndLoaded) {
  ScratchDir dir;
  SceneDesc d = with_ground();
  ToonDesc toon;
  toon.ramp_image = "ramp.png";
  toon.ramp_axis = ToonRampAxis::facing;
  d.materials.push_back({"cel", toon, {}});
  d.objects[0].material = "cel";
  const std::vector<std::string> missing = problems(d, dir.path);
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_NE(missing[0].find("materials[1].ramp_image: file not found: ramp.png"), std::string::npos)
      << missing[0];

  RgbImage ramp;
  ramp.width = 4;
  ramp.height = 2;
  ramp.pixels.assign(8, Color(0.5f));
  std::string error;
  ASSERT_TRUE(write_image(dir.path / "ramp.png", ramp, &error)) << error;
  EXPECT_TRUE(problems(d, dir.path).empty());
  d.base_dir = dir.path;
  const CompileResult compiled = compile_scene(d);
  ASSERT_TRUE(compiled.scene);
  const auto& m = std::get<ToonMaterial>(compiled.scene->world->materials[1]);
  ASSERT_TRUE(m.ramp_image);
  EXPECT_EQ(m.ramp_image->width, 4);
  EXPECT_EQ(m.ramp_axis, ToonRampAxis::facing);
}

TEST(SceneJsonMaterialChecks, ToonAndMixLoadFromJson) {
  const char* text = R"({"format": "inkray-scene", "version": 1,
    "materials": [
      {"name": "blend", "type": "mix", "a": "cel", "b": "white", "factor": 0.25},
      {"name": "cel", "type": "toon", "color": [0.9, 0.4, 0.3], "bands": 3, "threshold": 0.4, "rim": true,
       "ramp": [[0, 0, 0], [1, 0.5, 0.2]]},
      {"name": "white", "type": "diffuse"}],
    "objects": [{"name": "ball", "material": "blend", "shape": {"type": "sphere"}}]})";
  const SceneLoadResult r = parse_scene(text, fs::temp_directory_path(), "toon.json");
  ASSERT_TRUE(r) << joined(r.errors);
  const CompileResult compiled = compile_scene(*r.scene);
  ASSERT_TRUE(compiled.scene);
  const auto& blend = std::get<MixMaterial>(compiled.scene->world->materials[0]);
  EXPECT_EQ(blend.a, 1u);
  EXPECT_EQ(blend.b, 2u);
  const auto& cel = std::get<ToonMaterial>(compiled.scene->world->materials[1]);
  EXPECT_EQ(cel.bands, 3);
  EXPECT_TRUE(cel.rim);
  EXPECT_EQ(cel.ramp->size(), 2u);
}

TEST(SceneJsonStrokeChecks, UnnamedEmittersAreNamedByIndex) {
  SceneDesc d = with_ground();
  d.strokes.resize(3);
  d.strokes[0].name = "strokes_1";
  for (StrokeEmitterDesc& e : d.strokes) e.object = "ground";
  name_unnamed(d);
  EXPECT_EQ(d.strokes[0].name, "strokes_1");
  EXPECT_EQ(d.strokes[1].name, "strokes_1_1");  // "strokes_1" is taken
  EXPECT_EQ(d.strokes[2].name, "strokes_2");
  EXPECT_TRUE(problems(d).empty()) << joined(problems(d));
}

TEST(SceneJsonStrokeChecks, BrushImageMattersOnlyForImageBrushes) {
  SceneDesc d = with_ground();
  StrokeEmitterDesc e;
  e.name = "grass";
  e.object = "ground";
  e.brush = BrushKind::bristle;
  e.brush_image = "no/such/brush.png";  // kept from an earlier edit; unused
  d.strokes.push_back(e);
  EXPECT_TRUE(problems(d).empty()) << joined(problems(d));
  d.strokes[0].brush = BrushKind::image;
  const std::vector<std::string> p = problems(d);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("strokes[0].brush_image: file not found: no/such/brush.png"), std::string::npos)
      << p[0];
}

TEST(SceneJsonStrokeChecks, RangesAndObjectsAreChecked) {
  SceneDesc d = with_ground();
  StrokeEmitterDesc e;
  e.name = "grass";
  e.object = "ground";
  e.width_min = e.width_max = 0.1f;  // equal is fine
  d.strokes.push_back(e);
  EXPECT_TRUE(problems(d).empty());
  d.strokes[0].object = "lawn";
  d.strokes[0].length_min = 2.f;
  const std::vector<std::string> p = problems(d);
  ASSERT_EQ(p.size(), 2u) << joined(p);
  EXPECT_EQ(p[0], "scene: strokes[0].object: no object named \"lawn\" (defined: ground)");
  EXPECT_EQ(p[1], "scene: strokes[0].length_min: must not exceed length_max (2 > 0.25)");
}

}  // namespace
}  // namespace inkray
