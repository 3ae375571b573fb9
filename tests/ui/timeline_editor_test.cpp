// The timeline and keys in the real editor under Xvfb, driven by an input script
// (--input-script, ui/editor_app.cpp): I keys a field at two frames, a drag of an
// animated field keys it, Alt+I and the field's menu delete and insert keys, the
// timeline scrubs to a frame in between (the field shows the interpolated value),
// Space plays and stops, and undo takes a key back without moving the frame.
#include "core/document/animation.h"
#include "core/document/json_io.h"

#include "tests/support/editor_run.h"

#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace inkray {
namespace {

using testing::editor_command;
using testing::editor_unavailable;
using testing::run_command;
using testing::ScratchFolder;

// The numbers after the n-th line starting with `head` in the editor's output.
std::vector<double> printed(const std::string& out, const std::string& head, int n = 0) {
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(head + " ", 0) != 0 || n-- > 0) continue;
    std::istringstream words(line.substr(head.size()));
    std::vector<double> numbers;
    std::string word;
    while (words >> word) {
      if (std::isdigit(static_cast<unsigned char>(word.back()))) numbers.push_back(std::stod(word));
    }
    return numbers;
  }
  return {};
}

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

TEST(TimelineEditor, KeysScrubsPlaysAndUndoesFromTheKeyboardAndMouse) {
  if (const std::string why = editor_unavailable(); !why.empty()) GTEST_SKIP() << why;
  ScratchFolder dir;
  const auto script = dir / "input.txt";
  std::ofstream(script) << kScript;
  const std::string scene = std::string(INKRAY_SOURCE_DIR) + "/tests/ui/data/timeline.json";
  const auto dump = dir / "dump.json";
  int code = 0;
  const std::string out =
      run_command(editor_command(dir.path(), 1280, 720) + " --input-script " + script.string() +
                      " --threads 1 --select ball --frames 110 --screenshot " +
                      (dir / "timeline.png").string() + " --scene-dump " + dump.string() + " " + scene,
                  &code);
  ASSERT_EQ(code, 0) << out;
  ASSERT_NE(out.find("input script: done"), std::string::npos) << out;

  // Shift+Right went to the shot's last frame; the drag there moved the ball along x.
  EXPECT_EQ(printed(out, "frame", 0), std::vector<double>{24}) << out;
  const std::vector<double> at_end = printed(out, "value", 0), at_start = printed(out, "value", 1);
  ASSERT_EQ(at_end.size(), 3u) << out;
  ASSERT_EQ(at_start.size(), 3u) << out;
  EXPECT_EQ(at_start[0], -1.0);
  EXPECT_GT(at_end[0], at_start[0] + 0.05) << out;
  EXPECT_EQ(printed(out, "keys", 0), (std::vector<double>{1, 24})) << out;

  // I, Alt+I and the menu's "Insert key" on the material's colour.
  EXPECT_EQ(printed(out, "keys", 1), std::vector<double>{24}) << out;
  EXPECT_TRUE(printed(out, "keys", 2).empty()) << out;
  EXPECT_EQ(printed(out, "keys", 3), std::vector<double>{24}) << out;

  // Scrubbing to the bar's middle shows a frame between the keys, and a value between theirs.
  const std::vector<double> scrubbed = printed(out, "frame", 1);
  ASSERT_EQ(scrubbed.size(), 1u) << out;
  EXPECT_GT(scrubbed[0], 1.0);
  EXPECT_LT(scrubbed[0], 24.0);
  const std::vector<double> between = printed(out, "value", 2);
  ASSERT_EQ(between.size(), 3u) << out;
  EXPECT_GT(between[0], at_start[0]);
  EXPECT_LT(between[0], at_end[0]);

  // Half a second of playback at 24 fps moved the frame; undo took the menu's key back
  // and left the frame where playback stopped.
  const std::vector<double> played = printed(out, "frame", 2);
  ASSERT_EQ(played.size(), 1u) << out;
  EXPECT_NE(played[0], scrubbed[0]) << out;
  EXPECT_TRUE(printed(out, "keys", 4).empty()) << out;
  EXPECT_EQ(printed(out, "frame", 3), played) << out;

  // The document as it was left: two keys on the ball's position, the frame played to.
  const SceneLoadResult saved = load_scene(dump);
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
