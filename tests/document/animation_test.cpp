// Tracks: paths into the document, interpolation, JSON, validation, and the compiled
// picture at a frame (document/animation.h).
#include "core/document/animation.h"

#include "core/compiler/compile.h"
#include "core/compiler/compile_objects.h"
#include "core/document/error_log.h"
#include "core/document/json_io.h"
#include "core/document/memory_budget.h"
#include "tests/support/messages.h"
#include "tests/support/render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inkray {
namespace {

using testing::joined;

KeyDesc key(double frame, std::vector<double> value, Interpolation interp = Interpolation::bezier) {
  return {frame, std::move(value), interp};
}

SceneDesc ball_scene() {
  SceneDesc d = testing::small_scene(32, 24);
  d.materials.push_back({"toon", ToonDesc{}, {}});
  d.objects.push_back(testing::make_object("ball", SphereDesc{}, "toon"));
  d.objects.back().transform.rotate.push_back({{0.f, 1.f, 0.f}, 10.f});
  d.lights.push_back({"key", PointLightDesc{{2.f, 3.f, 4.f}, Color(1.f), 20.f}});
  d.outlines.enabled = true;
  return d;
}

TEST(Animation, PathsReachEveryKindOfKeyableParameter) {
  const SceneDesc d = ball_scene();
  for (const char* path :
       {"camera/look_from", "camera/vfov", "camera/focus_distance", "objects/ball/transform/translate",
        "objects/ball/transform/scale", "objects/ball/transform/rotate/0/degrees", "objects/ball/visible",
        "objects/ball/shape/radius", "lights/key/intensity", "lights/key/color", "materials/toon/threshold",
        "materials/toon/color", "outlines/width", "outlines/silhouette/color", "environment/color",
        "render/painterly_radius"}) {
    std::string error;
    EXPECT_TRUE(animation_target(d, path, &error)) << path << ": " << error;
  }
}

TEST(Animation, PathsThatCannotBeKeyedSayWhy) {
  const SceneDesc d = ball_scene();
  const std::pair<const char*, const char*> cases[] = {
      {"objects/cube/transform/translate", "no entry named \"cube\""},
      {"objects/ball/transform/rotate/3/degrees", "1 rotations"},
      {"objects/ball/colour", "no parameter \"colour\""},
      {"objects/ball/material", "cannot be keyed"},
      {"render/width", "cannot be keyed"},
      {"materials/toon", "add a parameter"},
      {"outlines/silhouette", "group"},
      {"sky/color", "a target starts with"},
  };
  for (const auto& [path, expected] : cases) {
    std::string error;
    EXPECT_FALSE(animation_target(d, path, &error)) << path;
    EXPECT_NE(error.find(expected), std::string::npos) << path << ": " << error;
  }
}

TEST(Animation, LinearAndStepKeysInterpolateAsNamed) {
  TrackDesc t{"camera/vfov",
              {key(1, {10}, Interpolation::linear), key(5, {30}, Interpolation::step), key(9, {0})}};
  EXPECT_DOUBLE_EQ(track_value(t, -3)[0], 10);
  EXPECT_DOUBLE_EQ(track_value(t, 1)[0], 10);
  EXPECT_DOUBLE_EQ(track_value(t, 2)[0], 15);
  EXPECT_DOUBLE_EQ(track_value(t, 4.5)[0], 27.5);
  EXPECT_DOUBLE_EQ(track_value(t, 5)[0], 30);
  EXPECT_DOUBLE_EQ(track_value(t, 8.99)[0], 30);
  EXPECT_DOUBLE_EQ(track_value(t, 9)[0], 0);
  EXPECT_DOUBLE_EQ(track_value(t, 100)[0], 0);
}

TEST(Animation, BezierKeysPassThroughKeysEaseAndNeverOvershoot) {
  // Uneven spacing and a peak: the curve must stay within each span's key values.
  TrackDesc t{"x", {key(1, {0, 5, 0}), key(2, {1, 5, 10}), key(10, {4, 5, 0}), key(11, {4.2, 5, 3})}};
  for (const KeyDesc& k : t.keys)
    for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(track_value(t, k.frame)[c], k.value[c], 1e-12);
  for (size_t i = 0; i + 1 < t.keys.size(); ++i) {
    const KeyDesc& a = t.keys[i];
    const KeyDesc& b = t.keys[i + 1];
    double last = a.value[0];
    for (int s = 1; s < 100; ++s) {
      const double f = a.frame + (b.frame - a.frame) * s / 100.0;
      const std::vector<double> v = track_value(t, f);
      for (size_t c = 0; c < 3; ++c) {
        EXPECT_GE(v[c], std::min(a.value[c], b.value[c]) - 1e-12) << f;
        EXPECT_LE(v[c], std::max(a.value[c], b.value[c]) + 1e-12) << f;
      }
      EXPECT_GE(v[0], last - 1e-12) << "x rises monotonically through monotone keys, frame " << f;
      last = v[0];
    }
  }
  // Eases out of the first key: slower than linear near it.
  EXPECT_LT(track_value(t, 1.1)[2], 1.0);
}

TEST(Animation, TheDocumentAtAFrameCarriesEveryTrack) {
  SceneDesc d = ball_scene();
  d.animation.push_back(
      {"objects/ball/transform/translate", {key(1, {0, 0, 0}, Interpolation::linear), key(11, {1, 2, 3})}});
  d.animation.push_back({"objects/ball/visible", {key(1, {1}), key(5, {0})}});
  d.animation.push_back({"materials/toon/bands", {key(1, {2}, Interpolation::linear), key(3, {5})}});
  d.animation.push_back({"outlines/unit", {key(1, {0}), key(4, {2})}});
  const SceneDesc at6 = scene_at_frame(d, 6);
  EXPECT_FLOAT_EQ(at6.objects[0].transform.translate.y, 1.f);
  EXPECT_TRUE(scene_at_frame(d, 4.9).objects[0].visible) << "toggles step, they do not round halfway";
  EXPECT_FALSE(at6.objects[0].visible);
  EXPECT_EQ(std::get<ToonDesc>(scene_at_frame(d, 2.5).materials[0].data).bands, 4) << "integers round";
  EXPECT_EQ(at6.outlines.unit, LineWidthUnit::world);
  EXPECT_EQ(d.objects[0].transform.translate, Vec3(0.f)) << "the document itself is unchanged";
  EXPECT_TRUE(animated_between(d, 2, 3));
  EXPECT_FALSE(animated_between(d, 11, 20));
}

TEST(Animation, WritesAreClampedToTheParameterRange) {
  SceneDesc d = ball_scene();
  d.animation.push_back({"materials/toon/threshold", {key(1, {-1}, Interpolation::linear), key(3, {3})}});
  EXPECT_FLOAT_EQ(std::get<ToonDesc>(scene_at_frame(d, 1).materials[0].data).threshold, 0.f);
  EXPECT_FLOAT_EQ(std::get<ToonDesc>(scene_at_frame(d, 3).materials[0].data).threshold, 1.f);
}

TEST(Animation, InsertAndDeleteKeysKeepTracksSorted) {
  SceneDesc d = ball_scene();
  d.camera.vfov = 30.f;
  ASSERT_TRUE(insert_key(d, "camera/vfov", 10));
  d.camera.vfov = 50.f;
  ASSERT_TRUE(insert_key(d, "camera/vfov", 1));
  d.camera.vfov = 60.f;
  ASSERT_TRUE(insert_key(d, "camera/vfov", 10));  // replaces
  const TrackDesc* t = find_track(d, "camera/vfov");
  ASSERT_TRUE(t);
  ASSERT_EQ(t->keys.size(), 2u);
  EXPECT_EQ(t->keys[0].frame, 1);
  EXPECT_EQ(t->keys[1].value, std::vector<double>{60.0});
  EXPECT_FALSE(insert_key(d, "camera/nothing", 1));
  EXPECT_TRUE(delete_key(d, "camera/vfov", 1));
  EXPECT_FALSE(delete_key(d, "camera/vfov", 1));
  EXPECT_TRUE(delete_key(d, "camera/vfov", 10));
  EXPECT_EQ(find_track(d, "camera/vfov"), nullptr) << "the last key takes its track with it";
}

constexpr const char* kHeader = R"({"format": "inkray-scene", "version": 1,
  "materials": [{"name": "m", "type": "toon"}],
  "objects": [{"name": "ball", "material": "m", "shape": {"type": "sphere"}}],
  "lights": [{"name": "key", "type": "point", "position": [0, 4, 0]}],
)";

