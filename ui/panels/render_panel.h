// Render settings and export: the document's resolution, samples and depth, the
// viewport's limits (samples, time, noise target), and "Export..." (the dialog is
// ui/panels/export_dialog.h) with the export queue's status. Columns stack when narrow.
#pragma once

#include "ui/model/editor_state.h"

namespace inkray {

void draw_render_panel(EditorState& state, const ProgressiveRenderer& renderer);

}  // namespace inkray
