// Edits of the document's line sets (outlines.sets) that the generic item edits of
// scene_edits.h do not cover: a new set in a preset's style, and a set moved in the
// drawing order (later sets are drawn on top). Pure functions, like scene_edits.h;
// duplicating, deleting and renaming a set are scene_edits.h's, which carry its tracks.
#pragma once

#include "ui/model/selection.h"

#include <string_view>

namespace inkray {

// A set taking every line, in the style `preset` names (ParamPresets<LineSetStyleDesc>),
// named after it ("ink", "ink.1", ...) and drawn last. Returns its selection.
Selection add_line_set(SceneDesc& scene, std::string_view preset);

// Moves the set `offset` places in the drawing order (-1: drawn earlier); false when
// that would leave the list. The selection it has afterwards in *moved.
bool move_line_set(SceneDesc& scene, const Selection& set, int offset, Selection* moved);

}  // namespace inkray
