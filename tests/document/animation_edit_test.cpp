// Tracks following the document's edits (document/animation_edit.h): renames move
// them, deletions drop them, an edited animated parameter gets a key where it was
// edited, and keys set or removed by hand keep what the frame shows.
#include "core/document/animation_edit.h"

#include "core/document/animation.h"
#include "core/document/graph_edit.h"
#include "tests/support/messages.h"
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

using testing::joined;

SceneDesc animated_scene() {
  SceneDesc d = testing::small_scene(32, 24);
  d.materials.push_back({"toon", ToonDesc{}, {}});
  d.materials.push_back({"nodes", graph_from_material(ToonDesc{}), {}});
  d.objects.push_back(testing::make_object("ball", SphereDesc{}, "toon"));
  d.objects.push_back(testing::make_object("ball.1", SphereDesc{}, "nodes"));
  d.lights.push_back({"key", PointLightDesc{{2.f, 3.f, 4.f}, Color(1.f), 20.f}});
  d.render.frame_start = 1;
  d.render.frame_end = 20;
  for (const char* path :
       {"objects/ball/transform/translate", "objects/ball.1/transform/translate", "lights/key/intensity",
        "materials/toon/threshold", "materials/nodes/nodes/surface/threshold"}) {
    EXPECT_TRUE(insert_key(d, path, 1.0)) << path;
  }
  d.objects[0].transform.translate = Vec3(2.f, 0.f, 0.f);
  EXPECT_TRUE(insert_key(d, "objects/ball/transform/translate", 11.0));
  return d;
}

std::vector<std::string> targets(const SceneDesc& d) {
  std::vector<std::string> out;
  for (const TrackDesc& t : d.animation) out.push_back(t.target);
  return out;
}

TEST(AnimationEdit, PathsOfEntriesAndNodes) {
  EXPECT_EQ(entry_path("objects", "ball"), "objects/ball/");
  EXPECT_EQ(entry_path("strokes", "fur"), "strokes/fur/");
  EXPECT_EQ(node_path("toon", "rim"), "materials/toon/nodes/rim/");
}

TEST(AnimationEdit, RenameMovesOnlyThatEntrysTracks) {
  SceneDesc d = animated_scene();
  d.objects[0].name = "sphere";
  // "objects/ball/" is not a prefix of "objects/ball.1/...": names end at the slash.
  EXPECT_EQ(rename_tracks(d, "objects/ball/", "objects/sphere/"), 1u);
  EXPECT_NE(find_track(d, "objects/sphere/transform/translate"), nullptr);
  EXPECT_EQ(find_track(d, "objects/ball/transform/translate"), nullptr);
  EXPECT_NE(find_track(d, "objects/ball.1/transform/translate"), nullptr);
  EXPECT_EQ(find_track(d, "objects/sphere/transform/translate")->keys.size(), 2u);
  EXPECT_TRUE(check_animation(d).empty()) << joined(check_animation(d));

  // A graph node's id: its settings' tracks follow too.
  EXPECT_EQ(rename_tracks(d, node_path("nodes", "surface"), node_path("nodes", "paint")), 1u);
  EXPECT_NE(find_track(d, "materials/nodes/nodes/paint/threshold"), nullptr);
}

TEST(AnimationEdit, DeleteAndCopyByPrefix) {
  SceneDesc d = animated_scene();
  EXPECT_EQ(copy_tracks(d, "lights/key/", "lights/fill/"), 1u);
  EXPECT_NE(find_track(d, "lights/fill/intensity"), nullptr);
  EXPECT_EQ(delete_tracks(d, "lights/"), 2u);
  EXPECT_EQ(delete_tracks(d, "objects/ball/"), 1u);
  EXPECT_EQ(targets(d),
            (std::vector<std::string>{"objects/ball.1/transform/translate", "materials/toon/threshold",
                                      "materials/nodes/nodes/surface/threshold"}));
}

TEST(AnimationEdit, TracksOfParametersAnEditTookAwayGo) {
  const SceneDesc before = animated_scene();
  SceneDesc after = before;
  // The graph loses its closure node, and the toon material becomes diffuse (no threshold).
  auto& graph = std::get<GraphDesc>(after.materials[1].data);
  EXPECT_EQ(remove_nodes(graph, {"surface"}), 1u);
  after.materials[0].data = DiffuseDesc{};
  EXPECT_EQ(drop_vanished_tracks(before, after), 2u);
  EXPECT_EQ(find_track(after, "materials/toon/threshold"), nullptr);
  EXPECT_EQ(find_track(after, "materials/nodes/nodes/surface/threshold"), nullptr);
  EXPECT_EQ(after.animation.size(), 3u);

  // A track that was already broken is left for check_animation to report.
  SceneDesc broken = before;
  broken.animation.push_back({"objects/nobody/visible", {{1.0, {1.0}, Interpolation::step}}});
  SceneDesc edited = broken;
  EXPECT_EQ(drop_vanished_tracks(broken, edited), 0u);
}

