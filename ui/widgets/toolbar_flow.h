// Toolbars that wrap instead of being cut off: widgets laid out left to right, a new
// line started where the next one would be clipped, each measured before it is drawn
// (the viewport's toolbar, the Line sets panel's buttons).
#pragma once

namespace inkray {

class ToolbarFlow {
 public:
  // Before drawing a widget `width` pixels wide: on the same line as the last one if it fits.
  void next(float width);

 private:
  bool started_ = false;
};

// Widths of common widgets with `label`, as ImGui will draw them ("##" hides the rest).
float text_width(const char* label);
float button_width(const char* label);
float labelled_width(float item, const char* label);
float checkbox_width(const char* label);

}  // namespace inkray
