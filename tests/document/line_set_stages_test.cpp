// Line sets are the resolve stage: a style or selection edit redraws over the samples
// taken; only the first set (or the last one gone) starts a new film, which then keeps
// the surfaces chains are labelled with.
#include "core/document/animation.h"
#include "core/document/stage_diff.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

SceneDesc with_one_set() {
  SceneDesc d;
  d.outlines.enabled = true;
  LineSetDesc ink;
  ink.name = "ink";
  d.outlines.sets.push_back(ink);
  return d;
}

TEST(LineSetStages, StyleAndSelectionEditsAreTheResolveStage) {
  const SceneDesc before = with_one_set();
  SceneDesc after = before;
  after.outlines.sets[0].style.width = 5.f;
  after.outlines.sets[0].style.dash = 4.f;
  after.outlines.sets[0].types.crease = false;
  after.outlines.sets[0].objects = "bolt*";
  EXPECT_EQ(changed_stages(before, after).names(), "resolve");
  after.outlines.sets.push_back(after.outlines.sets[0]);
  after.outlines.sets[1].name = "second";
  EXPECT_EQ(changed_stages(before, after).names(), "resolve");
}

TEST(LineSetStages, TheFirstSetAndTheLastOneGoneStartANewFilm) {
  SceneDesc plain;
  plain.outlines.enabled = true;
  EXPECT_TRUE(changed_stages(plain, with_one_set()).has(Stage::sampling));
  EXPECT_TRUE(changed_stages(with_one_set(), plain).has(Stage::sampling));
}

// A set's fields are keyable by the set's name, as an object's are by its.
TEST(LineSetStages, SetFieldsAreKeyedByTheSetsName) {
  SceneDesc d = with_one_set();
  d.outlines.sets[0].style.width = 3.f;
  std::vector<double> value;
  ASSERT_TRUE(read_target(d, "outlines/sets/ink/style/width", &value));
  EXPECT_EQ(value, std::vector<double>{3.0});
  EXPECT_FALSE(read_target(d, "outlines/sets/pencil/style/width", &value));
  TrackDesc track;
  track.target = "outlines/sets/ink/style/width";
  track.keys = {KeyDesc{1.0, {1.0}, Interpolation::linear}, KeyDesc{11.0, {11.0}, Interpolation::linear}};
  d.animation.push_back(track);
  EXPECT_TRUE(check_animation(d).empty());
  apply_animation(d, 6.0);
  EXPECT_NEAR(d.outlines.sets[0].style.width, 6.f, 1e-4f);
}

}  // namespace
}  // namespace inkray
