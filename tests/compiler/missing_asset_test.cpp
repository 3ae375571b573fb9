// Scenes whose files are missing or broken: the editor's compile draws placeholders
// and names each file and who uses it; the command line's still refuses the scene;
// a file that appears, or a path relinked to it, is read by the next compile.
#include "core/compiler/compile.h"
#include "core/document/asset_relink.h"
#include "core/document/json_io.h"
#include "core/render/batch_render.h"

#include "tests/support/file_helpers.h"
#include "tests/support/scene_copies.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace inkray {
namespace {

namespace fs = std::filesystem;
const fs::path kScenes = INKRAY_SOURCE_DIR "/scenes";

// scenes/`name` copied alone into `folder`: every mesh, texture and brush it names is missing.
SceneDesc copied_without_files(const fs::path& folder, const std::string& name) {
  SceneDesc scene = testing::example_scene_alone(folder, name);
  scene.render.width = 64;
  scene.render.height = 48;
  return scene;
}

void copy_files_back(const fs::path& folder) {
  fs::copy(kScenes / "meshes", folder / "meshes", fs::copy_options::recursive);
  fs::copy(kScenes / "textures", folder / "textures", fs::copy_options::recursive);
}

CompileOptions with_stand_ins() {
  CompileOptions options;
  options.stand_in_for_missing_assets = true;
  return options;
}

bool any_line_has(const std::vector<std::string>& lines, const std::string& a, const std::string& b = {}) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) {
    return l.find(a) != std::string::npos && l.find(b) != std::string::npos;
  });
}

size_t object_index(const RenderScene& scene, const std::string& name) {
  for (size_t i = 0; i < scene.world->objects.size(); ++i)
    if (scene.world->objects[i].name == name) return i;
  ADD_FAILURE() << "no compiled object " << name;
  return 0;
}

const TriangleMesh& object_mesh(const RenderScene& scene, const std::string& name) {
  return std::get<TriangleMesh>(scene.world->geometry.shape(uint32_t(object_index(scene, name))));
}

void mesh_bounds(const TriangleMesh& mesh, Point3* lo, Point3* hi) {
  *lo = Point3(INFINITY);
  *hi = Point3(-INFINITY);
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    *lo = glm::min(*lo, mesh.positions[v]);
    *hi = glm::max(*hi, mesh.positions[v]);
  }
}

// The floor material's texture as compiled.
const ImageTexture& floor_texture(const RenderScene& scene) {
  const auto& m = std::get<DiffuseMaterial>(scene.world->materials[0]);
  return std::get<ImageTexture>(m.albedo);
}

RgbImage render(const std::shared_ptr<const RenderScene>& scene, int spp) {
  RenderSession session(2);
  session.set_scene(scene);
  render_batch(session, {spp, 0.0});
  return session.film().resolve();
}

TEST(MissingAssets, WithStandInsTheSceneCompilesAndNamesEachFile) {
  testing::ScratchFolder folder;
  const SceneDesc scene = copied_without_files(folder.path(), "mesh.json");
  const CompileResult c = compile_scene(scene, with_stand_ins());
  ASSERT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
  EXPECT_TRUE(c.errors.empty());
  EXPECT_TRUE(any_line_has(c.warnings, "textures/tiles.png", "material \"tiles\""));
  EXPECT_TRUE(any_line_has(c.warnings, "meshes/torus_knot.obj", "object \"knot\""));
  EXPECT_TRUE(any_line_has(c.warnings, "meshes/icosahedron.obj", "object \"gem\""));
  EXPECT_EQ(floor_texture(*c.scene).image, stand_in_image());

  // The knot's placeholder: a unit box under its transform (scale 0.55, a quarter
  // turn about x, which a cube does not show, at (-1.6, 1.35, 0)).
  Point3 lo, hi;
  mesh_bounds(object_mesh(*c.scene, "knot"), &lo, &hi);
  const Point3 centre(-1.6f, 1.35f, 0.f);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(lo[a], centre[a] - 0.275f, 1e-4f) << "axis " << a;
    EXPECT_NEAR(hi[a], centre[a] + 0.275f, 1e-4f) << "axis " << a;
  }
}

