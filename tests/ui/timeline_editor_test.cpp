// The timeline and keys in the real editor under Xvfb, driven by an input script
// (--input-script, ui/editor_app.cpp): I keys a field at two frames, a drag of an
// animated field keys it, Alt+I and the field's menu delete and insert keys, the
// timeline scrubs to a frame in between (the field shows the interpolated value),
// Space plays and stops, and undo takes a key back without moving the frame.
#include "core/document/animation.h"
#include "core/document/json_io.h"

#include "tests/support/editor_run.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace inkray {
namespace {

using namespace inkray::testing;

constexpr const char* kScript = R"(# The ball is selected; its position is the first field of its transform.
wait 3
hover param:objects/ball/transform/translate 0.1 0.5
key i
hover timeline.scrub 0.5 0.8
key shift+right
print-frame
hover param:objects/ball/transform/translate 0.1 0.5
key i
down
hover param:objects/ball/transform/translate 0.25 0.5
up
print-value objects/ball/transform/translate
print-keys objects/ball/transform/translate
hover param:materials/red/albedo
key i
print-keys materials/red/albedo
key alt+i
print-keys materials/red/albedo
click right
hover keys_menu.insert
click
print-keys materials/red/albedo
hover timeline.scrub 0.5 0.8
key shift+left
print-value objects/ball/transform/translate
down
hover timeline.scrub 0.6 0.8
up
print-frame
print-value objects/ball/transform/translate
key space
wait-ms 500
key space
print-frame
key ctrl+z
print-keys materials/red/albedo
print-frame
)";

class TimelineEditor : public EditorTest {};

TEST_F(TimelineEditor, KeysScrubsPlaysAndUndoesFromTheKeyboardAndMouse) {
  const std::string out = run_editor_script(dir, 1280, 720, kScript, "--threads 1 --select ball --frames 110",
                                            "timeline.json", &code);
  ASSERT_EQ(code, 0) << out;
  ASSERT_NE(out.find("input script: done"), std::string::npos) << out;

  // Shift+Right went to the shot's last frame; the drag there moved the ball along x.
  EXPECT_EQ(printed_numbers(out, "frame", 0), std::vector<double>{24}) << out;
  const std::vector<double> at_end = printed_numbers(out, "value", 0),
                            at_start = printed_numbers(out, "value", 1);
  ASSERT_EQ(at_end.size(), 3u) << out;
  ASSERT_EQ(at_start.size(), 3u) << out;
  EXPECT_EQ(at_start[0], -1.0);
  EXPECT_GT(at_end[0], at_start[0] + 0.05) << out;
  EXPECT_EQ(printed_numbers(out, "keys", 0), (std::vector<double>{1, 24})) << out;

  // I, Alt+I and the menu's "Insert key" on the material's colour.
  EXPECT_EQ(printed_numbers(out, "keys", 1), std::vector<double>{24}) << out;
  EXPECT_TRUE(printed_numbers(out, "keys", 2).empty()) << out;
  EXPECT_EQ(printed_numbers(out, "keys", 3), std::vector<double>{24}) << out;

  // Scrubbing to the bar's middle shows a frame between the keys, and a value between theirs.
  const std::vector<double> scrubbed = printed_numbers(out, "frame", 1);
  ASSERT_EQ(scrubbed.size(), 1u) << out;
  EXPECT_GT(scrubbed[0], 1.0);
  EXPECT_LT(scrubbed[0], 24.0);
  const std::vector<double> between = printed_numbers(out, "value", 2);
  ASSERT_EQ(between.size(), 3u) << out;
  EXPECT_GT(between[0], at_start[0]);
  EXPECT_LT(between[0], at_end[0]);

  // Half a second of playback at 24 fps moved the frame; undo took the menu's key back
  // and left the frame where playback stopped.
  const std::vector<double> played = printed_numbers(out, "frame", 2);
  ASSERT_EQ(played.size(), 1u) << out;
  EXPECT_NE(played[0], scrubbed[0]) << out;
  EXPECT_TRUE(printed_numbers(out, "keys", 4).empty()) << out;
  EXPECT_EQ(printed_numbers(out, "frame", 3), played) << out;

  // The document as it was left: two keys on the ball's position, the frame played to.
  const SceneLoadResult saved = load_scene(dir / "dump.json");
  ASSERT_TRUE(saved) << (saved.errors.empty() ? "" : saved.errors.front());
  const TrackDesc* track = find_track(*saved.scene, "objects/ball/transform/translate");
  ASSERT_NE(track, nullptr);
  ASSERT_EQ(track->keys.size(), 2u);
  EXPECT_NEAR(track->keys[1].value[0], at_end[0], 1e-5);
  EXPECT_EQ(find_track(*saved.scene, "materials/red/albedo"), nullptr);
  EXPECT_EQ(double(saved.scene->render.frame), played[0]);
}

}  // namespace
}  // namespace inkray
