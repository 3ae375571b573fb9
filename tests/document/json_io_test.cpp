// Scene files: lossless save -> load round trips, atomic saving, and one broken file
// per kind of mistake, each checked for the message a user would need to fix it.
#include "core/document/json_io.h"

#include "core/document/json_write.h"
#include "core/document/scene_checks.h"
#include "core/document/tagged_variant.h"
#include "tests/support/damaged_text.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace inkray {
namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(INKRAY_SOURCE_DIR) / "tests" / "data";
const fs::path kBroken = kData / "scenes" / "broken";
const fs::path kValid = kData / "scenes" / "valid";

std::string read_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

// A fresh directory per test, removed afterwards.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / ("inkray_" + std::string(info->test_suite_name()) + "_" +
                                         info->name() + "_" + std::to_string(::getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  fs::path path_;
};

ObjectDesc make_object(std::string name, ShapeVariant shape, std::string material, bool visible = true) {
  ObjectDesc o;
  o.name = std::move(name);
  o.shape = std::move(shape);
  o.material = std::move(material);
  o.visible = visible;
  return o;
}

// Every material, shape, light and texture type, with values that are awkward as decimals.
SceneDesc every_type_scene() {
  SceneDesc s;
  s.camera.look_from = {1.f / 3.f, -2.5e-7f, 1234.5678f};
  s.camera.look_at = {0.1f, 0.2f, 0.3f};
  s.camera.up = {0.f, 0.f, 1.f};
  s.camera.vfov = 33.3f;
  s.camera.aperture = 0.05f;
  s.camera.focus_distance = 7.7f;
  s.render = {.width = 320,
              .height = 200,
              .spp = 3,
              .time_limit = 1.5f,
              .max_depth = 5,
              .seed = 42,
              .clamp = 10.f,
              .filter = PixelFilter::gaussian,
              .filter_radius = 1.25f};
  s.environment = GradientEnvironmentDesc{{0.1f, 0.2f, 0.3f}, {0.4f, 0.5f, 0.6f}, {0.7f, 0.8f, 0.9f}};

  const std::string texture = (kValid / "textures" / "checker.png").string();
  const std::string mesh = (kData / "meshes" / "cube.obj").string();
  s.materials = {
      {"plain", DiffuseDesc{Color(0.1f, 0.2f, 0.3f)}, {}},
      {"imaged", DiffuseDesc{ImageTextureDesc{texture, Color(0.5f), false}}, {}},
      {"checked", DiffuseDesc{CheckerTextureDesc{Color(0.9f), Color(0.05f, 0.1f, 0.15f), 3.5f}}, {}},
      {"metal", ConductorDesc{CheckerTextureDesc{}, 0.35f}, {}},
      {"glass", DielectricDesc{1.33f, 0.1f, Color(0.9f, 1.f, 0.95f)}, {}},
      {"lamp", EmissiveDesc{ImageTextureDesc{texture, Color(2.f), true}, 12.5f, true}, {}},
      {"flat", UnlitDesc{Color(0.25f)}, {}},
      {"clear", TransparentDesc{Color(0.6f)}, {}},
  };
  ObjectDesc sphere = make_object("ball", SphereDesc{{1.f, 2.f, 3.f}, 0.75f}, "plain");
  ObjectDesc quad =
      make_object("card", QuadDesc{{-1.f, 0.f, -1.f}, {2.f, 0.f, 0.f}, {0.f, 0.f, 2.f}}, "checked", false);
  quad.transform.rotate = {{{1.f, 0.f, 0.f}, 90.f}, {{0.f, 1.f, 0.f}, -12.5f}};
  ObjectDesc box = make_object("crate", BoxDesc{{-1.f, -1.f, -1.f}, {1.f, 2.f, 3.f}}, "metal");
  box.transform.scale = {2.f, 0.5f, -1.f};
  box.transform.translate = {10.f, 0.f, -3.25f};
  ObjectDesc model = make_object("model", MeshDesc{mesh}, "glass");
  s.objects = {sphere, quad, box, model};
  s.lights = {
      {"bulb", PointLightDesc{{0.f, 5.f, 0.f}, Color(1.f, 0.9f, 0.8f), 50.f}},
      {"stage", SpotLightDesc{{1.f, 4.f, 1.f}, {0.f, 0.f, 0.f}, Color(1.f), 80.f, 35.f, 20.f}},
      {"sun", DirectionalLightDesc{{0.3f, -1.f, 0.2f}, Color(1.f, 1.f, 0.9f), 3.f}},
  };
  return s;
}