TEST(MissingAssets, WithoutStandInsTheCompileNamesTheMissingFiles) {
  testing::ScratchFolder folder;
  const CompileResult c = compile_scene(copied_without_files(folder.path(), "mesh.json"));
  EXPECT_FALSE(c.scene);
  EXPECT_TRUE(any_line_has(c.errors, "file not found", "textures/tiles.png"));
  EXPECT_TRUE(any_line_has(c.errors, "file not found", "meshes/torus_knot.obj"));
}

TEST(MissingAssets, TheMissingTextureRendersAsAMagentaChecker) {
  testing::ScratchFolder folder;
  const CompileResult c = compile_scene(copied_without_files(folder.path(), "mesh.json"), with_stand_ins());
  ASSERT_TRUE(c.scene);
  const RgbImage image = render(c.scene, 8);
  ASSERT_EQ(image.width, 64);
  for (const Color& p : image.pixels)
    ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b));
  // Pixels that see only the floor (a strip along the bottom, under the objects): a
  // magenta albedo reflects no green, red and blue alike (the bluish sky tints it a
  // little), and its squares alternate bright and dark.
  float brightest = 0.f, darkest = INFINITY;
  int floor_pixels = 0;
  for (int x = 0; x < image.width; ++x) {
    for (int y = image.height - 6; y < image.height; ++y) {
      const Color p = image.at(x, y);
      const Ray ray = c.scene->camera.generate_ray(Vec2(float(x) + 0.5f, float(y) + 0.5f), Vec2(0.5f));
      const float t = -ray.o.y / ray.d.y;  // the floor plane, y = 0
      const Point3 hit = ray.o + t * ray.d;
      if (!(t > 0.f) || std::abs(hit.x) > 5.5f || std::abs(hit.z) > 5.5f) continue;
      ++floor_pixels;
      EXPECT_LT(p.g, 0.05f * std::max(p.r, p.b) + 1e-4f) << "pixel " << x << ", " << y;
      EXPECT_NEAR(p.r, p.b, 0.5f * std::max(p.r, p.b) + 1e-4f) << "pixel " << x << ", " << y;
      brightest = std::max(brightest, p.r);
      darkest = std::min(darkest, p.r);
    }
  }
  ASSERT_GT(floor_pixels, 100);
  EXPECT_GT(brightest, 5.f * darkest) << "both squares of the checker are seen";
}

TEST(MissingAssets, FilesThatAppearAreReadByTheNextCompile) {
  testing::ScratchFolder folder;
  const SceneDesc scene = copied_without_files(folder.path(), "mesh.json");
  SceneCompiler compiler;
  const CompileResult first = compiler.compile(scene, with_stand_ins());
  ASSERT_TRUE(first.scene);
  EXPECT_EQ(object_mesh(*first.scene, "knot").indices.size(), 36u) << "a box of 12 triangles";

  copy_files_back(folder.path());
  const CompileResult second = compiler.compile(scene, with_stand_ins());
  ASSERT_TRUE(second.scene);
  EXPECT_TRUE(second.warnings.empty());
  EXPECT_GT(object_mesh(*second.scene, "knot").indices.size(), 36u);
  EXPECT_NE(floor_texture(*second.scene).image, stand_in_image());
}

TEST(MissingAssets, ARelinkedPathIsReadByTheNextCompile) {
  testing::ScratchFolder folder;
  SceneDesc scene = copied_without_files(folder.path(), "mesh.json");
  SceneCompiler compiler;
  ASSERT_TRUE(compiler.compile(scene, with_stand_ins()).scene);

  fs::create_directory(folder / "found");
  fs::copy(kScenes / "meshes", folder / "found");
  EXPECT_EQ(relink(scene, "meshes/torus_knot.obj", folder / "found" / "torus_knot.obj"), 2u)
      << "the icosahedron lived beside the knot and is found beside it";
  const CompileResult c = compiler.compile(scene, with_stand_ins());
  ASSERT_TRUE(c.scene);
  EXPECT_GT(object_mesh(*c.scene, "knot").indices.size(), 36u);
  EXPECT_GT(object_mesh(*c.scene, "gem").indices.size(), 36u);
  EXPECT_TRUE(any_line_has(c.warnings, "textures/tiles.png"))
      << "the list of files changed, so it is told again";
  EXPECT_FALSE(any_line_has(c.warnings, "torus_knot.obj"));
}

