// The Line sets panel (the right column's second tab; docs/outlines.md, "Line sets and
// styles"): the document's line sets in drawing order, each row with its enabled
// switch, a swatch of its style and what it selects, and buttons to add (in the ink
// style), duplicate, delete and reorder them; below, the chosen set's selection and
// style through the generated widgets, with the style's Preset menu. Its edits take
// the properties panel's path (param_panel.h): one undo step each, keys by I and Alt+I
// on outlines/sets/NAME/..., and a style's edit redraws the lines over the samples taken.
#pragma once

#include "ui/model/editor_state.h"

namespace inkray {

void draw_line_sets_panel(EditorState& state);

}  // namespace inkray
