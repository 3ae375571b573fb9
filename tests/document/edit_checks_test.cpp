// An edit that keeps every name is checked on the items it changed (CheckScope,
// docs/architecture.md "Checks of an edit"): over every shipped scene and edits that
// break and mend each kind of item, what problems_added finds that way is exactly
// what checking both whole documents finds.
#include "core/document/edit_checks.h"
#include "core/document/json_io.h"
#include "core/document/scene_checks.h"

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

std::vector<fs::path> shipped_scenes() {
  std::vector<fs::path> files;
  for (const fs::path& dir : {fs::path(INKRAY_SOURCE_DIR) / "scenes",
                              fs::path(INKRAY_SOURCE_DIR) / "tests" / "data" / "scenes" / "valid"})
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

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

struct NamedEdit {
  std::string what;
  std::function<void(SceneDesc&)> apply;
};

// Edits that keep every name and each break one check of one item (or of the whole
// document), for the first few items of each list.
std::vector<NamedEdit> breaking_edits(const SceneDesc& scene) {
  std::vector<NamedEdit> edits;
  const size_t most = 12;
  for (size_t i = 0; i < std::min(scene.objects.size(), most); ++i) {
    edits.push_back({"objects[" + std::to_string(i) + "].material dangling",
                     [i](SceneDesc& s) { s.objects[i].material = "no such material"; }});
    edits.push_back({"objects[" + std::to_string(i) + "].material empty",
                     [i](SceneDesc& s) { s.objects[i].material.clear(); }});
    edits.push_back({"objects[" + std::to_string(i) + "] a missing mesh",
                     [i](SceneDesc& s) { s.objects[i].shape = MeshDesc{"no/such/mesh.obj"}; }});
    edits.push_back({"objects[" + std::to_string(i) + "] moved",
                     [i](SceneDesc& s) { s.objects[i].transform.translate += Vec3(0.5f, 0.f, 0.f); }});
  }
  for (size_t i = 0; i < std::min(scene.materials.size(), most); ++i) {
    edits.push_back({"materials[" + std::to_string(i) + "] a mix of itself", [i](SceneDesc& s) {
                       s.materials[i].data = MixDesc{s.materials[i].name, s.materials[i].name};
                     }});
    edits.push_back({"materials[" + std::to_string(i) + "] a mix of nothing", [i](SceneDesc& s) {
                       s.materials[i].data = MixDesc{"", "nothing"};
                     }});
    edits.push_back({"materials[" + std::to_string(i) + "] a missing texture", [i](SceneDesc& s) {
                       s.materials[i].data = DiffuseDesc{ImageTextureDesc{"no/such/image.png"}};
                     }});
  }
  for (size_t i = 0; i < std::min(scene.lights.size(), most); ++i) {
    edits.push_back({"lights[" + std::to_string(i) + "] a spot at its target", [i](SceneDesc& s) {
                       SpotLightDesc spot;
                       spot.target = spot.position;
                       s.lights[i].data = spot;
                     }});
  }
  for (size_t i = 0; i < std::min(scene.strokes.size(), most); ++i) {
    edits.push_back({"strokes[" + std::to_string(i) + "] on nothing",
                     [i](SceneDesc& s) { s.strokes[i].object = "nobody"; }});
    edits.push_back({"strokes[" + std::to_string(i) + "] widths crossed",
                     [i](SceneDesc& s) { s.strokes[i].width_min = s.strokes[i].width_max + 1.f; }});
    edits.push_back({"strokes[" + std::to_string(i) + "] an image brush with no image", [i](SceneDesc& s) {
                       s.strokes[i].brush = BrushKind::image;
                       s.strokes[i].brush_image.clear();
                     }});
  }
  edits.push_back({"camera looking at its eye", [](SceneDesc& s) { s.camera.look_at = s.camera.look_from; }});
  edits.push_back({"frames reversed", [](SceneDesc& s) { s.render.frame_end = s.render.frame_start - 1; }});
  return edits;
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