TEST(MissingAssets, ABrokenFileIsAPlaceholderWithTheReadersError) {
  testing::ScratchFolder folder;
  SceneDesc scene = copied_without_files(folder.path(), "mesh.json");
  copy_files_back(folder.path());
  testing::write_file(folder / "textures/tiles.png", "not a png");
  testing::write_file(folder / "meshes/torus_knot.obj", "v 0 0 0\nf 1 2 3\n");

  EXPECT_FALSE(compile_scene(scene).scene) << "without stand-ins a broken file is still an error";

  SceneCompiler compiler;
  std::vector<fs::path> opened;
  compiler.assets().on_file_read = [&](const fs::path& file) { opened.push_back(file); };
  const CompileResult c = compiler.compile(scene, with_stand_ins());
  ASSERT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
  EXPECT_TRUE(any_line_has(c.warnings, "tiles.png: cannot read image", "material \"tiles\""));
  EXPECT_TRUE(any_line_has(c.warnings, "torus_knot.obj", "object \"knot\""));
  EXPECT_EQ(floor_texture(*c.scene).image, stand_in_image());
  EXPECT_EQ(object_mesh(*c.scene, "knot").indices.size(), 36u);

  // A broken file is read once, not on every edit; once mended, it is read again.
  const auto reads_of = [&](const std::string& name) {
    return std::count_if(opened.begin(), opened.end(),
                         [&](const fs::path& f) { return f.filename() == name; });
  };
  scene.objects[1].transform.translate.y += 0.5f;
  std::get<DiffuseDesc>(scene.materials[0].data).albedo = ImageTextureDesc{"textures/tiles.png", Color(0.9f)};
  const CompileResult edited = compiler.compile(scene, with_stand_ins());
  ASSERT_TRUE(edited.scene);
  EXPECT_TRUE(edited.warnings.empty()) << "the same files are not reported again";
  EXPECT_EQ(reads_of("torus_knot.obj"), 1);
  EXPECT_EQ(reads_of("tiles.png"), 1) << "its header, found broken: its pixels are not tried";

  fs::copy_file(kScenes / "meshes/torus_knot.obj", folder / "meshes/torus_knot.obj",
                fs::copy_options::overwrite_existing);
  const CompileResult mended = compiler.compile(scene, with_stand_ins());
  ASSERT_TRUE(mended.scene);
  EXPECT_GT(object_mesh(*mended.scene, "knot").indices.size(), 36u);
}

TEST(MissingAssets, AMissingBrushPaintsTheStrokesInTheChecker) {
  testing::ScratchFolder folder;
  SceneDesc scene = copied_without_files(folder.path(), "strokes_mesh.json");
  scene.strokes[0].count = 200;
  const CompileResult c = compile_scene(scene, with_stand_ins());
  ASSERT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
  EXPECT_TRUE(any_line_has(c.warnings, "palette_knife.png", "stroke emitter \"knot_strokes\""));
  const RenderObject& strokes = c.scene->world->objects[object_index(*c.scene, "knot_strokes")];
  const auto* unlit = std::get_if<UnlitMaterial>(&c.scene->world->materials[strokes.material]);
  ASSERT_TRUE(unlit);
  const auto* checker = std::get_if<CheckerTexture>(&unlit->color);
  ASSERT_TRUE(checker);
  EXPECT_EQ(checker->even, kStandInEven);
  EXPECT_FALSE(compile_scene(scene).scene) << "the command line's compile refuses it";
}

TEST(MissingAssets, ARelinkedBrushPaintsTheStrokesAgain) {
  testing::ScratchFolder folder;
  SceneDesc scene = copied_without_files(folder.path(), "strokes_mesh.json");
  scene.strokes[0].count = 200;
  SceneCompiler compiler;
  ASSERT_TRUE(compiler.compile(scene, with_stand_ins()).scene);

  fs::copy_file(kScenes / "../resources/brushes/palette_knife.png", folder / "palette_knife.png");
  EXPECT_EQ(relink(scene, scene.strokes[0].brush_image, folder / "palette_knife.png"), 1u);
  EXPECT_EQ(scene.strokes[0].brush_image, "palette_knife.png");
  const CompileResult c = compiler.compile(scene, with_stand_ins());
  ASSERT_TRUE(c.scene);
  const RenderObject& strokes = c.scene->world->objects[object_index(*c.scene, "knot_strokes")];
  EXPECT_TRUE(std::holds_alternative<DiffuseMaterial>(c.scene->world->materials[strokes.material]));
}

}  // namespace
}  // namespace inkray
