// The editor's animation logic without a window: the one path builder the widgets,
// the timeline and the keys share, tracks following renames, duplicates and deletes,
// the current frame kept out of undo, auto-keying through Document::edit, and the
// playback clock.
#include "core/document/animation.h"
#include "core/document/graph_edit.h"
#include "ui/model/document.h"
#include "ui/model/scene_edits.h"
#include "ui/panels/timeline_panel.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

using namespace std::chrono_literals;

// The default document (ground, sphere, sun) with the sphere's position keyed at 1 and 11.
Document animated_document() {
  Document doc;
  SceneDesc s = doc.scene();
  s.render.frame_end = 24;
  s.strokes.push_back({});
  s.strokes.back().name = "fur";
  s.strokes.back().object = "sphere";
  EXPECT_TRUE(insert_key(s, "objects/sphere/transform/translate", 1));
  s.objects[1].transform.translate = Vec3(0.f, 2.f, 0.f);
  EXPECT_TRUE(insert_key(s, "objects/sphere/transform/translate", 11));
  EXPECT_TRUE(insert_key(s, "strokes/fur/hue_jitter", 1));
  EXPECT_TRUE(insert_key(s, "lights/sun/intensity", 1));
  doc.reset(std::move(s));
  return doc;
}

TEST(KeyPath, NamesParametersAsAnimationPathsDo) {
  const SceneDesc s = animated_document().scene();
  const Selection sphere{ItemKind::object, 1};
  EXPECT_EQ(key_path(s, sphere), "objects/sphere/");
  EXPECT_EQ(key_path(s, sphere, "transform.translate"), "objects/sphere/transform/translate");
  EXPECT_EQ(key_path(s, sphere, "transform/rotate/0/degrees"), "objects/sphere/transform/rotate/0/degrees");
  EXPECT_EQ(key_path(s, {ItemKind::light, 0}, "intensity"), "lights/sun/intensity");
  EXPECT_EQ(key_path(s, {ItemKind::material, 1}, "albedo"), "materials/red/albedo");
  EXPECT_EQ(key_path(s, {ItemKind::emitter, 0}, "hue_jitter"), "strokes/fur/hue_jitter");
  EXPECT_EQ(key_path(s, {ItemKind::outlines, -1}, "silhouette.color"), "outlines/silhouette/color");
  EXPECT_EQ(key_path(s, {ItemKind::camera, -1}, "look_from"), "camera/look_from");
  EXPECT_EQ(key_path(s, {ItemKind::render, -1}, "painterly_radius"), "render/painterly_radius");
  EXPECT_EQ(key_path(s, {ItemKind::environment, -1}, "color"), "environment/color");
  EXPECT_EQ(key_path(s, {}), "");
  EXPECT_EQ(key_path(s, {ItemKind::object, 7}), "");
  // Every path it builds for these resolves.
  for (const std::string& path :
       {key_path(s, sphere, "transform.translate"), key_path(s, {ItemKind::light, 0}, "intensity"),
        key_path(s, {ItemKind::material, 1}, "albedo"),
        key_path(s, {ItemKind::outlines, -1}, "silhouette.color"),
        key_path(s, {ItemKind::camera, -1}, "look_from")}) {
    std::string error;
    EXPECT_TRUE(animation_target(s, path, &error)) << path << ": " << error;
  }
}

TEST(TracksFollow, RenameDuplicateAndDeleteTakeTracksAlong) {
  SceneDesc s = animated_document().scene();
  ASSERT_TRUE(rename_item(s, {ItemKind::object, 1}, "ball"));
  EXPECT_NE(find_track(s, "objects/ball/transform/translate"), nullptr);
  EXPECT_EQ(find_track(s, "objects/sphere/transform/translate"), nullptr);
  ASSERT_TRUE(rename_item(s, {ItemKind::light, 0}, "key"));
  EXPECT_NE(find_track(s, "lights/key/intensity"), nullptr);
  ASSERT_TRUE(rename_item(s, {ItemKind::emitter, 0}, "hair"));
  EXPECT_NE(find_track(s, "strokes/hair/hue_jitter"), nullptr);
  EXPECT_TRUE(check_animation(s).empty());

  const Selection copy = duplicate_item(s, {ItemKind::object, 1});
  EXPECT_EQ(s.objects[size_t(copy.index)].name, "ball.1");
  EXPECT_EQ(find_track(s, "objects/ball.1/transform/translate")->keys,
            find_track(s, "objects/ball/transform/translate")->keys);

  // Deleting the ball deletes its strokes, and both their tracks; its copy keeps its own.
  ASSERT_TRUE(delete_item(s, {ItemKind::object, 1}));
  EXPECT_EQ(find_track(s, "objects/ball/transform/translate"), nullptr);
  EXPECT_EQ(find_track(s, "strokes/hair/hue_jitter"), nullptr);
  EXPECT_NE(find_track(s, "objects/ball.1/transform/translate"), nullptr);
  ASSERT_TRUE(delete_item(s, {ItemKind::light, 0}));
  EXPECT_EQ(find_track(s, "lights/key/intensity"), nullptr);
  EXPECT_TRUE(check_animation(s).empty());
}

