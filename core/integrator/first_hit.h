// FirstHit: what the path tracer reports of a camera sample's first hit, for
// the film's AOVs. Its own header so the film (above the integrator) includes
// it, and the integrator needs nothing of the film.
#pragma once

#include "core/math/types.h"

namespace inkray {

// What the camera sample saw at its first hit.
struct FirstHit {
  // Of the first surface that is not a perfect mirror or clear glass along the camera's
  // specular chain: what a mirror or a pane shows, as the denoiser's guide needs.
  Color albedo{0.f};
  Normal3 normal{0.f};
  float depth = 0.f;  // distance along the camera's forward axis
  int object = -1;    // -1 where the sample escaped
  int material = -1;
  // A toon surface's hard features where the camera sees it directly or through
  // mirrors and glass: its quantised light level in [0, 1] (toon_band_level), plus 2
  // inside the specular band and 4 inside the rim. -1 elsewhere. The denoiser
  // never blurs across a change of it (docs/architecture.md, "Denoising").
  float band = -1.f;
};

}  // namespace inkray
