// The panel layout over window sizes from 1024x700 to 3840x2160 and UI scales 1 to 2:
// panels tile the window without overlap or gaps, keep their minimums, and a drag of a
// shared edge moves exactly that edge.
#include "ui/model/panel_layout.h"
#include "ui/model/ui_settings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace inkray {
namespace {

constexpr float kTop = 20.f;

float area(const PanelRect& r) { return r.w * r.h; }

bool overlap(const PanelRect& a, const PanelRect& b) {
  return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

// The timeline comes first: its height is fixed rather than a usable minimum.
std::vector<PanelRect> shown(const PanelRects& r, bool nodes) {
  std::vector<PanelRect> v{r.timeline, r.scene, r.viewport, r.output, r.properties};
  if (nodes) v.push_back(r.node_editor);
  return v;
}

TEST(PanelLayout, PanelsTileTheWindowAtEverySizeAndScale) {
  const float sizes[][2] = {{1024, 700}, {1280, 720}, {1600, 900}, {1920, 1080}, {2560, 1440}, {3840, 2160}};
  for (const auto& size : sizes) {
    for (float scale : {1.f, 1.25f, 1.5f, 2.f}) {
      for (bool nodes : {false, true}) {
        const PanelRects r = place_panels(PanelLayout{}, size[0], size[1], kTop, scale, nodes);
        const auto panels = shown(r, nodes);
        float total = 0.f;
        for (size_t i = 0; i < panels.size(); ++i) {
          const PanelRect& p = panels[i];
          SCOPED_TRACE(testing::Message() << size[0] << "x" << size[1] << " scale " << scale << " nodes "
                                          << nodes << " panel " << i);
          EXPECT_GE(p.x, 0.f);
          EXPECT_GE(p.y, kTop);
          EXPECT_LE(p.x + p.w, size[0] + 0.01f);
          EXPECT_LE(p.y + p.h, size[1] + 0.01f);
          EXPECT_GE(p.w, 150.f);  // usable at every size
          EXPECT_GE(p.h, i == 0 ? std::floor(kTimelineHeight * scale) : 110.f);
          total += area(p);
          for (size_t j = i + 1; j < panels.size(); ++j) EXPECT_FALSE(overlap(p, panels[j])) << "with " << j;
        }
        EXPECT_NEAR(total, size[0] * (size[1] - kTop), 1.f);  // no gaps
      }
    }
  }
}

TEST(PanelLayout, DraggingASharedEdgeMovesThatEdge) {
  for (bool nodes : {false, true}) {
    const PanelLayout layout;
    const PanelRects r = place_panels(layout, 1600, 900, kTop, 1.f, nodes);
    // The scene panel's right edge 40 px to the right.
    PanelRect dragged = r.scene;
    dragged.w += 40.f;
    PanelRects after =
        place_panels(resized(layout, Panel::scene, r, dragged, 1.f, nodes), 1600, 900, kTop, 1.f, nodes);
    EXPECT_FLOAT_EQ(after.scene.w, r.scene.w + 40.f);
    EXPECT_FLOAT_EQ(after.viewport.x, r.viewport.x + 40.f);
    EXPECT_FLOAT_EQ(after.properties.w, r.properties.w);
    // The properties panel's left edge 30 px to the left.
    dragged = r.properties;
    dragged.x -= 30.f, dragged.w += 30.f;
    after =
        place_panels(resized(layout, Panel::properties, r, dragged, 1.f, nodes), 1600, 900, kTop, 1.f, nodes);
    EXPECT_FLOAT_EQ(after.properties.w, r.properties.w + 30.f);
    EXPECT_FLOAT_EQ(after.scene.w, r.scene.w);
    // The viewport's bottom edge 50 px down.
    dragged = r.viewport;
    dragged.h += 50.f;
    after =
        place_panels(resized(layout, Panel::viewport, r, dragged, 1.f, nodes), 1600, 900, kTop, 1.f, nodes);
    EXPECT_NEAR(after.viewport.h, r.viewport.h + 50.f, 1.f);
    // The timeline stays under the viewport, as tall as before.
    EXPECT_NEAR(after.timeline.y, after.viewport.y + after.viewport.h, 0.01f);
    EXPECT_FLOAT_EQ(after.timeline.h, r.timeline.h);
    EXPECT_FLOAT_EQ(after.timeline.w, after.viewport.w);
  }
}

TEST(PanelLayout, OuterEdgesSnapBack) {
  const PanelLayout layout;
  const PanelRects r = place_panels(layout, 1600, 900, kTop, 1.f, false);
  PanelRect dragged = r.scene;
  dragged.x -= 20.f, dragged.w += 20.f;  // the window's left border
  EXPECT_EQ(resized(layout, Panel::scene, r, dragged, 1.f, false), layout);
}

TEST(PanelLayout, SizesScaleWithTheInterface) {
  const PanelRects one = place_panels(PanelLayout{}, 3840, 2160, kTop, 1.f, false);
  const PanelRects two = place_panels(PanelLayout{}, 3840, 2160, kTop, 2.f, false);
  EXPECT_FLOAT_EQ(two.scene.w, 2.f * one.scene.w);
  EXPECT_FLOAT_EQ(two.properties.w, 2.f * one.properties.w);
}

TEST(UiSettings, RoundTripAndDamagedFiles) {
  const auto dir = std::filesystem::temp_directory_path() / "inkray_ui_settings_test";
  std::filesystem::remove_all(dir);
  const auto file = dir / "editor.txt";
  std::vector<std::string> problems;
  EXPECT_EQ(read_ui_settings(file, &problems), UiSettings{});  // missing: defaults, no complaint
  EXPECT_TRUE(problems.empty());

  UiSettings s;
  s.ui_scale = 1.5f;
  s.layout.scene_width = 333.f;
  s.layout.node_split = 0.55f;
  std::string error;
  ASSERT_TRUE(write_ui_settings(file, s, &error)) << error;
  EXPECT_EQ(read_ui_settings(file, &problems), s);
  EXPECT_TRUE(problems.empty());

  std::ofstream(file) << "ui_scale 40\nscene_width banana\ncolour red\nproperties_width 1e30\n";
  const UiSettings damaged = read_ui_settings(file, &problems);
  EXPECT_EQ(damaged.ui_scale, kMaxUiScale);
  EXPECT_EQ(damaged.layout.scene_width, PanelLayout{}.scene_width);
  EXPECT_LE(damaged.layout.properties_width, 2000.f);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("editor.txt:2"), std::string::npos) << problems[0];
  EXPECT_NE(problems[0].find("scene_width"), std::string::npos) << problems[0];
  EXPECT_NE(problems[1].find("unknown setting \"colour\""), std::string::npos) << problems[1];
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace inkray
