// What keyable fields asked for this frame (param_widgets.h, KeyTargets), turned into
// document edits: I keys the field under the mouse (or, over the panel, the focused one)
// at the current frame, Alt+I deletes its key there, and the fields' right-click menus
// insert, delete or clear (docs/architecture.md, "Timeline and keys"). Every panel with
// keyable fields calls it once, inside its window, after drawing them.
#pragma once

#include "ui/model/editor_state.h"
#include "ui/widgets/param_widgets.h"

namespace inkray {

void apply_key_actions(EditorState& state, KeyTargets& keys);

}  // namespace inkray