SceneLoadResult parse_with(const std::string& animation) {
  return parse_scene(std::string(kHeader) + R"("animation": )" + animation + "}", ".", "anim.json");
}

TEST(AnimationJson, RoundTripsEveryValueKind) {
  const SceneLoadResult loaded = parse_with(R"([
    {"target": "objects/ball/transform/translate", "keys": [{"frame": 1, "value": [0, 0, 0], "interp": "linear"},
                                                          {"frame": 12.5, "value": [1, 0.3, 0]}]},
    {"target": "objects/ball/visible", "keys": [{"frame": 1, "value": true}, {"frame": 4, "value": false}]},
    {"target": "materials/m/bands", "keys": [{"frame": 1, "value": 2}, {"frame": 4, "value": 3, "interp": "step"}]},
    {"target": "outlines/unit", "keys": [{"frame": 1, "value": "world"}]},
    {"target": "materials/m/color", "keys": [{"frame": 2, "value": [0.1, 0.2, 0.3]}]}])");
  ASSERT_TRUE(loaded) << joined(loaded.errors);
  const SceneDesc& d = *loaded.scene;
  ASSERT_EQ(d.animation.size(), 5u);
  EXPECT_EQ(d.animation[0].keys[0].interp, Interpolation::linear);
  EXPECT_EQ(d.animation[1].keys[1].value, std::vector<double>{0.0});
  EXPECT_EQ(d.animation[3].keys[0].value, std::vector<double>{2.0});
  const std::string text = scene_to_string(d);
  EXPECT_NE(text.find("\"value\": \"world\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"value\": false"), std::string::npos);
  EXPECT_NE(text.find("0.3"), std::string::npos);
  const SceneLoadResult again = parse_scene(text, ".", "again.json");
  ASSERT_TRUE(again) << joined(again.errors);
  EXPECT_EQ(again.scene->animation, d.animation);
}

