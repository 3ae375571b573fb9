#include "ui/model/line_set_edits.h"

#include "ui/model/scene_edits.h"

#include <utility>

namespace inkray {

Selection add_line_set(SceneDesc& scene, std::string_view preset) {
  LineSetDesc set;
  set.name = unique_name(scene, ItemKind::line_set, preset);
  ParamPresets<LineSetStyleDesc>::apply(preset, set.style);
  scene.outlines.sets.push_back(std::move(set));
  return {ItemKind::line_set, int(scene.outlines.sets.size()) - 1};
}

bool move_line_set(SceneDesc& scene, const Selection& set, int offset, Selection* moved) {
  if (set.kind != ItemKind::line_set || !is_valid(scene, set)) return false;
  const int to = set.index + offset;
  if (to < 0 || to >= int(scene.outlines.sets.size())) return false;
  std::vector<LineSetDesc>& sets = scene.outlines.sets;
  LineSetDesc moving = std::move(sets[size_t(set.index)]);
  sets.erase(sets.begin() + set.index);
  sets.insert(sets.begin() + to, std::move(moving));
  *moved = {ItemKind::line_set, to};
  return true;
}

}  // namespace inkray