SceneDesc save_and_load(const SceneDesc& scene, const fs::path& file) {
  std::string error;
  EXPECT_TRUE(save_scene(scene, file, &error)) << error;
  SceneLoadResult loaded = load_scene(file);
  EXPECT_TRUE(loaded) << joined(loaded.errors);
  return loaded ? *loaded.scene : SceneDesc{};
}

// ---------------------------------------------------------------- round trips
TEST(SceneJsonRoundTrip, EveryTypeIsLossless) {
  ScratchDir dir;
  for (const bool gradient : {true, false}) {
    SceneDesc original = every_type_scene();
    if (!gradient) original.environment = ConstantEnvironmentDesc{Color(0.125f, 0.f, 3.f)};
    const SceneDesc loaded = save_and_load(original, dir.path() / "every_type.json");
    EXPECT_EQ(scene_to_string(loaded), scene_to_string(original));
    EXPECT_EQ(loaded.base_dir, dir.path());

    // Spot checks that the comparison above is comparing something.
    EXPECT_EQ(loaded.camera.look_from.x, 1.f / 3.f);
    EXPECT_EQ(loaded.camera.look_from.y, -2.5e-7f);
    EXPECT_EQ(loaded.render.filter, PixelFilter::gaussian);
    ASSERT_EQ(loaded.materials.size(), 8u);
    const auto& lamp = std::get<EmissiveDesc>(loaded.materials[5].data);
    EXPECT_EQ(std::get<ImageTextureDesc>(lamp.color).scale, Color(2.f));
    EXPECT_TRUE(lamp.two_sided);
    EXPECT_FALSE(std::get<ImageTextureDesc>(std::get<DiffuseDesc>(loaded.materials[1].data).albedo).srgb);
    ASSERT_EQ(loaded.objects.size(), 4u);
    EXPECT_FALSE(loaded.objects[1].visible);
    ASSERT_EQ(loaded.objects[1].transform.rotate.size(), 2u);
    EXPECT_EQ(loaded.objects[1].transform.rotate[1].degrees, -12.5f);
    EXPECT_EQ(std::get<BoxDesc>(loaded.objects[2].shape).max, Point3(1.f, 2.f, 3.f));
    EXPECT_EQ(std::get<SpotLightDesc>(loaded.lights[1].data).falloff_angle, 20.f);
    EXPECT_EQ(loaded.environment.index(), original.environment.index());
  }
}

TEST(SceneJsonRoundTrip, ParsedFileIsLossless) {
  SceneLoadResult first = load_scene(kValid / "cornell.json");
  ASSERT_TRUE(first) << joined(first.errors);
  const std::string text = scene_to_string(*first.scene);
  // Re-parse beside the original so its relative asset paths still resolve.
  SceneLoadResult second = parse_scene(text, first.scene->base_dir, "cornell (re-saved)");
  ASSERT_TRUE(second) << joined(second.errors);
  EXPECT_EQ(scene_to_string(*second.scene), text);
  EXPECT_EQ(scene_to_json(*second.scene), scene_to_json(*first.scene));
}