TEST(AnimationJson, BrokenTracksAreNamedWithWhatWasExpected) {
  const std::pair<const char*, const char*> cases[] = {
      {R"([{"target": "objects/cube/transform/translate", "keys": [{"frame": 1, "value": [0,0,0]}]}])",
       "animation[0] (\"objects/cube/transform/translate\"): no entry named \"cube\""},
      {R"([{"target": "objects/ball/transform/translate", "keys": [{"frame": 1, "value": 3}]}])",
       "animation[0].keys[0].value: expected an array of 3 numbers"},
      {R"([{"target": "materials/m/threshold", "keys": [{"frame": 1, "value": "high"}]}])",
       "animation[0].keys[0].value: expected a number in [0, 1]"},
      {R"([{"target": "outlines/unit", "keys": [{"frame": 1, "value": "inches"}]}])",
       "expected one of \"pixels\", \"percent\", \"world\""},
      {R"([{"target": "camera/vfov", "keys": [{"frame": 5, "value": 30}, {"frame": 2, "value": 40}]}])",
       "animation[0].keys[1].frame: keys must be in increasing frame order"},
      {R"([{"target": "camera/vfov", "keys": [{"frame": 5, "value": 30}, {"frame": 5, "value": 40}]}])",
       "one per frame"},
      {R"([{"target": "camera/vfov", "keys": [{"frame": 1, "value": 30}]},
           {"target": "camera/vfov", "keys": [{"frame": 2, "value": 30}]}])",
       "animation[1].target: another track already animates \"camera/vfov\""},
      {R"([{"target": "camera/vfov", "keys": []}])", "animation[0].keys: expected a non-empty array of keys"},
      {R"([{"target": "camera/vfov", "keys": [{"value": 30}]}])", "missing required key \"frame\""},
      {R"([{"target": "camera/vfov", "keys": [{"frame": 1, "value": 30, "ease": 1}]}])", "ease"},
      {R"({"target": "camera/vfov"})", "animation: expected an array of tracks"},
      {R"([{"keys": []}])", "animation[0].target: expected a parameter path"},
  };
  for (const auto& [animation, expected] : cases) {
    const SceneLoadResult loaded = parse_with(animation);
    EXPECT_FALSE(loaded) << animation;
    EXPECT_NE(joined(loaded.errors).find(expected), std::string::npos)
        << animation << "\n got: " << joined(loaded.errors);
  }
}

