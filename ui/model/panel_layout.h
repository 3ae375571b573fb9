// Where the editor's panels sit: the scene list on the left, the viewport in the middle
// with the timeline under it and the output tabs (or the node editor) below that, the
// properties on the right. The timeline has a fixed height; the others are resizable.
// Sizes are in points (pixels at UI scale 1), changed by dragging a panel's inner edge
// and remembered between runs (ui/model/ui_settings.h). Window-free, so the arithmetic is tested.
#pragma once

namespace inkray {

struct PanelRect {
  float x = 0, y = 0, w = 0, h = 0;
};

enum class Panel { scene, viewport, output, properties, node_editor, timeline };

// The timeline's height in points: its toolbar, the frame ruler and two rows of keys.
inline constexpr float kTimelineHeight = 100.f;

struct PanelLayout {
  float scene_width = 280.f;
  float properties_width = 380.f;
  float output_height = 250.f;
  float node_split = 0.4f;  // the viewport's share of the height while the node editor is open
  bool operator==(const PanelLayout&) const = default;
};

// The panels' rectangles in a window of the given pixel size below a menu bar `top`
// pixels high, at UI `scale`. Every panel keeps a usable minimum: when the window is
// too small for the stored sizes, the side panels and the bottom panel give way first.
struct PanelRects {
  PanelRect scene, viewport, output, properties, node_editor, timeline;
  const PanelRect& operator[](Panel p) const;
};
PanelRects place_panels(const PanelLayout& layout, float width, float height, float top, float scale,
                        bool node_editor_open);

// After the user dragged an edge of `panel` so that ImGui reports it at `dragged`, the
// layout that reproduces it. Only edges shared with another panel count; outer edges
// snap back.
PanelLayout resized(const PanelLayout& layout, Panel panel, const PanelRects& placed,
                    const PanelRect& dragged, float scale, bool node_editor_open);

// Keeps stored sizes sane (positive, finite, within generous bounds).
PanelLayout sanitized(PanelLayout layout);

}  // namespace inkray