TEST(AnimationEdit, EditingAnAnimatedParameterKeysItWhereItWasEdited) {
  // At frame 6, between the ball's keys at 1 and 11, with a light intensity its track hides.
  SceneDesc before = animated_scene();
  before.render.frame = 6;
  std::get<PointLightDesc>(before.lights[0].data).intensity = 50.f;
  const SceneDesc shown = scene_at_frame(before, before.render.frame);

  // The panel edits the ball as shown at frame 6: its translate changes, and the light's
  // intensity (animated, copied along with the value it shows) does not.
  SceneDesc after = before;
  after.objects[0] = shown.objects[0];
  after.objects[0].transform.translate.y = 3.f;
  after.lights[0] = shown.lights[0];
  after.materials[0].name = "toon";  // untouched
  EXPECT_EQ(key_edited(before, after), 1u);
  const TrackDesc* ball = find_track(after, "objects/ball/transform/translate");
  ASSERT_EQ(ball->keys.size(), 3u);
  EXPECT_EQ(ball->keys[1].frame, 6.0);
  EXPECT_EQ(ball->keys[1].value[1], 3.0);
  EXPECT_EQ(scene_at_frame(after, 6).objects[0].transform.translate.y, 3.f);

  // Nothing animated changed: no key.
  SceneDesc unrelated = before;
  unrelated.camera.vfov += 5.f;
  EXPECT_EQ(key_edited(before, unrelated), 0u);
  EXPECT_EQ(unrelated.animation, before.animation);
}

TEST(AnimationEdit, KeysByHandKeepWhatTheFrameShows) {
  SceneDesc d = animated_scene();
  d.render.frame = 6;
  const Vec3 at_6 = scene_at_frame(d, 6).objects[0].transform.translate;
  EXPECT_EQ(key_state(d, "objects/ball/transform/translate", 6), KeyState::animated);
  EXPECT_EQ(key_state(d, "objects/ball/transform/translate", 11), KeyState::keyed);
  EXPECT_EQ(key_state(d, "objects/ball/transform/scale", 6), KeyState::none);

  // A key at 6 holds the interpolated value, so the picture does not jump.
  ASSERT_TRUE(key_shown_value(d, "objects/ball/transform/translate", 6));
  EXPECT_EQ(key_state(d, "objects/ball/transform/translate", 6), KeyState::keyed);
  EXPECT_EQ(scene_at_frame(d, 6).objects[0].transform.translate, at_6);
  EXPECT_FALSE(key_shown_value(d, "objects/ball/material", 6));  // not keyable

  EXPECT_FALSE(unkey(d, "objects/ball/transform/translate", 7));  // no key there
  ASSERT_TRUE(unkey(d, "objects/ball/transform/translate", 1));
  ASSERT_TRUE(unkey(d, "objects/ball/transform/translate", 11));
  // The last key goes with the track; the parameter keeps the value frame 6 showed.
  ASSERT_TRUE(unkey(d, "objects/ball/transform/translate", 6));
  EXPECT_EQ(find_track(d, "objects/ball/transform/translate"), nullptr);
  EXPECT_EQ(d.objects[0].transform.translate, at_6);

  const float intensity = std::get<PointLightDesc>(scene_at_frame(d, 6).lights[0].data).intensity;
  std::get<PointLightDesc>(d.lights[0].data).intensity = 99.f;  // a base value the track hides
  ASSERT_TRUE(clear_keys(d, "lights/key/intensity"));
  EXPECT_EQ(std::get<PointLightDesc>(d.lights[0].data).intensity, intensity);
  EXPECT_FALSE(clear_keys(d, "lights/key/intensity"));
}

TEST(AnimationEdit, KeyFramesOfAllTracksOrOfOneEntry) {
  const SceneDesc d = animated_scene();
  EXPECT_EQ(key_frames(d), (std::vector<double>{1.0, 11.0}));
  EXPECT_EQ(key_frames(d, "objects/ball/"), (std::vector<double>{1.0, 11.0}));
  EXPECT_EQ(key_frames(d, "lights/key/"), (std::vector<double>{1.0}));
  EXPECT_TRUE(key_frames(d, "strokes/").empty());
}

}  // namespace
}  // namespace inkray