TEST(AnimationJson, AnUnknownTargetStillOpensForEditingAndKeepsItsKeys) {
  const std::string text = std::string(kHeader) +
                           R"("animation": [{"target": "objects/gone/transform/translate",
                                             "keys": [{"frame": 1, "value": [1, 2, 3]}]}]})";
  const SceneLoadResult loaded = parse_scene(text, ".", "anim.json", ReadFor::editing);
  ASSERT_TRUE(loaded) << joined(loaded.errors);
  EXPECT_NE(joined(loaded.warnings).find("no entry named \"gone\""), std::string::npos)
      << joined(loaded.warnings);
  EXPECT_EQ(loaded.scene->animation[0].keys[0].value, (std::vector<double>{1, 2, 3}));
  EXPECT_NE(scene_to_string(*loaded.scene).find("\"objects/gone/transform/translate\""), std::string::npos);
}

// Many tracks: 5,000 on one target once made 12.5 million messages (2.1 GiB), one per
// pair. A track sharing its target is reported once, against the first; tracks on
// thousands of objects resolve (through an index of names) and all apply.
TEST(AnimationScale, ManyTracksGiveALineEachAndAllApply) {
  constexpr int kTracks = 5000;
  SceneDesc shared = ball_scene();
  for (int i = 0; i < kTracks; ++i)
    shared.animation.push_back({"objects/ball/transform/translate", {key(1, {0, double(i), 0})}});
  const std::vector<std::string> problems = check_animation(shared);
  ASSERT_EQ(problems.size(), size_t(kTracks - 1));
  EXPECT_EQ(problems.back(),
            "animation[4999] (\"objects/ball/transform/translate\"): animation[0] already "
            "animates this target");
  const std::string text = scene_to_string(shared);
  const SceneLoadResult loaded = parse_scene(text, ".", "many.json");
  ASSERT_FALSE(loaded);
  // The reader reports the first ErrorLog::kMaxLines problems and how many more there are.
  EXPECT_EQ(loaded.errors.size(), ErrorLog::kMaxLines + 1);
  ASSERT_FALSE(loaded.errors.empty());
  EXPECT_NE(loaded.errors[0].find("animation[1].target: another track already animates"), std::string::npos)
      << loaded.errors[0];

  SceneDesc spread = ball_scene();
  for (int i = 0; i < kTracks; ++i) {
    spread.objects.push_back(testing::make_object("o" + std::to_string(i), SphereDesc{}, "toon"));
    spread.animation.push_back({"objects/o" + std::to_string(i) + "/transform/translate",
                                {key(1, {0, 0, 0}, Interpolation::linear), key(3, {double(i), 0, 0})}});
  }
  EXPECT_TRUE(check_animation(spread).empty()) << joined(check_animation(spread));
  const SceneDesc at = scene_at_frame(spread, 2);
  for (int i = 0; i < kTracks; ++i)
    ASSERT_EQ(at.objects[size_t(i) + 1].transform.translate.x, float(i) / 2) << i;
  const SceneLoadResult reopened = parse_scene(scene_to_string(spread), ".", "spread.json");
  ASSERT_TRUE(reopened) << joined(reopened.errors);
  EXPECT_EQ(reopened.scene->animation, spread.animation);
}

