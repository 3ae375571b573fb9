// Test mode: named widgets report where they were drawn, so screenshot tests can
// check that every control is reachable at every window size (docs/architecture.md,
// "Testing the editor"). Off unless enabled; then each call records ImGui's last item
// rectangle and the visible rectangle of the window it sits in.
#pragma once

#include <string>
#include <string_view>

namespace inkray::widget_report {

void enable(bool on);
bool enabled();
// Call at the start of every frame: the report holds the last frame's widgets only.
void begin_frame();
// Records the last ImGui item under `name` (unique within a frame; a repeat replaces it).
void item(std::string_view name);
// One line per widget: "name x0 y0 x1 y1 visible_x0 visible_y0 visible_x1 visible_y1",
// window pixels, the visible rectangle being the window's inner clip rectangle.
std::string text();

}  // namespace inkray::widget_report
