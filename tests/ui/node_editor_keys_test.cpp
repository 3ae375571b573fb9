// Keys on a node material's parameters and on the render settings in the real editor
// under Xvfb, driven by an input script (--input-script, ui/editor_app.cpp): the node
// editor shows an animated parameter at the current frame, so a drag of its field starts
// from there and keys it; I and Alt+I over a node's colour bar and over a render-panel
// field insert and delete keys, as in the properties panel.
#include "core/document/animation.h"
#include "core/document/json_io.h"

#include "tests/support/editor_run.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace inkray {
namespace {

using namespace inkray::testing;

// The document is at frame 12; mask.b is keyed 0 at frame 1 and 2.3 at frame 24
// (1.1 at frame 12) over a stored 5.
constexpr const char* kScript = R"(wait 3
print-value materials/paint/nodes/mask/b
hover param:materials/paint/nodes/mask/b 0.5 0.5
down
hover param:materials/paint/nodes/mask/b 0.6 0.5
up
print-keys materials/paint/nodes/mask/b
print-value materials/paint/nodes/mask/b
hover param:materials/paint/nodes/rim/color 0.3 0.5
key i
print-keys materials/paint/nodes/rim/color
key alt+i
print-keys materials/paint/nodes/rim/color
# Keyed again, for the saved document.
key i
hover param:render/max_depth
key i
print-keys render/max_depth
)";

class NodeEditorKeys : public EditorTest {};

TEST_F(NodeEditorKeys, NodeAndRenderFieldsShowTheFrameAndTakeKeys) {
  const std::string out = run_editor_script(
      dir, 1600, 900, kScript, "--threads 1 --node-editor paint --frames 80", "node_keys.json", &code);
  ASSERT_EQ(code, 0) << out;
  ASSERT_NE(out.find("input script: done"), std::string::npos) << out;

  // The drag started from the frame's 1.1, not the stored 5, and keyed frame 12.
  EXPECT_NEAR(printed_numbers(out, "value", 0).at(0), 1.1, 1e-5) << out;
  EXPECT_EQ(printed_numbers(out, "keys", 0), (std::vector<double>{1, 12, 24})) << out;
  const double dragged = printed_numbers(out, "value", 1).at(0);
  EXPECT_NE(dragged, 1.1) << out;
  EXPECT_NEAR(dragged, 1.1, 0.5) << out;

  // I and Alt+I over the colour bar of the unlit node.
  EXPECT_EQ(printed_numbers(out, "keys", 1), std::vector<double>{12}) << out;
  EXPECT_TRUE(printed_numbers(out, "keys", 2).empty()) << out;
  // I over a field of the render panel.
  EXPECT_EQ(printed_numbers(out, "keys", 3), std::vector<double>{12}) << out;

  const SceneLoadResult saved = load_scene(dir / "dump.json");
  ASSERT_TRUE(saved) << (saved.errors.empty() ? "" : saved.errors.front());
  const TrackDesc* track = find_track(*saved.scene, "materials/paint/nodes/mask/b");
  ASSERT_NE(track, nullptr);
  ASSERT_EQ(track->keys.size(), 3u);
  ASSERT_EQ(track->keys[1].value.size(), 1u);
  EXPECT_NEAR(track->keys[1].value[0], dragged, 1e-5);  // printed with 6 digits
  const TrackDesc* colour = find_track(*saved.scene, "materials/paint/nodes/rim/color");
  ASSERT_NE(colour, nullptr);
  ASSERT_EQ(colour->keys.size(), 1u);
  EXPECT_NEAR(colour->keys[0].value[1], 0.92, 1e-6);
  ASSERT_NE(find_track(*saved.scene, "render/max_depth"), nullptr);
}

}  // namespace
}  // namespace inkray
