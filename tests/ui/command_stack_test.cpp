// Undo/redo over the document: apply, undo, redo, merging drags, dirty state.
#include "ui/model/command_stack.h"
#include "ui/model/document.h"
#include "ui/model/scene_edits.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

SceneDesc with_fov(SceneDesc s, float fov) {
  s.camera.vfov = fov;
  return s;
}

TEST(CommandStack, ApplyUndoRedo) {
  SceneDesc scene;
  CommandStack stack;
  stack.apply(scene, with_fov(scene, 30.f), "fov 30");
  stack.apply(scene, with_fov(scene, 50.f), "fov 50");
  EXPECT_EQ(scene.camera.vfov, 50.f);
  ASSERT_TRUE(stack.undo(scene));
  EXPECT_EQ(scene.camera.vfov, 30.f);
  EXPECT_EQ(stack.redo_label(), "fov 50");
  ASSERT_TRUE(stack.undo(scene));
  EXPECT_EQ(scene.camera.vfov, 40.f);
  EXPECT_FALSE(stack.undo(scene));
  ASSERT_TRUE(stack.redo(scene));
  ASSERT_TRUE(stack.redo(scene));
  EXPECT_EQ(scene.camera.vfov, 50.f);
  EXPECT_FALSE(stack.redo(scene));
}

TEST(CommandStack, NewEditDropsRedo) {
  SceneDesc scene;
  CommandStack stack;
  stack.apply(scene, with_fov(scene, 30.f), "a");
  stack.undo(scene);
  stack.apply(scene, with_fov(scene, 60.f), "b");
  EXPECT_FALSE(stack.can_redo());
  EXPECT_EQ(scene.camera.vfov, 60.f);
}

TEST(CommandStack, DragMergesIntoOneStep) {
  SceneDesc scene;
  CommandStack stack;
  for (float fov = 41.f; fov <= 60.f; fov += 1.f)
    stack.apply(scene, with_fov(scene, fov), "fov", "camera:vfov");
  EXPECT_EQ(stack.size(), 1u);
  EXPECT_EQ(scene.camera.vfov, 60.f);
  stack.end_merge();  // the drag ended: the next drag is a new step
  stack.apply(scene, with_fov(scene, 70.f), "fov", "camera:vfov");
  EXPECT_EQ(stack.size(), 2u);
  stack.undo(scene);
  EXPECT_EQ(scene.camera.vfov, 60.f);
  stack.undo(scene);
  EXPECT_EQ(scene.camera.vfov, 40.f);
}

TEST(CommandStack, DifferentKeysDoNotMerge) {
  SceneDesc scene;
  CommandStack stack;
  stack.apply(scene, with_fov(scene, 45.f), "fov", "camera:vfov");
  SceneDesc s = scene;
  s.camera.aperture = 0.1f;
  stack.apply(scene, s, "aperture", "camera:aperture");
  EXPECT_EQ(stack.size(), 2u);
}

TEST(Document, DirtyFollowsUndoAndSave) {
  Document doc;
  EXPECT_FALSE(doc.dirty());
  doc.edit(with_fov(doc.scene(), 30.f), "fov");
  EXPECT_TRUE(doc.dirty());
  doc.undo();
  EXPECT_FALSE(doc.dirty());  // back to the saved state
  doc.redo();
  EXPECT_TRUE(doc.dirty());
  EXPECT_NE(doc.display_name().find('*'), std::string::npos);
}

TEST(Document, MergedEditAfterSaveIsDirty) {
  Document doc;
  const auto file = std::filesystem::temp_directory_path() / "inkray_merge_dirty_test.json";
  doc.edit(with_fov(doc.scene(), 30.f), "fov", "k");
  std::string error;
  ASSERT_TRUE(doc.save_as(file, &error)) << error;
  EXPECT_FALSE(doc.dirty());
  doc.edit(with_fov(doc.scene(), 31.f), "fov", "k");  // merges into the saved step, yet changes the document
  EXPECT_TRUE(doc.dirty());
  std::filesystem::remove(file);
}

TEST(Document, UndoOfADeleteSelectsTheItemAgain) {
  Document doc;
  SceneDesc scene = doc.scene();
  ASSERT_FALSE(scene.objects.empty());
  const Selection deleted{ItemKind::object, int(scene.objects.size()) - 1};
  ASSERT_TRUE(delete_item(scene, deleted));
  Selection selection = deleted;
  doc.edit(std::move(scene), "Delete", {}, selection);
  selection = {};  // as the editor does after a delete
  ASSERT_TRUE(doc.undo(&selection));
  EXPECT_EQ(selection, deleted);
  EXPECT_TRUE(is_valid(doc.scene(), selection));
  ASSERT_TRUE(doc.redo(&selection));
  EXPECT_EQ(selection, Selection{});  // what was selected when the delete was undone
}

TEST(CommandStack, MergedStepsKeepTheFirstSelection) {
  CommandStack stack;
  SceneDesc scene;
  const Selection first{ItemKind::camera, -1}, later{ItemKind::render, -1};
  stack.apply(scene, with_fov(scene, 30.f), "fov", "k", first);
  stack.apply(scene, with_fov(scene, 31.f), "fov", "k", later);
  Selection selection = later;
  ASSERT_TRUE(stack.undo(scene, &selection));
  EXPECT_EQ(selection, first);
}

TEST(CommandStack, DiscardedStepLeavesNoRedo) {
  CommandStack stack;
  SceneDesc scene;
  const SceneDesc original = scene;
  stack.apply(scene, with_fov(scene, 30.f), "drag", "gizmo");
  ASSERT_TRUE(stack.discard_newest(scene));
  EXPECT_EQ(scene, original);
  EXPECT_FALSE(stack.can_undo());
  EXPECT_FALSE(stack.can_redo());  // an Esc leaves nothing to redo
  EXPECT_FALSE(stack.discard_newest(scene));
}

}  // namespace
}  // namespace inkray
