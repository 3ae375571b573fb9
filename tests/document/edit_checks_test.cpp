// An edit that keeps every name is checked on the items it changed (CheckScope,
// docs/architecture.md "Checks of an edit"): over every shipped scene and edits that
// break and mend each kind of item, what problems_added finds that way is exactly
// what checking both whole documents finds.
#include "core/document/edit_checks.h"
#include "core/document/json_io.h"
#include "core/document/scene_checks.h"
#include "tests/support/breaking_edits.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

namespace inkray {
namespace {

namespace fs = std::filesystem;
using namespace inkray::testing;

// problems_added as it would be with every item checked.
std::vector<std::string> added_by_whole_checks(const SceneDesc& before, const SceneDesc& after) {
  std::unordered_map<std::string, int> known;
  for (std::string& p : scene_problems(before)) ++known[std::move(p)];
  std::vector<std::string> added;
  for (std::string& p : scene_problems(after))
    if (known[p] > 0)
      --known[p];
    else
      added.push_back(std::move(p));
  return added;
}

std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(ScopedChecks, FindWhatWholeChecksFindOverEveryScene) {
  int compared = 0, refused = 0;
  for (const fs::path& file : shipped_scenes()) {
    SceneLoadResult loaded = load_scene(file, ReadFor::editing);
    ASSERT_TRUE(loaded.scene) << file;
    const SceneDesc& original = *loaded.scene;
    for (const NamedEdit& edit : breaking_edits(original)) {
      SceneDesc broken = original;
      edit.apply(broken);
      ASSERT_TRUE(same_names(original, broken)) << file << ": " << edit.what;
      const std::string what = file.filename().string() + ": " + edit.what;
      // Breaking, then mending (the reverse edit adds nothing to the broken document).
      EXPECT_EQ(sorted(problems_added(original, broken)), sorted(added_by_whole_checks(original, broken)))
          << what;
      EXPECT_EQ(sorted(problems_added(broken, original)), sorted(added_by_whole_checks(broken, original)))
          << what;
      // A second edit on the broken document: the problem stays, nothing is added twice.
      SceneDesc again = broken;
      again.camera.vfov += 1.f;
      EXPECT_EQ(sorted(problems_added(broken, again)), sorted(added_by_whole_checks(broken, again))) << what;
      refused += !problems_added(original, broken).empty();
      ++compared;
    }
  }
  EXPECT_GT(compared, 300);
  EXPECT_GT(refused, 200) << "the edits should break the scenes they are made on";
}

TEST(ScopedChecks, ChangedItemsAreThoseThatDiffer) {
  SceneDesc a;
  a.materials = {{"m", DiffuseDesc{}, {}}, {"n", DiffuseDesc{}, {}}};
  ObjectDesc o;
  o.name = "o";
  o.material = "m";
  a.objects = {o, o};
  a.objects[1].name = "p";
  SceneDesc b = a;
  EXPECT_TRUE(changed_items(a, b).empty());
  b.objects[1].transform.translate.x = 1.f;
  const CheckScope scope = changed_items(a, b);
  EXPECT_FALSE(scope.empty());
  EXPECT_EQ(scope.objects, (std::vector<bool>{false, true}));
  EXPECT_EQ(scope.materials, (std::vector<bool>{false, false}));
  b.objects[0].name = "renamed";
  EXPECT_FALSE(same_names(a, b)) << "a rename is checked on the whole document";
}

}  // namespace
}  // namespace inkray
