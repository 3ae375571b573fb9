// The denoiser: a film's mean radiance with its noise filtered away, guided by the
// first-hit features and choosing its filter per pixel from the two half-buffers
// (docs/architecture.md, "Denoising"). Lines are not in its input: they are
// composited over its output (resolve.h), so they are never blurred.
#pragma once

#include "core/base/cancel.h"
#include "core/base/parallel.h"
#include "core/film/film.h"

namespace inkray {

// The features the denoiser reads: a render that will be denoised keeps these.
AovSet denoise_aovs();

struct Denoised {
  RgbImage image;  // mean radiance, denoised; empty when cancelled
  // Estimated relative RMS error of `image`, over luminance as Film::estimated_relative_error:
  // each half denoised alone and checked against the other (bias included), then
  // scaled to the two halves together. 0 before both halves have samples.
  double relative_error = 0.0;
  // Share of pixels per filter scale chosen (0: the raw mean), for the docs and tests.
  std::vector<double> scale_share;
};

// Denoises `film`. Features the film does not keep are left out of the guide (a film
// without ids may blur across them). Rows run within `pool` when given, else in the
// caller's arena; the result is the same either way.
Denoised denoise(const Film& film, ThreadBudget* pool = nullptr, const Cancel& cancel = {});

// About how long denoise() takes on a width x height film on `pool`, measured on this
// machine by denoising a small noisy film and scaled by the pixel count: what a render
// with a time limit keeps back for it (docs/final-renders.md, "Time limits").
double estimate_denoise_seconds(int width, int height, ThreadBudget* pool = nullptr);

}  // namespace inkray
