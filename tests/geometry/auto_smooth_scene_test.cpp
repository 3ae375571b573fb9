// Auto smooth and crease patches through the document and the compiler: the
// smooth_angle parameter in JSON, its stage and cache, the patches a compiled scene
// carries for crease lines and how they follow the crease threshold, and a rendered
// blob whose normals turn smooth.
#include "core/compiler/compile.h"
#include "core/document/json_io.h"
#include "core/geometry/mesh_features.h"
#include "support/messages.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>

namespace inkray {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = INKRAY_SOURCE_DIR;
const fs::path kTestMeshes = kSource / "tests/data/meshes";

using testing::joined;

ObjectDesc mesh_object(const std::string& name, const std::string& path, float smooth_angle = 30.f) {
  ObjectDesc o;
  o.name = name;
  o.material = "m";
  o.shape = MeshDesc{path, smooth_angle};
  return o;
}

SceneDesc mesh_scene(const std::string& path, float smooth_angle = 30.f) {
  SceneDesc d = testing::small_scene(32, 24);
  d.base_dir = kTestMeshes;
  d.materials = {{"m", DiffuseDesc{}, {}}};
  d.objects = {mesh_object("mesh", path, smooth_angle)};
  d.lights = {{"sun", DirectionalLightDesc{}}};
  return d;
}

const TriangleMesh& mesh_of(const RenderScene& scene, size_t object) {
  return std::get<TriangleMesh>(scene.world->geometry.shape(uint32_t(object)));
}

size_t distinct(const std::vector<uint32_t>& ids) {
  return std::set<uint32_t>(ids.begin(), ids.end()).size();
}

// ---------------------------------------------------------------- the document

TEST(SmoothAngleJson, RoundTrips) {
  SceneDesc d = mesh_scene("bevel_cube.obj", 42.5f);
  d.objects.push_back(mesh_object("flat", "bevel_cube.obj", 0.f));
  d.objects.push_back(mesh_object("default", "bevel_cube.obj"));
  const std::string text = scene_to_string(d);
  EXPECT_NE(text.find("\"smooth_angle\": 42.5"), std::string::npos) << text;
  const SceneLoadResult back = parse_scene(text, kTestMeshes, "round trip");
  ASSERT_TRUE(back) << joined(back.errors);
  EXPECT_EQ(back.scene->objects, d.objects);
  EXPECT_EQ(scene_to_string(*back.scene), text);
}

std::string scene_with_mesh_shape(const std::string& shape) {
  return R"({"format": "inkray-scene", "version": 1,
             "materials": [{"name": "m", "type": "diffuse"}],
             "objects": [{"name": "o", "material": "m", "shape": )" +
         shape + "}]}";
}

TEST(SmoothAngleJson, DefaultsTo30) {
  const SceneLoadResult r = parse_scene(
      scene_with_mesh_shape(R"({"type": "mesh", "path": "bevel_cube.obj"})"), kTestMeshes, "s.json");
  ASSERT_TRUE(r) << joined(r.errors);
  EXPECT_EQ(std::get<MeshDesc>(r.scene->objects[0].shape).smooth_angle, 30.f);
}

TEST(SmoothAngleJson, BadValuesNameTheKey) {
  for (const std::string value : {"\"soft\"", "true", "[30]", "-1", "200", "null"}) {
    const SceneLoadResult r = parse_scene(
        scene_with_mesh_shape(R"({"type": "mesh", "path": "bevel_cube.obj", "smooth_angle": )" + value + "}"),
        kTestMeshes, "s.json");
    EXPECT_FALSE(r) << value;
    EXPECT_NE(joined(r.errors).find("objects[0].shape.smooth_angle"), std::string::npos)
        << value << ": " << joined(r.errors);
  }
}

TEST(SmoothAngleStage, IsTheObjectsGeometry) {
  const SceneDesc a = mesh_scene("bevel_cube.obj");
  SceneDesc b = a;
  std::get<MeshDesc>(b.objects[0].shape).smooth_angle = 60.f;
  StageSet expected;
  expected.add(Stage::geometry);
  EXPECT_EQ(changed_stages(a, b).names(), expected.names());
}

// ---------------------------------------------------------------- the compiler

TEST(AutoSmoothCompile, SmoothAngleEditsReadNoFile) {
  SceneDesc d = mesh_scene("bevel_cube.obj", 30.f);
  SceneCompiler compiler;
  int reads = 0;
  compiler.assets().on_file_read = [&](const fs::path&) { ++reads; };
  CompileResult c = compiler.compile(d);
  ASSERT_TRUE(c.scene) << joined(c.errors);
  EXPECT_EQ(reads, 1);
  EXPECT_EQ(mesh_of(*c.scene, 0).normals.size(), mesh_of(*c.scene, 0).vertex_count());
  EXPECT_EQ(mesh_of(*c.scene, 0).vertex_count(), 96u) << "nothing smooth at 30 degrees: split at every edge";

  // Another angle smooths again, from the mesh as read; back to flat keeps no normals.
  for (const float angle : {60.f, 0.f, 30.f}) {
    SCOPED_TRACE(angle);
    std::get<MeshDesc>(d.objects[0].shape).smooth_angle = angle;
    const uint64_t bvhs = compiler.counters().shape_bvhs;
    c = compiler.compile(d);
    ASSERT_TRUE(c.scene) << joined(c.errors);
    EXPECT_EQ(reads, 1) << "a new smooth angle read the file again";
    EXPECT_EQ(compiler.counters().shape_bvhs, bvhs + 1);
    const TriangleMesh& mesh = mesh_of(*c.scene, 0);
    EXPECT_EQ(mesh.normals.empty(), angle == 0.f);
    if (angle == 60.f) {
      EXPECT_EQ(mesh.vertex_count(), 24u);
    }
    const CompileResult fresh = compile_scene(d);
    ASSERT_TRUE(fresh.scene);
    EXPECT_EQ(mesh.normals, mesh_of(*fresh.scene, 0).normals);
  }

  // Other edits reuse the smoothed mesh's BVH.
  const uint64_t bvhs = compiler.counters().shape_bvhs;
  d.objects[0].transform.translate.x = 1.f;
  d.materials[0].data = DiffuseDesc{Color(0.2f)};
  ASSERT_TRUE(compiler.compile(d).scene);
  EXPECT_EQ(compiler.counters().shape_bvhs, bvhs);
  EXPECT_EQ(reads, 1);
}

TEST(AutoSmoothCompile, NormalsInTheFileAreKept) {
  const CompileResult c = compile_scene(mesh_scene("cube.obj", 180.f));
  ASSERT_TRUE(c.scene) << joined(c.errors);
  std::string error;
  const auto file = load_obj(kTestMeshes / "cube.obj", &error);
  ASSERT_TRUE(file) << error;
  const TriangleMesh& mesh = mesh_of(*c.scene, 0);
  EXPECT_EQ(mesh.normals, file->normals);
  EXPECT_EQ(mesh.indices, file->indices);
}

// ---------------------------------------------------------------- crease patches

SceneDesc crease_scene(float threshold) {
  SceneDesc d = mesh_scene("bevel_cube.obj");
  d.camera.look_from = Point3(0.f, 2.f, 6.f);
  d.objects.push_back(mesh_object("twin", "bevel_cube.obj"));
  d.objects.back().transform.translate = Vec3(2.f, 0.f, 0.f);
  ObjectDesc ball;
  ball.name = "ball";
  ball.material = "m";
  ball.transform.translate = Vec3(-2.f, 0.f, 0.f);
  ball.shape = SphereDesc{Point3(0.f), 0.5f};
  d.objects.push_back(ball);
  ObjectDesc box;
  box.name = "box";
  box.material = "m";
  box.shape = BoxDesc{Point3(-0.5f, -2.f, -0.5f), Point3(0.5f, -1.f, 0.5f)};
  d.objects.push_back(box);
  d.outlines.enabled = true;
  d.outlines.crease.enabled = true;
  d.outlines.crease.threshold = threshold;
  return d;
}

// Patch ids of the triangle a ray from `from` towards `to` hits first.
uint32_t patch_seen(const RenderScene& scene, const Point3& from, const Point3& to, uint32_t* object) {
  Hit hit;
  EXPECT_TRUE(scene.world->geometry.intersect(Ray{from, glm::normalize(to - from)}, 100.f, &hit));
  *object = hit.geometry;
  return crease_patch(scene, hit.geometry, hit.prim);
}

TEST(CreasePatches, CompiledPerObject) {
  const CompileResult c = compile_scene(crease_scene(30.f));
  ASSERT_TRUE(c.scene) << joined(c.errors);
  const RenderScene& s = *c.scene;
  ASSERT_EQ(s.world->objects.size(), 4u);
  ASSERT_TRUE(s.world->objects[0].crease_patches);
  EXPECT_EQ(distinct(*s.world->objects[0].crease_patches), 26u);
  EXPECT_EQ(s.world->objects[0].crease_patches->size(), mesh_of(s, 0).triangle_count());
  EXPECT_EQ(s.world->objects[0].crease_patches, s.world->objects[1].crease_patches)
      << "one mesh, one threshold: shared";
  EXPECT_FALSE(s.world->objects[2].crease_patches) << "a sphere has no patches";
  EXPECT_EQ(crease_patch(s, 2, 0), kNoPatch);
  ASSERT_TRUE(s.world->objects[3].crease_patches);
  EXPECT_EQ(distinct(*s.world->objects[3].crease_patches), 6u) << "a box's faces";

  // What the line detector asks: hits on a face and on the chamfer beside it.
  uint32_t object_a = 0, object_b = 0;
  const uint32_t face = patch_seen(s, Point3(0.f, 0.f, 5.f), Point3(0.f, 0.f, 0.5f), &object_a);
  const uint32_t face_again = patch_seen(s, Point3(0.2f, -0.1f, 5.f), Point3(0.2f, -0.1f, 0.5f), &object_b);
  EXPECT_EQ(object_a, 0u);
  EXPECT_EQ(face, face_again);
  const uint32_t chamfer = patch_seen(s, Point3(0.f, 3.45f, 3.45f), Point3(0.f, 0.45f, 0.45f), &object_b);
  EXPECT_EQ(object_b, 0u);
  EXPECT_NE(face, chamfer);
  EXPECT_NE(face, kNoPatch);
}

TEST(CreasePatches, FollowTheThresholdWithoutRebuildingTheWorld) {
  SceneDesc d = crease_scene(30.f);
  SceneCompiler compiler;
  int reads = 0;
  compiler.assets().on_file_read = [&](const fs::path&) { ++reads; };
  ASSERT_TRUE(compiler.compile(d).scene);
  const CompileCounters before = compiler.counters();

  const auto check = [&](const SceneDesc& doc, size_t cube_patches) {
    const CompileResult c = compiler.compile(doc);
    ASSERT_TRUE(c.scene) << joined(c.errors);
    StageSet sampling;
    sampling.add(Stage::sampling);
    EXPECT_EQ(c.changes.names(), sampling.names());
    EXPECT_EQ(compiler.counters().shape_bvhs, before.shape_bvhs);
    EXPECT_EQ(compiler.counters().top_levels, before.top_levels);
    EXPECT_EQ(reads, 1);
    const CompileResult fresh = compile_scene(doc);
    ASSERT_TRUE(fresh.scene);
    for (size_t i = 0; i < c.scene->world->objects.size(); ++i) {
      const auto& a = c.scene->world->objects[i].crease_patches;
      const auto& b = fresh.scene->world->objects[i].crease_patches;
      ASSERT_EQ(bool(a), bool(b)) << i;
      if (a) {
        EXPECT_EQ(*a, *b) << "object " << i << ": an edit gives other patches than a compile from scratch";
      }
    }
    if (cube_patches == 0) {
      EXPECT_FALSE(c.scene->world->objects[0].crease_patches);
    } else {
      ASSERT_TRUE(c.scene->world->objects[0].crease_patches);
      EXPECT_EQ(distinct(*c.scene->world->objects[0].crease_patches), cube_patches);
    }
  };
  d.outlines.crease.threshold = 60.f;
  check(d, 1u);
  d.outlines.crease.threshold = 40.f;
  check(d, 7u);
  d.outlines.crease.enabled = false;
  check(d, 0u);
  d.outlines.crease.enabled = true;
  d.outlines.enabled = false;
  check(d, 0u);
  d.outlines.enabled = true;
  check(d, 7u);
}

TEST(CreasePatches, NonUniformScaleMeasuresAnglesInTheWorld) {
  SceneDesc d = crease_scene(40.f);
  d.objects[0].transform.scale = Vec3(1.f, 3.f, 1.f);
  const CompileResult c = compile_scene(d);
  ASSERT_TRUE(c.scene) << joined(c.errors);
  const TriangleMesh& world = mesh_of(*c.scene, 0);
  const std::vector<uint32_t> expected = smooth_patches(
      find_feature_edges(std::span(world.positions.data(), world.vertex_count()), world.indices), 40.f);
  ASSERT_TRUE(c.scene->world->objects[0].crease_patches);
  EXPECT_EQ(*c.scene->world->objects[0].crease_patches, expected);
  EXPECT_NE(distinct(expected), 7u) << "stretched, some chamfers lie within 40 degrees of a face";
  EXPECT_EQ(distinct(*c.scene->world->objects[1].crease_patches), 7u) << "the unscaled twin";
}

TEST(CreasePatches, StrokesHaveNone) {
  SceneDesc d = crease_scene(30.f);
  d.strokes.push_back(StrokeEmitterDesc{.name = "paint", .object = "mesh", .count = 40});
  const CompileResult c = compile_scene(d);
  ASSERT_TRUE(c.scene) << joined(c.errors);
  ASSERT_EQ(c.scene->world->objects.size(), 5u);
  EXPECT_TRUE(c.scene->world->objects[0].crease_patches);
  EXPECT_FALSE(c.scene->world->objects[4].crease_patches) << "the strokes copied their base object's patches";
  EXPECT_EQ(crease_patch(*c.scene, 4, 0), kNoPatch);
}

// ---------------------------------------------------------------- the picture

// How far the first-hit normal is from varying continuously: the mean length of its
// second difference across three neighbouring pixels (in a row or a column) that all
// see the blob. Curvature alone leaves it near zero; a facet edge adds a kink.
double normal_kinks(float smooth_angle) {
  SceneDesc d = testing::small_scene(160, 120);
  d.base_dir = kSource / "scenes/meshes";
  d.camera.look_from = Point3(0.f, 0.5f, 4.f);
  d.materials = {{"m", DiffuseDesc{}, {}}};
  d.objects = {mesh_object("blob", "faceted_blob.obj", smooth_angle)};
  d.lights = {{"sun", DirectionalLightDesc{}}};
  const CompileResult c = compile_scene(d);
  EXPECT_TRUE(c.scene) << joined(c.errors);
  if (!c.scene) return 0.0;
  RenderSession session(2);
  AovSet aovs;
  aovs.add(Aov::normal);
  session.set_scene(c.scene, aovs);
  render_batch(session, {4, 0.0});
  const RgbImage n = session.film().resolve_aov(Aov::normal);
  double sum = 0.0;
  int triples = 0;
  const auto hit = [&](int x, int y) { return glm::length(n.at(x, y)) > 0.5f; };
  for (int y = 1; y + 1 < n.height; ++y) {
    for (int x = 1; x + 1 < n.width; ++x) {
      for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (!hit(x - dx, y - dy) || !hit(x, y) || !hit(x + dx, y + dy)) continue;
        sum += glm::length(n.at(x - dx, y - dy) - 2.f * n.at(x, y) + n.at(x + dx, y + dy));
        ++triples;
      }
    }
  }
  EXPECT_GT(triples, 5000);
  return sum / std::max(triples, 1);
}

TEST(AutoSmoothRender, FacetedBlobTurnsSmooth) {
  const double flat = normal_kinks(0.f), smooth = normal_kinks(30.f);
  std::printf("[ measured ] mean second difference of first-hit normals: flat %.4f, smooth %.4f\n", flat,
              smooth);
  EXPECT_LT(smooth, 0.5 * flat);
}

}  // namespace
}  // namespace inkray
