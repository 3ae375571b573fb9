// The Line sets panel's logic without a window: a line set is an item like the
// others (its key paths, its tracks following a rename, a copy or a delete), new sets
// take a preset's style under a unique name, sets move in the drawing order, a row's
// summary says what a set selects, and each preset's swatch strokes differ as the
// styles do.
#include "core/document/animation.h"
#include "ui/model/document.h"
#include "ui/model/line_set_edits.h"
#include "ui/model/line_set_summary.h"
#include "ui/model/line_style_sample.h"
#include "ui/model/scene_edits.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace inkray {
namespace {

std::vector<std::string> set_names(const SceneDesc& s) {
  std::vector<std::string> names;
  for (const LineSetDesc& set : s.outlines.sets) names.push_back(set.name);
  return names;
}

TEST(LineSetEdits, NewSetsTakeThePresetUnderAUniqueName) {
  SceneDesc s = Document::default_scene();
  const Selection first = add_line_set(s, "ink");
  const Selection second = add_line_set(s, "ink");
  EXPECT_EQ(first, (Selection{ItemKind::line_set, 0}));
  EXPECT_EQ(second, (Selection{ItemKind::line_set, 1}));
  EXPECT_EQ(set_names(s), (std::vector<std::string>{"ink", "ink.1"}));
  LineSetStyleDesc ink;
  ParamPresets<LineSetStyleDesc>::apply("ink", ink);
  EXPECT_EQ(s.outlines.sets[1].style, ink);
  EXPECT_EQ(item_name(s, second), "ink.1");
  EXPECT_FALSE(is_valid(s, {ItemKind::line_set, 2}));
}

TEST(LineSetEdits, MoveChangesTheDrawingOrderWithinTheList) {
  SceneDesc s = Document::default_scene();
  for (const char* preset : {"ink", "pencil", "technical"}) add_line_set(s, preset);
  Selection moved;
  ASSERT_TRUE(move_line_set(s, {ItemKind::line_set, 2}, -1, &moved));
  EXPECT_EQ(moved, (Selection{ItemKind::line_set, 1}));
  EXPECT_EQ(set_names(s), (std::vector<std::string>{"ink", "technical", "pencil"}));
  EXPECT_FALSE(move_line_set(s, {ItemKind::line_set, 0}, -1, &moved));
  EXPECT_FALSE(move_line_set(s, {ItemKind::line_set, 2}, 1, &moved));
  EXPECT_FALSE(move_line_set(s, {ItemKind::object, 0}, 1, &moved));
  EXPECT_EQ(set_names(s), (std::vector<std::string>{"ink", "technical", "pencil"}));
}

TEST(LineSetEdits, TracksFollowTheSetsName) {
  SceneDesc s = Document::default_scene();
  add_line_set(s, "ink");
  const Selection ink{ItemKind::line_set, 0};
  EXPECT_EQ(key_path(s, ink), "outlines/sets/ink/");
  EXPECT_EQ(key_path(s, ink, "style.width"), "outlines/sets/ink/style/width");
  ASSERT_TRUE(insert_key(s, "outlines/sets/ink/style/width", 1));

  const Selection copy = duplicate_item(s, ink);
  EXPECT_EQ(copy, (Selection{ItemKind::line_set, 1}));
  EXPECT_EQ(set_names(s), (std::vector<std::string>{"ink", "ink.1"}));
  ASSERT_NE(find_track(s, "outlines/sets/ink.1/style/width"), nullptr);

  // A dotted name is one step of the path: the name is never split.
  ASSERT_TRUE(rename_item(s, copy, "ink.copy"));
  EXPECT_NE(find_track(s, "outlines/sets/ink.copy/style/width"), nullptr);
  EXPECT_EQ(find_track(s, "outlines/sets/ink.1/style/width"), nullptr);
  EXPECT_TRUE(check_animation(s).empty());
  EXPECT_FALSE(rename_item(s, copy, "ink"));  // taken

  ASSERT_TRUE(delete_item(s, ink));
  EXPECT_EQ(find_track(s, "outlines/sets/ink/style/width"), nullptr);
  EXPECT_NE(find_track(s, "outlines/sets/ink.copy/style/width"), nullptr);
  EXPECT_EQ(set_names(s), std::vector<std::string>{"ink.copy"});
}

TEST(LineSetSummary, NamesWhatDiffersFromTakingEverything) {
  LineSetDesc set;
  EXPECT_EQ(line_set_summary(set), "all lines");
  set.visibility = LineVisibility::hidden;
  EXPECT_EQ(line_set_summary(set), "all types; hidden");
  set = {};
  set.types = {true, false, false, true, false, false};
  set.paths.direct = set.paths.refracted = false;
  set.objects = "bolt*, nut";
  EXPECT_EQ(line_set_summary(set), "silhouette, crease; in mirrors; objects bolt*, nut");
  set = {};
  set.types = {false, false, false, false, false, false};
  set.visibility = LineVisibility::both;
  set.materials = "glass";
  EXPECT_EQ(line_set_summary(set), "no line types; visible and hidden; materials glass");
}

// The widest half width of a preset's sample strokes, and how many strokes it makes.
struct Sampled {
  float widest = 0.f, narrowest_end = 1e9f;
  size_t strokes = 0;
};

Sampled sampled(std::string_view preset) {
  LineSetStyleDesc style;
  ParamPresets<LineSetStyleDesc>::apply(preset, style);
  const std::vector<LineStroke> strokes = sample_strokes(style, 90.f, 36.f, 1.5f);
  Sampled out;
  out.strokes = strokes.size();
  for (const LineStroke& stroke : strokes) {
    for (const StrokeSample& s : stroke.samples) out.widest = std::max(out.widest, s.half_width);
    if (!stroke.samples.empty())
      out.narrowest_end = std::min(out.narrowest_end, stroke.samples.front().half_width);
  }
  return out;
}

TEST(LineStyleSample, PresetsDrawTheirOwnStrokes) {
  const Sampled ink = sampled("ink"), pencil = sampled("pencil"), brush = sampled("brush"),
                sketch = sampled("sketch"), technical = sampled("technical"),
                hidden = sampled("technical_hidden");
  // Ink: one stroke, 3 px at 1080 lines drawn at 1.5 swatch pixels each, tapered to a point.
  EXPECT_EQ(ink.strokes, 1u);
  EXPECT_NEAR(ink.widest, 0.5f * 3.f * 1.5f, 0.01f);
  EXPECT_LT(ink.narrowest_end, 0.2f * ink.widest);
  // Pencil and sketch go over the line two and three times; the brush is the widest.
  EXPECT_EQ(pencil.strokes, 2u);
  EXPECT_EQ(sketch.strokes, 3u);
  EXPECT_GT(brush.widest, ink.widest);
  // Technical: even, one stroke; its hidden variant is cut into dashes.
  EXPECT_EQ(technical.strokes, 1u);
  EXPECT_NEAR(technical.narrowest_end, technical.widest, 1e-4f);
  EXPECT_GT(hidden.strokes, 4u);
  // Every stroke lies in the box.
  LineSetStyleDesc sketchy;
  ParamPresets<LineSetStyleDesc>::apply("sketch", sketchy);
  for (const LineStroke& stroke : sample_strokes(sketchy, 90.f, 36.f, 1.5f))
    for (const StrokeSample& s : stroke.samples) {
      EXPECT_GE(s.p.x, 0.f);
      EXPECT_LE(s.p.x, 90.f);
      EXPECT_GE(s.p.y, 0.f);
      EXPECT_LE(s.p.y, 36.f);
    }
}

}  // namespace
}  // namespace inkray