TEST(SceneJsonRoundTrip, FloatsSurviveBitForBit) {
  // Random bit patterns cover every exponent, subnormals and awkward mantissas.
  std::mt19937 rng(1234);
  std::vector<float> values;
  while (values.size() < 30000) {
    const float f = std::bit_cast<float>(static_cast<std::uint32_t>(rng()));
    if (!std::isfinite(f)) continue;
    // Beyond positions' range (kMaxCoordinate) the number alone must survive.
    if (std::fabs(f) > kMaxCoordinate) {
      const nlohmann::json number = float_to_json_number(f);
      ASSERT_EQ(nlohmann::json::parse(number.dump()).get<float>(), f);
      continue;
    }
    values.push_back(f);
  }
  values.insert(values.end(), {0.f, -0.f, 0.1f, 0.8f, 1e-45f, 1e9f, -1.17549435e-38f});
  SceneDesc scene;
  scene.materials = {{"m", DiffuseDesc{}, {}}};
  for (std::size_t i = 0; i + 2 < values.size(); i += 3) {
    std::string name = "s";
    name += std::to_string(i);
    scene.objects.push_back(
        make_object(name, SphereDesc{{values[i], values[i + 1], values[i + 2]}, 1.f}, "m"));
  }
  SceneLoadResult loaded = parse_scene(scene_to_string(scene), {}, "floats");
  ASSERT_TRUE(loaded) << joined(loaded.errors);
  ASSERT_EQ(loaded.scene->objects.size(), scene.objects.size());
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Point3 a = std::get<SphereDesc>(scene.objects[i].shape).center;
    const Point3 b = std::get<SphereDesc>(loaded.scene->objects[i].shape).center;
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(std::bit_cast<std::uint32_t>(a[k]), std::bit_cast<std::uint32_t>(b[k]))
          << a[k] << " object " << i;
    }
  }
}

TEST(SceneJsonRoundTrip, WriterIsExplicitOrderedAndReadable) {
  SceneLoadResult minimal = load_scene(kValid / "minimal.json");
  ASSERT_TRUE(minimal) << joined(minimal.errors);
  SceneDesc scene = *minimal.scene;
  scene.materials = {{"grey", DiffuseDesc{}, {}}};
  scene.objects = {make_object("ball", SphereDesc{}, "grey")};
  const std::string text = scene_to_string(scene);
  std::size_t previous = 0;
  for (const char* key : {"\"format\"", "\"version\"", "\"camera\"", "\"render\"", "\"environment\"",
                          "\"materials\"", "\"objects\"", "\"lights\""}) {
    const std::size_t at = text.find(key);
    ASSERT_NE(at, std::string::npos) << key;
    EXPECT_GT(at, previous) << key << " is out of order";
    previous = at;
  }
  // Defaults are written too, so files are explicit.
  for (const char* key : {"\"aperture\"", "\"time_limit\"", "\"filter\": \"box\"", "\"visible\": true",
                          "\"rotate\": []", "\"translate\""}) {
    EXPECT_NE(text.find(key), std::string::npos) << key;
  }
  // Shortest decimals, not the float's full double expansion.
  EXPECT_NE(text.find("\"albedo\": [0.8, 0.8, 0.8]"), std::string::npos) << text;
  EXPECT_EQ(text.find("0.800000011920929"), std::string::npos);
  EXPECT_EQ(text.substr(0, 4), "{\n  ");
  EXPECT_EQ(scene_to_json(scene), nlohmann::json::parse(text));
}

