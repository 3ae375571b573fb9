// The editor's edits that go beyond setting one value (a locked uniform scale, a new
// mix's inputs) and the check that refuses an edit which would break the scene, as pure
// functions over the document so they are tested without a window.
#pragma once

#include "core/document/desc.h"

#include <string>
#include <vector>

namespace inkray {

// The scale after one component of a locked (uniform) scale was edited: all three
// multiplied by that component's ratio. `before` itself when the edit cannot scale
// proportionally (a zero component before or after).
Vec3 locked_scale(const Vec3& before, const Vec3& edited);

// A material that has just become a mix gets inputs that keep the scene valid: two
// other materials that are not mixes (so no cycle), new diffuse ones when there are
// not enough. Inputs already naming such a material stay.
void give_mix_inputs(SceneDesc& scene, size_t material);

// What the editor checks before committing an edit: the problems a scene file would
// be read with (check_scene, plus required names left empty), as full lines.
std::vector<std::string> scene_problems(const SceneDesc& scene);
// The problems `after` has that `before` had not: an edit that adds any would make
// the scene unrenderable.
std::vector<std::string> problems_added(const SceneDesc& before, const SceneDesc& after);

}  // namespace inkray
