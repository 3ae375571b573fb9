// What one edit of a large document copies, in bytes allocated: the editor's
// copy and check of the edited document, its undo step, the renderer's copy and
// the compiler's diff, file list, scoped checks and memory estimate (docs/architecture.md, "Documents shared
// by their copies"). Sections are shared item by item, so an edit pays for what
// it touches, not for the 20,000 objects around it.
#include "core/document/edit_checks.h"
#include "core/document/memory_budget.h"
#include "core/document/scene_checks.h"
#include "core/document/stage_diff.h"
#include "ui/model/document.h"
#include "ui/viewport/camera_controller.h"

#include "tests/support/allocation_counter.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace inkray {
namespace {

// As scripts/make_many_objects.py writes it: spheres in a grid sharing 64 materials.
SceneDesc many_objects(int objects, int materials) {
  SceneDesc s;
  s.camera.look_from = Point3(0.f, 7.f, 80.f);
  s.camera.look_at = Point3(0.f, 0.f, 30.f);
  s.outlines.enabled = true;
  for (int m = 0; m < materials; ++m) {
    const Color color(0.2f + 0.6f * float(m) / float(materials), 0.5f, 0.7f);
    if (m % 2) {
      s.materials.push_back({"m" + std::to_string(m), DiffuseDesc{color}, {}});
    } else {
      ToonDesc toon;
      toon.color = color;
      s.materials.push_back({"m" + std::to_string(m), toon, {}});
    }
  }
  const int side = 142;
  for (int k = 0; k < objects; ++k) {
    ObjectDesc o;
    o.name = "sphere_" + std::to_string(k);
    o.shape = SphereDesc{Point3(float(k % side) - 70.f, 0.4f, float(k / side) - 70.f), 0.4f};
    o.material = "m" + std::to_string(k % materials);
    s.objects.push_back(std::move(o));
  }
  LightDesc sun;
  sun.name = "sun";
  sun.data = DirectionalLightDesc{Vec3(-0.6f, -1.f, -0.45f), Color(1.f), 4.f};
  s.lights.push_back(sun);
  return s;
}

// The way of one slider or gizmo step from the editor to the compiler's input.
class EditPath {
 public:
  explicit EditPath(SceneDesc scene) : compiled_(scene) { doc_.reset(std::move(scene)); }

  // Bytes allocated while `change` is made to a copy of the document and carried through.
  size_t bytes(const std::function<void(SceneDesc&)>& change) {
    const testing::CountAllocations count;
    SceneDesc after = doc_.scene();
    change(after);
    EXPECT_TRUE(problems_added(doc_.scene(), after).empty());  // the properties panel's check
    doc_.edit(std::move(after), "drag", "drag");
    const SceneDesc submitted = doc_.scene();  // the renderer takes its own copy
    EXPECT_FALSE(changed_stages(compiled_, submitted).empty());
    EXPECT_TRUE(collect_assets(submitted).empty());
    EXPECT_TRUE(same_names(compiled_, submitted));
    const CheckScope scope = changed_items(compiled_, submitted);
    ErrorLog log("");
    check_scene(submitted, submitted.base_dir, log, &scope);
    EXPECT_TRUE(log.take().empty());
    std::vector<std::string> errors;
    check_memory_budget(submitted, 0, errors);
    EXPECT_TRUE(errors.empty());
    compiled_ = submitted;
    return count.bytes();
  }

 private:
  Document doc_;
  SceneDesc compiled_;  // what the compiler saw last
};

constexpr size_t kMostBytesPerEdit = 64 * 1024;

struct Edit {
  const char* name;
  std::function<void(SceneDesc&, int)> change;  // the drag's step-th change
};

const std::vector<Edit>& edits() {
  static const std::vector<Edit> list = {
      {"material colour",
       [](SceneDesc& s, int step) {
         std::get<ToonDesc>(s.materials[10].data).color = Color(0.01f * float(step));
       }},
      {"object move",
       [](SceneDesc& s, int step) {
         s.objects[12345].transform.translate = Vec3(0.01f * float(step), 0.f, 0.f);
       }},
      {"camera orbit", [](SceneDesc& s, int) { s.camera = orbit(s.camera, 0.02f, 0.f); }},
      {"light intensity",
       [](SceneDesc& s, int step) {
         std::get<DirectionalLightDesc>(s.lights[0].data).intensity = float(step);
       }},
      {"line colour",
       [](SceneDesc& s, int step) { s.outlines.silhouette.color = Color(0.01f * float(step)); }},
  };
  return list;
}

TEST(EditCopies, AnEditOf20000ObjectsCopiesAtMost64KiB) {
  EditPath path(many_objects(20000, 64));
  for (const Edit& edit : edits()) {
    // The first step of a drag opens its undo step; the later ones extend it.
    for (int step = 1; step <= 3; ++step) {
      const size_t bytes = path.bytes([&](SceneDesc& s) { edit.change(s, step); });
      EXPECT_LE(bytes, kMostBytesPerEdit) << edit.name << ", step " << step;
      if (step == 3) std::printf("%-16s %7zu bytes per edit\n", edit.name, bytes);
    }
  }
}

// The measure can fail: the same documents held as plain vectors cost megabytes a copy.
TEST(EditCopies, AWholeCopyIsSeenByTheCount) {
  const SceneDesc scene = many_objects(20000, 64);
  const std::vector<ObjectDesc> plain = scene.objects.to_vector();
  const testing::CountAllocations count;
  const std::vector<ObjectDesc> copy = plain;  // NOLINT(performance-unnecessary-copy-initialization)
  EXPECT_GE(count.bytes(), plain.size() * sizeof(ObjectDesc));
  EXPECT_GT(count.bytes(), 60 * kMostBytesPerEdit);
  EXPECT_EQ(copy.size(), plain.size());
}

}  // namespace
}  // namespace inkray