// ---------------------------------------------------------------- reading
TEST(SceneJsonLoad, CornellValuesAndGeneratedNames) {
  SceneLoadResult r = load_scene(kValid / "cornell.json");
  ASSERT_TRUE(r) << joined(r.errors);
  const SceneDesc& s = *r.scene;
  EXPECT_EQ(s.base_dir, fs::absolute(kValid).lexically_normal());
  EXPECT_EQ(s.camera.look_from, Point3(278.f, 278.f, -800.f));
  EXPECT_EQ(s.render.max_depth, 50);
  EXPECT_EQ(s.render.filter, PixelFilter::gaussian);
  EXPECT_EQ(s.render.seed, RenderSettings{}.seed);  // absent keys keep defaults
  EXPECT_EQ(std::get<Color>(std::get<DiffuseDesc>(s.materials[2].data).albedo),
            Color(0.73f));  // grey shorthand
  const auto& checker = std::get<CheckerTextureDesc>(std::get<DiffuseDesc>(s.materials[3].data).albedo);
  EXPECT_EQ(checker.odd, Color(0.1f));
  EXPECT_EQ(checker.scale, 8.f);
  EXPECT_EQ(std::get<ImageTextureDesc>(std::get<DiffuseDesc>(s.materials[4].data).albedo).path,
            "textures/checker.png");  // kept relative, as written
  ASSERT_EQ(s.objects.size(), 8u);
  EXPECT_EQ(s.objects[6].name, "object_6");
  EXPECT_EQ(s.objects[7].name, "object_7");
  EXPECT_FALSE(s.objects[7].visible);
  EXPECT_EQ(std::get<MeshDesc>(s.objects[7].shape).path, "../../meshes/cube.obj");
  EXPECT_EQ(s.objects[5].transform.rotate.at(0).degrees, 15.f);
  EXPECT_EQ(s.objects[5].transform.translate, Vec3(265.f, 0.f, 295.f));
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].name, "light_0");
  EXPECT_EQ(s.lights[1].name, "sun");
}

TEST(SceneJsonLoad, GeneratedNamesAvoidExplicitOnes) {
  const char* text = R"({"format": "inkray-scene", "version": 1,
    "materials": [{"name": "m", "type": "diffuse"}],
    "objects": [{"name": "object_1", "material": "m"}, {"material": "m"}, {"material": "m"}]})";
  SceneLoadResult r = parse_scene(text, {}, "names");
  ASSERT_TRUE(r) << joined(r.errors);
  std::set<std::string> names;
  for (const ObjectDesc& o : r.scene->objects) names.insert(o.name);
  EXPECT_EQ(names.size(), 3u);
  EXPECT_TRUE(names.contains("object_2"));
}

TEST(SceneJsonLoad, MinimalFileGivesDefaults) {
  SceneLoadResult r = load_scene(kValid / "minimal.json");
  ASSERT_TRUE(r) << joined(r.errors);
  EXPECT_EQ(scene_to_string(*r.scene), scene_to_string(SceneDesc{}));
}

// The document-wide checks run on a SceneDesc directly, as the editor will after an edit.
TEST(SceneJsonChecks, RunWithoutJson) {
  SceneDesc s;
  s.render.width = s.render.height = 10000;
  s.materials = {{"m", DiffuseDesc{ImageTextureDesc{"missing.png"}}, {}}, {"m", UnlitDesc{}, {}}};
  s.objects = {make_object("", MeshDesc{"meshes/cube.obj"}, "m"), make_object("", SphereDesc{}, "gone"),
               make_object("object_0_1", SphereDesc{}, "m")};
  s.objects[0].name.clear();
  s.lights.resize(2);
  name_unnamed(s);
  EXPECT_EQ(s.objects[0].name, "object_0");
  EXPECT_EQ(s.objects[1].name, "object_1");
  EXPECT_EQ(s.lights[1].name, "light_1");
  ErrorLog log("edited");
  check_scene(s, kValid, log);
  const std::string all = joined(log.take());
  for (const char* part : {"edited: render: image size 10000 x 10000",
                           "edited: materials[1].name: duplicate material name \"m\"",
                           "edited: materials[0].albedo.path: file not found: missing.png",
                           "edited: objects[1].material: no material named \"gone\" (defined: m)"}) {
    EXPECT_NE(all.find(part), std::string::npos) << part << "\n" << all;
  }
  EXPECT_EQ(all.find("objects[0].shape.path"), std::string::npos) << all;  // meshes/cube.obj exists there
}

TEST(SceneJsonChecks, PathWithNulIsRejected) {
  const char* text =
      R"({"format": "inkray-scene", "version": 1, "materials": [{"name": "m", "type": "diffuse",
    "albedo": {"type": "image", "path": "textures/checker.png\u0000.txt"}}]})";
  SceneLoadResult r = parse_scene(text, kValid, "nul.json");
  EXPECT_FALSE(r);
  EXPECT_NE(joined(r.errors).find("nul.json: materials[0].albedo.path: expected a file path without NUL"),
            std::string::npos)
      << joined(r.errors);
}

