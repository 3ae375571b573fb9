// Render settings and export: the document's resolution, samples and depth,
// the viewport's limits (samples, time, noise target), and "Export render..."
// which renders the current document in the background to PNG/EXR with AOVs.
#pragma once

#include "ui/editor_state.h"

namespace inkray {

void draw_render_panel(EditorState& state, const ProgressiveRenderer& renderer);

}  // namespace inkray
