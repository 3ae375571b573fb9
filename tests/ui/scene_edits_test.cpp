// Structural edits keep names unique and references consistent.
#include "ui/model/document.h"
#include "ui/model/scene_edits.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

TEST(SceneEdits, UniqueNames) {
  SceneDesc s = Document::default_scene();
  EXPECT_EQ(unique_name(s, ItemKind::object, "sphere"), "sphere.1");
  EXPECT_EQ(unique_name(s, ItemKind::object, "cube"), "cube");
  const Selection copy = duplicate_item(s, {ItemKind::object, 1});
  EXPECT_EQ(s.objects[size_t(copy.index)].name, "sphere.1");
  const Selection copy2 = duplicate_item(s, copy);
  EXPECT_EQ(s.objects[size_t(copy2.index)].name, "sphere.2");
}

TEST(SceneEdits, AddShapesGetAMaterial) {
  SceneDesc s;
  const Selection box = add_shape(s, NewShape::box);
  ASSERT_EQ(box.kind, ItemKind::object);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.objects[0].material, s.materials[0].name);
  add_shape(s, NewShape::sphere);
  EXPECT_EQ(s.materials.size(), 1u);  // shared
}

TEST(SceneEdits, RenameFollowsReferences) {
  SceneDesc s = Document::default_scene();
  add_stroke_emitter(s, "sphere");
  ASSERT_TRUE(rename_item(s, {ItemKind::object, 1}, "ball"));
  EXPECT_EQ(s.strokes[0].object, "ball");
  ASSERT_TRUE(rename_item(s, {ItemKind::material, 1}, "crimson"));
  EXPECT_EQ(s.objects[1].material, "crimson");
  EXPECT_FALSE(rename_item(s, {ItemKind::object, 1}, "ground"));  // taken
  EXPECT_FALSE(rename_item(s, {ItemKind::object, 1}, ""));
}

TEST(SceneEdits, DeleteObjectDeletesItsEmitters) {
  SceneDesc s = Document::default_scene();
  add_stroke_emitter(s, "sphere");
  add_stroke_emitter(s, "ground");
  ASSERT_TRUE(delete_item(s, {ItemKind::object, 1}));
  ASSERT_EQ(s.strokes.size(), 1u);
  EXPECT_EQ(s.strokes[0].object, "ground");
  EXPECT_FALSE(delete_item(s, {ItemKind::material, 0}));  // the ground still uses it
}

TEST(SceneEdits, HideAndBounds) {
  SceneDesc s = Document::default_scene();
  ASSERT_TRUE(set_visible(s, {ItemKind::object, 1}, false));
  EXPECT_FALSE(s.objects[1].visible);
  Point3 c;
  float r;
  object_bounds(s.objects[1], &c, &r);
  EXPECT_NEAR(c.y, 1.f, 1e-5f);
  EXPECT_GE(r, 1.f);
}

TEST(Selection, ValidatedDropsDeletedItems) {
  SceneDesc s = Document::default_scene();
  const Selection sel{ItemKind::object, 1};
  EXPECT_EQ(validated(s, sel), sel);
  delete_item(s, sel);
  EXPECT_EQ(validated(s, sel).kind, ItemKind::none);
  EXPECT_EQ(item_name(s, {ItemKind::camera, -1}), "Camera");
}

}  // namespace
}  // namespace inkray