// ---------------------------------------------------------------- saving
TEST(SceneJsonSave, ReplacesExistingFileAndLeavesNoTemporary) {
  ScratchDir dir;
  const fs::path file = dir.path() / "scene.json";
  std::ofstream(file) << "old contents";
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  const SceneDesc scene = every_type_scene();
  std::string error;
  ASSERT_TRUE(save_scene(scene, file, &error)) << error;
  EXPECT_EQ(read_file(file), scene_to_string(scene));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.json"});
  EXPECT_EQ(fs::status(file).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST(SceneJsonSave, MissingDirectoryFailsAndWritesNothing) {
  ScratchDir dir;
  const fs::path file = dir.path() / "no_such_folder" / "scene.json";
  std::string error;
  EXPECT_FALSE(save_scene(every_type_scene(), file, &error));
  EXPECT_NE(error.find(file.string()), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(file.parent_path()));
  EXPECT_TRUE(dir.entries().empty());
}

TEST(SceneJsonSave, TargetThatIsADirectoryFailsCleanly) {
  ScratchDir dir;
  fs::create_directory(dir.path() / "taken");
  std::string error;
  EXPECT_FALSE(save_scene(SceneDesc{}, dir.path() / "taken", &error));
  EXPECT_NE(error.find("taken"), std::string::npos) << error;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken"});  // the temporary was removed
  EXPECT_TRUE(fs::is_empty(dir.path() / "taken"));
}

TEST(SceneJsonSave, SavingThroughASymlinkReplacesItsTarget) {
  ScratchDir dir;
  const fs::path real = dir.path() / "real.json", link = dir.path() / "link.json";
  std::ofstream(real) << "old";
  fs::create_symlink(real.filename(), link);
  std::string error;
  ASSERT_TRUE(save_scene(SceneDesc{}, link, &error)) << error;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read_file(real), scene_to_string(SceneDesc{}));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"link.json", "real.json"}));
}

// ---------------------------------------------------------------- the format's documentation
std::string format_doc() { return read_file(fs::path(INKRAY_SOURCE_DIR) / "docs" / "scene-format.md"); }

TEST(SceneJsonDocs, ExamplesLoad) {
  const std::string doc = format_doc();
  int complete_scenes = 0;
  for (std::size_t at = doc.find("```json\n"); at != std::string::npos; at = doc.find("```json\n", at + 1)) {
    const std::size_t begin = at + 8, end = doc.find("```", begin);
    ASSERT_NE(end, std::string::npos);
    const std::string block = doc.substr(begin, end - begin);
    if (block.find("\"format\"") == std::string::npos) continue;
    ++complete_scenes;
    SceneLoadResult r = parse_scene(block, kValid, "scene-format.md example");
    EXPECT_TRUE(r) << joined(r.errors);
  }
  EXPECT_GE(complete_scenes, 1);
}

// Collects every Param name of a struct.
struct NameCollector {
  std::vector<std::string> names;
  template <class T>
  void operator()(const Param& p, T&) {
    names.emplace_back(p.name);
  }
};

// Every Param name of each struct, and of each alternative of each variant with its
// type name (quoted).
template <class... Descs>
void collect_names(NameCollector& c) {
  const auto collect = [&](auto desc) { visit_params(desc, c); };
  (collect(Descs{}), ...);
}
template <class... Variants>
void collect_alternative_names(NameCollector& c) {
  (for_each_alternative<Variants>([&]<class T>(std::type_identity<T>) {
     if constexpr (Tagged<T>) {
       c.names.push_back("\"" + std::string(T::type_name) + "\"");
       collect_names<T>(c);
     }
   }),
   ...);
}

