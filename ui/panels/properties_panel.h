// The properties panel: the selected item's parameters, drawn from its
// parameter list. Every change becomes a document edit whose merge key names
// the item and parameter, so one slider drag is one undo step.
#pragma once

#include "ui/model/editor_state.h"

namespace inkray {

void draw_properties_panel(EditorState& state);

}  // namespace inkray