// Keys take memory: 400,000 of them cost 278 MB of peak memory in inkray-render
// (scripts/measure_memory_costs), so the estimate counts them and a budget refuses them.
TEST(AnimationScale, KeysCountInTheMemoryEstimate) {
  SceneDesc d = ball_scene();
  TrackDesc track{"objects/ball/transform/translate", {}};
  for (int k = 0; k < 400000; ++k) track.keys.push_back(key(k + 1, {0, k * 1e-6, 0}, Interpolation::linear));
  d.animation = {track};
  const MemoryEstimate estimate = estimate_memory(d);
  ASSERT_FALSE(estimate.items.empty());
  EXPECT_EQ(estimate.items[0].what, "animation (400000 keys)");
  EXPECT_GE(estimate.items[0].bytes, std::uint64_t(278) << 20);
  std::vector<std::string> errors;
  check_memory_budget(d, std::uint64_t(128) << 20, errors);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("animation (400000 keys)"), std::string::npos) << errors[0];
}

TEST(AnimationCompile, TheCompilerRendersTheCurrentFrame) {
  SceneDesc d = ball_scene();
  d.animation.push_back({"objects/ball/transform/translate", {key(1, {0, 0, 0}), key(3, {5, 0, 0})}});
  SceneCompiler compiler;
  d.render.frame = 1;
  const CompileResult a = compiler.compile(d);
  ASSERT_TRUE(a.scene) << joined(a.errors);
  d.render.frame = 3;
  const CompileResult b = compiler.compile(d);
  ASSERT_TRUE(b.scene) << joined(b.errors);
  EXPECT_NEAR(a.scene->world->scene_center.x, 0.f, 1e-4f);
  EXPECT_NEAR(b.scene->world->scene_center.x, 5.f, 1e-4f);
  EXPECT_TRUE(b.changes.has(Stage::object));
  EXPECT_FALSE(b.changes.has(Stage::material)) << "a frame step changes what moved and nothing else";
}

TEST(AnimationCompile, StrokesMoveWithTheirObjectAndKeepTheirPlaces) {
  SceneDesc d = ball_scene();
  d.strokes.push_back(StrokeEmitterDesc{.name = "paint", .object = "ball", .count = 50});
  d.render.frame_start = 1;
  d.animation.push_back({"objects/ball/transform/translate", {key(1, {0, 0, 0}), key(5, {2, 1, 0})}});
  d.animation.push_back({"objects/ball/transform/rotate/0/degrees", {key(1, {10}), key(5, {100})}});
  const auto stroke_mesh = [](const RenderScene& s) {
    for (uint32_t i = 0; i < s.world->objects.size(); ++i)
      if (s.world->objects[i].name == "paint") return std::get<TriangleMesh>(s.world->geometry.shape(i));
    ADD_FAILURE() << "no strokes";
    return TriangleMesh{};
  };
  SceneCompiler compiler;
  d.render.frame = 1;
  const CompileResult rest = compiler.compile(d);
  ASSERT_TRUE(rest.scene) << joined(rest.errors);
  const TriangleMesh at_rest = stroke_mesh(*rest.scene);
  d.render.frame = 5;
  const CompileResult moved = compiler.compile(d);
  ASSERT_TRUE(moved.scene) << joined(moved.errors);
  const TriangleMesh now = stroke_mesh(*moved.scene);
  ASSERT_EQ(now.positions.size(), at_rest.positions.size()) << "the same strokes, none grown again";
  const SceneDesc at5 = scene_at_frame(d, 5), at1 = scene_at_frame(d, 1);
  const Transform t5 = transform_from_desc(at5.objects[0].transform);
  const Transform t1 = transform_from_desc(at1.objects[0].transform);
  for (size_t i = 0; i + 1 < now.positions.size(); i += 37) {
    const Point3 in_object = Point3(t1.inv * glm::vec4(at_rest.positions[i], 1.f));
    EXPECT_LT(glm::length(now.positions[i] - t5.point(in_object)), 1e-4f) << i;
  }
}

}  // namespace
}  // namespace inkray