// A parameter added to desc.h must be documented: its name appears as a table row.
TEST(SceneJsonDocs, EveryParameterIsDocumented) {
  NameCollector c;
  collect_names<CameraDesc, RenderSettings, ObjectDesc, RotationDesc, OutlineDesc, LineStyleDesc,
                LineOverrideDesc, StrokeEmitterDesc, LineSetDesc, LineSetStyleDesc, PressurePoint,
                LineTypeChoice, LinePathChoice>(c);
  collect_alternative_names<EnvironmentDesc, MaterialVariant, ColorInput, ShapeVariant, LightVariant>(c);
  const std::string doc = format_doc();
  for (const std::string& name : c.names) {
    const bool is_type = name.starts_with('"');
    const std::string row = is_type ? "`" + name + "`" : "| `" + name + "` |";
    EXPECT_NE(doc.find(row), std::string::npos) << name << " is not in docs/scene-format.md";
  }
}

// ---------------------------------------------------------------- broken files
struct BrokenCase {
  const char* file;
  std::vector<std::string> expected;  // substrings of one error line (after "<file>: ")
};

const std::vector<BrokenCase>& broken_cases() {
  static const std::vector<BrokenCase> cases = {
      {"syntax_error.json", {"line 4, column 10: ", "syntax error", "expected '}'"}},
      {"trailing_garbage.json", {"line 2, column 1: ", "expected end of input"}},
      {"empty.json", {"the file is empty"}},
      {"top_level_array.json", {"expected a JSON object at the top level, got an array"}},
      {"wrong_format.json", {"format: expected \"inkray-scene\", got \"mitsuba-scene\""}},
      {"missing_format.json", {"missing required key \"format\""}},
      {"unsupported_version.json", {"version: version 2 is newer", "(supported: 1)"}},
      {"version_not_integer.json", {"version: expected an integer", "got \"1\""}},
      {"unknown_key.json",
       {"objects[1]: unknown key \"materail\" (expected one of: name, material, visible, lines, shape, "
        "transform)"}},
      {"unknown_top_level_key.json", {"unknown key \"camrea\" (expected one of: format, version, camera"}},
      {"unknown_texture_key.json",
       {"materials[0].albedo: unknown key \"sclae\" (expected one of: type, even, odd, scale)"}},
      {"unknown_type.json",
       {"materials[2].type: unknown material type \"gold\" (expected one of: diffuse, conductor, "
        "dielectric"}},
      {"missing_type.json", {"environment: missing required key \"type\"", "constant, gradient"}},
      {"missing_material.json", {"objects[3].material: no material named \"gold\"", "white, red"}},
      {"duplicate_names.json",
       {"materials[1].name: duplicate material name \"white\" (also used by materials[0])"}},
      {"duplicate_key.json", {"camera: duplicate key \"vfov\""}},
      {"negative_width.json", {"render.width: expected an integer in [1, 16384], got -640"}},
      {"billion_spp.json", {"render.spp: expected an integer in [1, 1048576], got 1000000000"}},
      {"fractional_integer.json", {"render.max_depth: expected an integer in [1, 1024], got 7.5"}},
      {"image_too_large.json", {"render: image size 16384 x 16384", "8192 x 8192"}},
      {"huge_number.json", {"camera.look_from[0]: number 1e400 is out of range (line 3, column"}},
      {"float_overflow.json", {"camera.look_at: expected an array of 3 numbers", "got [0, 1e+300, 0]"}},
      {"short_vector.json", {"camera.up: expected an array of 3 numbers, got [0, 1]"}},
      {"string_for_number.json", {"camera.vfov: expected a number in [0.01, 179], got \"wide\""}},
      {"color_as_name.json",
       {"materials[0].albedo: expected a number or an array of 3 numbers", "got \"red\""}},
      {"color_out_of_range.json", {"materials[0].albedo: ", "each in [0, 1], got [2, 0, 0]"}},
      {"bad_choice.json", {"render.filter: expected one of \"box\", \"gaussian\", got \"lanczos\""}},
      {"wrong_bool.json", {"objects[0].visible: expected true or false, got 1"}},
      {"missing_mesh.json", {"objects[2].shape.path: file not found: meshes/bunny.obj (resolved to /"}},
      {"missing_texture.json",
       {"materials[0].albedo.path: file not found: textures/wood.png (resolved to /"}},
      {"missing_required.json", {"materials[0]: missing required key \"name\""}},
      {"zero_direction.json", {"lights[0].direction: expected a non-zero direction"}},
      {"zero_scale.json", {"objects[0].transform.scale: expected non-zero scale factors"}},
      {"spot_at_itself.json", {"lights[0].target: must differ from the spot light's position"}},
      {"camera_without_direction.json", {"camera.look_at: must differ from camera.look_from"}},
      {"camera_up_along_view.json", {"camera.up: must not be parallel to the view direction"}},
      {"many_problems.json", {"render.spp: expected an integer in [1, 1048576], got 0"}},
      {"mix_unknown_material.json", {"materials[1].a: no material named \"paint\" (defined: rust, worn)"}},
      {"mix_cycle.json",
       {"materials[1].a: mixes refer to each other in a cycle: \"worn\" -> \"rusty\" -> \"worn\""}},
      {"mix_self.json", {"materials[1].b: mix \"loop\" refers to itself"}},
      {"toon_missing_ramp.json",
       {"materials[0].ramp_image: file not found: ramps/sunset.png (resolved to /"}},
      {"strokes_unknown_object.json", {"strokes[0].object: no object named \"tree\" (defined: ground)"}},
      {"strokes_duplicate_names.json",
       {"strokes[2].name: duplicate stroke emitter name \"grass\" (also used by strokes[0])"}},
      {"strokes_missing_brush.json",
       {"strokes[0].brush_image: file not found: brushes/dab.png (resolved to /"}},
      {"strokes_brush_image_unset.json", {"strokes[0].brush_image: required when brush is \"image\""}},
      {"strokes_width_range.json", {"strokes[0].width_min: must not exceed width_max (0.5 > 0.2)"}},
      {"strokes_length_range.json", {"strokes[0].length_min: must not exceed length_max (1 > 0.5)"}},
  };
  return cases;
}

