// The Line sets panel in the real editor under Xvfb, driven by an input script
// (--input-script, ui/editor_app.cpp): its tab opens, Add makes an ink set, the style's
// Preset menu turns it to pencil, Up moves it to the front of the drawing order, a drag
// edits its opacity, I keys its width at two frames (outlines/sets/NAME/style/width),
// a row's switch turns a set off, Delete takes two sets away and undo brings the last
// one back. The document the editor ends with says each of these happened.
#include "core/document/animation.h"
#include "core/document/json_io.h"

#include "tests/support/editor_run.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace inkray {
namespace {

using namespace inkray::testing;

// The scene has the sets "outline" and "hidden"; Add makes "ink", chosen, drawn last.
constexpr const char* kScript = R"(wait 3
hover tabs.line_sets
click
wait 2
hover line_sets.add
click
wait 2
hover preset:outlines/sets/ink/style
click
# The menu's first frame sizes it out of sight.
wait 3
hover preset_menu.pencil
click
wait 2
print-value outlines/sets/ink/style/passes
hover line_sets.up
click
wait 2
hover line_sets.up
click
wait 2
hover param:outlines/sets/ink/style/opacity 0.02 0.5
down
hover param:outlines/sets/ink/style/opacity 0.2 0.5
up
wait 2
print-value outlines/sets/ink/style/opacity
hover param:outlines/sets/ink/style/width
key i
hover timeline.scrub 0.5 0.8
key shift+right
print-frame
hover param:outlines/sets/ink/style/width
key i
print-keys outlines/sets/ink/style/width
hover line_sets.enabled:outline
click
wait 2
print-value outlines/sets/outline/enabled
hover line_sets.row:hidden
click
hover line_sets.delete
click
wait 2
hover line_sets.row:outline
click
hover line_sets.delete
click
wait 2
key ctrl+z
wait 2
)";

class LineSetsEditor : public EditorTest {};

TEST_F(LineSetsEditor, AddsStylesMovesKeysDeletesAndUndoes) {
  // Tall enough for the chosen set's style fields to show without scrolling.
  const std::string out =
      run_editor_script(dir, 1280, 1100, kScript, "--threads 1 --frames 160", "line_sets.json", &code);
  ASSERT_EQ(code, 0) << out;
  ASSERT_NE(out.find("input script: done"), std::string::npos) << out;

  // The pencil preset goes over each line twice; the drag took the opacity below its 0.8.
  EXPECT_EQ(printed_numbers(out, "value", 0), std::vector<double>{2}) << out;
  const std::vector<double> opacity = printed_numbers(out, "value", 1);
  ASSERT_EQ(opacity.size(), 1u) << out;
  EXPECT_LT(opacity[0], 0.75) << out;
  // Keys at the first frame and, after Shift+Right, at the last.
  EXPECT_EQ(printed_numbers(out, "frame", 0), std::vector<double>{24}) << out;
  EXPECT_EQ(printed_numbers(out, "keys", 0), (std::vector<double>{1, 24})) << out;
  EXPECT_EQ(printed_numbers(out, "value", 2), std::vector<double>{0}) << out;

  // The document as it was left: "ink" moved to the front, "hidden" deleted, and the
  // delete of "outline" undone (it comes back switched off, behind "ink").
  const SceneLoadResult saved = load_scene(dir / "dump.json");
  ASSERT_TRUE(saved) << (saved.errors.empty() ? "" : saved.errors.front());
  const std::vector<LineSetDesc>& sets = saved.scene->outlines.sets;
  ASSERT_EQ(sets.size(), 2u) << out;
  EXPECT_EQ(sets[0].name, "ink");
  EXPECT_EQ(sets[1].name, "outline");
  EXPECT_FALSE(sets[1].enabled);
  LineSetStyleDesc pencil;
  ParamPresets<LineSetStyleDesc>::apply("pencil", pencil);
  LineSetStyleDesc ink = sets[0].style;
  EXPECT_NEAR(ink.opacity, opacity[0], 1e-5);
  ink.opacity = pencil.opacity;
  EXPECT_EQ(ink, pencil);
  const TrackDesc* width = find_track(*saved.scene, "outlines/sets/ink/style/width");
  ASSERT_NE(width, nullptr);
  ASSERT_EQ(width->keys.size(), 2u);
  EXPECT_NEAR(width->keys[1].value[0], pencil.width, 1e-5);
  EXPECT_TRUE(check_animation(*saved.scene).empty());
}

}  // namespace
}  // namespace inkray
