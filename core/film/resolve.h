// The film's final image: mean radiance, then the painterly pixel filter, then
// the outline colours composited over it. Colour, opacity and filter settings
// are read here, not while tracing, so editing them needs no re-render.
#pragma once

#include "core/base/cancel.h"
#include "core/base/parallel.h"
#include "core/film/film.h"
#include "core/world/render_scene.h"

namespace inkray {

// The filter's rows run within `pool`'s threads when given, else in the caller's
// arena; the result is the same either way. The settings may differ from those the film was rendered with:
// that is how a line colour or filter edit shows without a re-render. When
// `cancel` cuts the painterly filter short, the result is an empty image.
RgbImage resolve_final(const Film& film, const RenderSettings& settings, const OutlineDesc& outlines,
                       ThreadBudget* pool = nullptr, const Cancel& cancel = {});
// Seconds the painterly filter will take on a width x height image, timed on a
// 64 x 64 crop and scaled by the pixel count; 0 without a filter. A final render
// with a time limit stops early enough to leave it this time.
double estimate_painterly_seconds(const RenderSettings& settings, int width, int height, ThreadBudget* pool = nullptr);

inline RgbImage resolve_final(const Film& film, const RenderScene& scene, ThreadBudget* pool = nullptr,
                              const Cancel& cancel = {}) {
  return resolve_final(film, scene.settings, scene.outlines, pool, cancel);
}

}  // namespace inkray
