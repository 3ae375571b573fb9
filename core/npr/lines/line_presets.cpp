// Named line styles. Lengths are pixels at 1080 lines, like every LineStyle's.
#include "core/npr/lines/line_presets.h"

namespace inkray {

LineStyle line_preset(std::string_view name) {
  LineStyle s;  // black, opaque, 2 px, even and unbroken
  if (name == "ink") {
    s.width = 3.f, s.taper_start = 0.15f, s.taper_end = 0.2f;
  } else if (name == "pencil") {
    // Every style's opacity follows the chain's coverage (stroke_chains), so a
    // pencil's faint lines stay faint without a modulation of their own.
    s.color = s.color_end = Color(0.25f);
    s.opacity = 0.8f, s.width = 1.2f;
    s.taper_start = s.taper_end = 0.05f;
    s.jitter = 0.6f, s.jitter_scale = 40.f, s.passes = 2;
  } else if (name == "brush") {  // the compiler attaches the bristle brush
    s.width = 5.f, s.taper_start = 0.2f, s.taper_end = 0.35f;
  } else if (name == "sketch") {
    s.color = s.color_end = Color(0.08f);
    s.opacity = 0.6f, s.width = 1.f, s.overshoot = 6.f;
    s.taper_start = s.taper_end = 0.1f;
    s.jitter = 1.5f, s.jitter_scale = 30.f, s.passes = 3;
    s.corner_angle = 120.f;  // corners drawn as two lines crossing
  } else if (name == "technical" || name == "technical_hidden") {
    s.width = 1.5f;
    if (name == "technical_hidden") s.dash = 6.f, s.gap = 4.f;
  } else {
    return {};
  }
  return s;
}

}  // namespace inkray