TEST(SceneJsonBroken, EveryFileReportsItsProblem) {
  std::set<std::string> covered;
  for (const BrokenCase& c : broken_cases()) {
    SCOPED_TRACE(c.file);
    covered.insert(c.file);
    const fs::path file = kBroken / c.file;
    ASSERT_TRUE(fs::exists(file));
    SceneLoadResult r;
    ASSERT_NO_THROW(r = load_scene(file));
    EXPECT_FALSE(r);
    EXPECT_FALSE(r.scene.has_value());
    ASSERT_FALSE(r.errors.empty());
    const bool found = std::any_of(r.errors.begin(), r.errors.end(), [&](const std::string& line) {
      if (!line.starts_with(file.string() + ": ")) return false;
      return std::all_of(c.expected.begin(), c.expected.end(),
                         [&](const std::string& part) { return line.find(part) != std::string::npos; });
    });
    EXPECT_TRUE(found) << "got:\n" << joined(r.errors);
  }
  // Every broken file on disk has an expectation here.
  for (const auto& entry : fs::directory_iterator(kBroken)) {
    EXPECT_TRUE(covered.contains(entry.path().filename().string())) << entry.path();
  }
  EXPECT_GE(covered.size(), 15u);
}

TEST(SceneJsonBroken, EveryProblemInAFileIsReported) {
  SceneLoadResult r = load_scene(kBroken / "many_problems.json");
  EXPECT_FALSE(r);
  const std::vector<std::string> expected = {
      "unknown key \"extra\"",
      "camera.vfov: expected a number",
      "camera.up: expected a non-zero direction",
      "render.spp: expected an integer",
      "materials[0]: missing required key \"name\"",
      "materials[0].albedo: expected a number or an array of 3 numbers, got [1, 1]",
      "objects[0].shape.type: unknown shape type \"cone\"",
      "objects[0].material: no material named \"nope\"",
      "lights[0].type: unknown light type \"laser\"",
  };
  EXPECT_EQ(r.errors.size(), expected.size()) << joined(r.errors);
  const std::string all = joined(r.errors);
  for (const std::string& part : expected) {
    EXPECT_NE(all.find(part), std::string::npos) << part << "\n" << all;
  }
}

