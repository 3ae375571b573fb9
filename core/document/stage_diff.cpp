#include "core/document/stage_diff.h"

namespace inkray {
namespace {

// Lists compare item by item, but for the items a copy still shares; a list that grew
// or shrank is its section's stage.
template <class T, class Compare>
void diff_list(const SharedList<T>& before, const SharedList<T>& after, Stage section, StageSet& out,
               Compare compare) {
  if (before.size() != after.size()) out.add(section);
  const size_t n = std::min(before.size(), after.size());
  for (size_t i = 0; i < n; ++i)
    if (!after.shares(before, i)) out.add(compare(before[i], after[i]));
}

StageSet material_changes(const MaterialDesc& before, const MaterialDesc& after) {
  StageSet out;
  if (before.name != after.name) out.add(Stage::material);
  out.add(changed_stages(before.data, after.data, Stage::material));
  out.add(changed_stages(before.lines, after.lines, Stage::material));
  return out;
}

StageSet light_changes(const LightDesc& before, const LightDesc& after) {
  StageSet out;
  if (before.name != after.name) out.add(Stage::light);
  out.add(changed_stages(before.data, after.data, Stage::light));
  return out;
}

}  // namespace

StageSet changed_stages(const ObjectDesc& before, const ObjectDesc& after) {
  StageSet out = changed_stages<ObjectDesc>(before, after, Stage::object);
  out.add(changed_stages(before.shape, after.shape, Stage::geometry));
  if (!(before.transform == after.transform)) out.add(Stage::object);
  return out;
}

StageSet changed_stages(const SceneDesc& before, const SceneDesc& after) {
  StageSet out;
  // Relative asset paths resolve against the folder: every file may be another.
  if (before.base_dir != after.base_dir) {
    out.add(Stage::geometry);
    out.add(Stage::material);
    out.add(Stage::strokes);
  }
  out.add(changed_stages(before.camera, after.camera, Stage::camera));
  out.add(changed_stages(before.render, after.render, Stage::sampling));
  out.add(changed_stages(before.outlines, after.outlines, Stage::sampling));
  // A film keeps the surfaces chains are labelled with only while there are line
  // sets (film_chains.h): the first set, or the last one gone, starts a new film.
  if (before.outlines.sets.empty() != after.outlines.sets.empty()) out.add(Stage::sampling);
  out.add(changed_stages(before.environment, after.environment, Stage::light));
  diff_list(before.materials, after.materials, Stage::material, out, material_changes);
  diff_list(before.objects, after.objects, Stage::object, out,
            [](const ObjectDesc& a, const ObjectDesc& b) { return changed_stages(a, b); });
  diff_list(before.lights, after.lights, Stage::light, out, light_changes);
  diff_list(before.strokes, after.strokes, Stage::strokes, out,
            [](const auto& a, const auto& b) { return changed_stages(a, b, Stage::strokes); });
  return out;
}

}  // namespace inkray
