// Named line styles (ParamPresets<LineSetStyleDesc>, line_set_desc.h). Lengths are
// pixels at 1080 lines; a preset replaces the whole style, colours black unless said.
#include "core/document/line_set_desc.h"

namespace inkray {

void ParamPresets<LineSetStyleDesc>::apply(std::string_view name, LineSetStyleDesc& s) {
  s = LineSetStyleDesc{};
  if (name == "ink") {
    s.width = 3.f, s.taper_start = 0.15f, s.taper_end = 0.2f;
  } else if (name == "pencil") {
    // A pencil's opacity follows the line's coverage anyway (every style's does),
    // so faint lines stay faint without a modulation of their own.
    s.color = s.color_end = Color(0.25f);
    s.opacity = 0.8f, s.width = 1.2f, s.taper_start = s.taper_end = 0.05f;
    s.jitter = 0.6f, s.jitter_scale = 40.f, s.passes = 2;
  } else if (name == "brush") {
    s.width = 5.f, s.taper_start = 0.2f, s.taper_end = 0.35f;
    s.brush = LineBrush::bristle, s.brush_repeat = 160.f;
  } else if (name == "sketch") {
    s.color = s.color_end = Color(0.08f);
    s.opacity = 0.6f, s.width = 1.f, s.taper_start = s.taper_end = 0.1f;
    s.jitter = 1.5f, s.jitter_scale = 30.f, s.overshoot = 6.f, s.passes = 3;
    s.corner_angle = 120.f;  // corners drawn as two lines crossing
  } else if (name == "technical") {
    s.width = 1.5f;
  } else if (name == "technical_hidden") {
    s.width = 1.5f, s.dash = 6.f, s.gap = 4.f;
  }
}

}  // namespace inkray