TEST(SceneJsonBroken, UnreadableFilesGiveOneClearLine) {
  SceneLoadResult missing = load_scene(kBroken / "no_such_scene.json");
  ASSERT_EQ(missing.errors.size(), 1u);
  EXPECT_NE(missing.errors[0].find("no_such_scene.json: "), std::string::npos);
  EXPECT_NE(missing.errors[0].find("no such file"), std::string::npos);
  SceneLoadResult folder = load_scene(kBroken);
  ASSERT_EQ(folder.errors.size(), 1u);
  EXPECT_NE(folder.errors[0].find("not a regular file"), std::string::npos);
}

TEST(SceneJsonBroken, DeepNestingIsRejectedWithoutRecursion) {
  const std::string deep = std::string(1'000'000, '[') + std::string(1'000'000, ']');
  SceneLoadResult r = parse_scene(deep, {}, "deep.json");
  EXPECT_FALSE(r);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_NE(r.errors[0].find("nested more than 64 levels"), std::string::npos) << r.errors[0];
  const std::string in_value = R"({"format": "inkray-scene", "version": 1, "camera": {"up": )" +
                               std::string(100, '[') + std::string(100, ']') + "}}";
  r = parse_scene(in_value, {}, "deep_value.json");
  EXPECT_FALSE(r);
  EXPECT_NE(joined(r.errors).find("deep_value.json: camera.up"), std::string::npos) << joined(r.errors);
}

TEST(SceneJsonBroken, ErrorListIsBounded) {
  std::string text = R"({"format": "inkray-scene", "version": 1, "materials": [)";
  for (int i = 0; i < 5000; ++i) {
    text += std::string(i ? "," : "") + R"({"name": "m)" + std::to_string(i) + R"(", "type": "gold"})";
  }
  text += "]}";
  SceneLoadResult r = parse_scene(text, {}, "many.json");
  EXPECT_FALSE(r);
  ASSERT_EQ(r.errors.size(), 101u);
  EXPECT_EQ(r.errors.back(), "many.json: 4900 more problems not shown");
}

TEST(SceneJsonBroken, InvalidUtf8AndControlCharactersAreErrors) {
  SceneLoadResult r =
      parse_scene("{\"format\": \"inkray-scene\", \"version\": 1, \"camera\": {\"\xff\": 1}}", {}, "u.json");
  EXPECT_FALSE(r);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_NE(r.errors[0].find("u.json: line 1, column"), std::string::npos) << r.errors[0];
  const char with_nul[] = "{\"format\": \"inkray\0scene\", \"version\": 1}";
  r = parse_scene(std::string(with_nul, sizeof with_nul - 1), {}, "nul.json");
  EXPECT_FALSE(r);
}

// Random edits of a valid file: the reader must answer every one without throwing,
// and give a scene exactly when it reports no errors.
TEST(SceneJsonBroken, MutatedFilesNeverThrow) {
  const std::string original = read_file(kValid / "cornell.json");
  ASSERT_FALSE(original.empty());
  std::mt19937 rng(99);
  const testing::TextDamage damage{
      .alphabet = "{}[]\":,0123456789.-+eE aZ\\\n\x01\xff", .max_erase = 16, .max_copy = 32, .inserts = true};
  int accepted = 0;
  for (int iteration = 0; iteration < 3000; ++iteration) {
    const std::string text = testing::damaged(original, rng, damage);
    SceneLoadResult r;
    ASSERT_NO_THROW(r = parse_scene(text, kValid, "mutated.json"));
    ASSERT_EQ(r.scene.has_value(), r.errors.empty());
    accepted += r.scene.has_value();
  }
  EXPECT_LT(accepted, 3000);
}

}  // namespace
}  // namespace inkray
