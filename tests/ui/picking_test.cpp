// Picking: a ray through the compiled scene finds the object under a pixel.
#include "core/compiler/compile.h"
#include "ui/viewport/picking.h"
#include "ui/model/scene_edits.h"

#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

SceneDesc two_spheres() {
  SceneDesc s = testing::sized_scene(200, 100);
  s.camera = {{.look_from = Point3(0.f, 0.f, 10.f), .look_at = Point3(0.f)}};
  s.materials.push_back({"m", DiffuseDesc{}, {}});
  s.objects = {testing::make_object("left", SphereDesc{Point3(-2.f, 0.f, 0.f), 1.f}, "m"),
               testing::make_object("right", SphereDesc{Point3(2.f, 0.f, 0.f), 1.f}, "m")};
  return s;
}

TEST(Picking, FindsTheObjectUnderThePixel) {
  const SceneDesc desc = two_spheres();
  const CompileResult compiled = compile_scene(desc);
  ASSERT_TRUE(compiled.scene) << compiled.errors.front();
  const RenderScene& scene = *compiled.scene;
  Vec2 left_px, right_px;
  ASSERT_TRUE(scene.camera.project(Point3(-2.f, 0.f, 0.f), &left_px));
  ASSERT_TRUE(scene.camera.project(Point3(2.f, 0.f, 0.f), &right_px));
  const PickResult a = pick(scene, left_px);
  EXPECT_EQ(a.object, 0);
  EXPECT_NEAR(a.depth, 9.f, 0.05f);  // the sphere's front, one radius before its centre
  EXPECT_EQ(pick(scene, right_px).object, 1);
  EXPECT_EQ(pick(scene, Vec2(100.f, 5.f)).object, -1);  // background above the spheres
}

TEST(Picking, HiddenObjectsAreNotPicked) {
  SceneDesc desc = two_spheres();
  desc.objects[0].visible = false;
  const CompileResult compiled = compile_scene(desc);
  ASSERT_TRUE(compiled.scene);
  Vec2 right_px;
  ASSERT_TRUE(compiled.scene->camera.project(Point3(2.f, 0.f, 0.f), &right_px));
  EXPECT_EQ(pick(*compiled.scene, right_px).object, 1);  // document index, not compiled index
}

}  // namespace
}  // namespace inkray
