// Line sets are the resolve stage: a style or selection edit redraws over the samples
// taken; only the first set (or the last one gone) starts a new film, which then keeps
// the surfaces chains are labelled with.
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

}  // namespace
}  // namespace inkray
