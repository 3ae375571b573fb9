// The toon closure's settings as one block (docs/architecture.md, "Parameter tables"):
// the document's ToonDesc and the compiled ToonMaterial both derive from it, so a
// setting is declared once, with one default, and compiling a toon material copies the
// block whole. The lit colour and the ramps are not here: the document holds them as a
// colour input and files, the compiled material as a texture and images.
#pragma once

#include "core/math/types.h"

namespace inkray {

// Second axis of a 2D ramp image (X-toon, Barla et al. 2006).
enum class ToonRampAxis { none, depth, facing };

struct ToonParams {
  Color shadow_color{0.25f};  // multiplies the lit colour in the darkest band
  int bands = 2;              // 2 = a single cel threshold
  float threshold = 0.5f;     // cel threshold on normalised light (first band edge)
  float softness = 0.02f;     // width of the transition between bands
  ToonRampAxis ramp_axis = ToonRampAxis::none;
  float ramp_near = 1.f, ramp_far = 20.f;  // depth range mapped to v for ramp_axis depth
  bool specular = true;
  Color specular_color{1.f};
  float specular_size = 0.1f;  // Blinn-Phong threshold: larger is a bigger highlight
  float shininess = 40.f;
  bool rim = false;
  Color rim_color{1.f};
  float rim_width = 0.3f;  // facing-ratio band width
  float rim_threshold = 0.5f;
  float environment = 0.25f;         // the sky counts as a light of this fraction of its strength
  bool environment_shadows = false;  // the sky is shadowed (one more shadow ray per sample)
  bool receive_indirect = false;     // add indirect light (bands stay on direct light)
  bool bounce_indirect = true;       // other surfaces see it as diffuse
  bool operator==(const ToonParams&) const = default;
};

}  // namespace inkray
