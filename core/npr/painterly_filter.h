// Painterly pixel filters over a resolved image: the generalized and the
// anisotropic Kuwahara filters, pure functions from image to image.
#pragma once

#include "core/base/cancel.h"
#include "core/base/parallel.h"
#include "core/image/rgb_image.h"

namespace inkray {

struct PainterlyFilterParams {
  float radius = 4.f;     // pixels (already scaled to the image by the caller); clamped to [0.5, 256]
  float sharpness = 8.f;  // sector weighting exponent q; 0 averages all sectors alike
  int sectors = 8;        // clamped to [1, 16]
};

// Both filters average linear RGB, but judge each sector's spread on a bounded
// copy (per channel Reinhard x/(1+x), then sRGB-encoded) so a bright light
// counts like white instead of deciding the weights everywhere near it. A
// sector's weight is 1 / (1 + sigma)^q, sigma the square root of the copy's
// variance summed over channels, in 8-bit code values (as in the papers'
// implementations, so q = 8 behaves as published). Samples beyond the border
// repeat the edge pixel. Non-finite input pixels are read as black, so they
// never spread. Rows run in parallel, within `pool`'s threads when one is
// given, else in the caller's arena; the result is bit-identical at any thread
// count. Once `cancel` is requested no further row is filtered (at large radii a
// filter takes seconds) and, if any row was left, the result is an empty image.

// Generalized Kuwahara (Papari, Petkov, Campisi 2007): N overlapping sectors
// of a disc with smooth weights.
RgbImage kuwahara_filter(const RgbImage& image, const PainterlyFilterParams& params,
                         ThreadBudget* pool = nullptr, const Cancel& cancel = {});

// Anisotropic Kuwahara (Kyprianidis, Kang, Döllner 2009): the disc becomes an
// ellipse stretched along the local flow of the smoothed structure tensor.
RgbImage anisotropic_kuwahara_filter(const RgbImage& image, const PainterlyFilterParams& params,
                                     ThreadBudget* pool = nullptr, const Cancel& cancel = {});

}  // namespace inkray