TEST(CurrentFrame, MovesWithoutUndoStepsAndStaysThroughUndo) {
  Document doc = animated_document();
  doc.set_frame(5);
  EXPECT_EQ(doc.scene().render.frame, 5.f);
  EXPECT_FALSE(doc.history().can_undo());
  EXPECT_FALSE(doc.dirty());

  SceneDesc s = doc.scene();
  s.render.frame_end = 48;
  doc.edit(std::move(s), "Edit frame range");
  doc.set_frame(30);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().render.frame_end, 24);
  EXPECT_EQ(doc.scene().render.frame, 30.f);  // the range came back, the frame stayed
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(doc.scene().render.frame, 30.f);

  // An edit of the frame alone (a "Current frame" field) is a frame change, not a step.
  const size_t steps = doc.history().size();
  s = doc.scene();
  s.render.frame = 12;
  doc.edit(std::move(s), "Edit frame", "render:frame");
  EXPECT_EQ(doc.scene().render.frame, 12.f);
  EXPECT_EQ(doc.history().size(), steps);
}

TEST(AutoKey, AnEditOfAnAnimatedParameterKeysItAtTheFrame) {
  Document doc = animated_document();
  doc.set_frame(6);
  // As the properties panel does: the item as shown at frame 6, one field changed.
  const SceneDesc shown = scene_at_frame(doc.scene(), 6);
  SceneDesc s = doc.scene();
  s.objects[1] = shown.objects[1];
  s.objects[1].transform.translate.x = 1.5f;
  doc.edit(std::move(s), "Edit translate");
  const TrackDesc* track = find_track(doc.scene(), "objects/sphere/transform/translate");
  ASSERT_EQ(track->keys.size(), 3u);
  EXPECT_EQ(track->keys[1].frame, 6.0);
  EXPECT_EQ(scene_at_frame(doc.scene(), 6).objects[1].transform.translate.x, 1.5f);
  // One undo step takes the key back.
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(find_track(doc.scene(), "objects/sphere/transform/translate")->keys.size(), 2u);

  // Deleting a graph's node in the node editor drops its tracks in the same step.
  s = doc.scene();
  s.materials[1].data = graph_from_material(ToonDesc{});
  doc.edit(std::move(s), "Make graph");
  s = doc.scene();
  ASSERT_TRUE(insert_key(s, "materials/red/nodes/surface/threshold", 1));
  doc.edit(std::move(s), "Insert key");
  s = doc.scene();
  EXPECT_EQ(remove_nodes(std::get<GraphDesc>(s.materials[1].data), {"surface"}), 1u);
  doc.edit(std::move(s), "Delete nodes");
  EXPECT_EQ(find_track(doc.scene(), "materials/red/nodes/surface/threshold"), nullptr);
}

TEST(Playback, FollowsTheClockAndLoopsOverTheShot) {
  RenderSettings r;
  r.frame_start = 1;
  r.frame_end = 10;
  r.fps = 10.f;
  PlaybackClock clock;
  const auto t0 = PlaybackClock::Clock::now();
  clock.start(8, t0);
  EXPECT_EQ(clock.frame_at(t0, r), 8.0);
  EXPECT_EQ(clock.frame_at(t0 + 99ms, r), 8.0);
  EXPECT_EQ(clock.frame_at(t0 + 100ms, r), 9.0);
  EXPECT_EQ(clock.frame_at(t0 + 250ms, r), 10.0);
  EXPECT_EQ(clock.frame_at(t0 + 300ms, r), 1.0);  // looped
  // A late look skips the frames in between: the clock never falls behind.
  EXPECT_EQ(clock.frame_at(t0 + 1500ms, r), 3.0);
  // From outside the shot, playback starts at its first frame.
  clock.start(40, t0);
  EXPECT_EQ(clock.frame_at(t0, r), 1.0);
}

}  // namespace
}  // namespace inkray
