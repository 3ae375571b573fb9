// The scene graph panel: camera, render settings, environment, outlines, and
// lists of objects, lights, materials and stroke emitters, with add, duplicate,
// delete, rename and hide. Every change is a document edit.
#pragma once

#include "ui/model/editor_state.h"

namespace inkray {

void draw_scene_graph_panel(EditorState& state);

}  // namespace inkray
