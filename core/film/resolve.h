// The film's final image: mean radiance, then the painterly pixel filter, then
// the outline colours composited over it. Colour, opacity and filter settings
// are read here, not while tracing, so editing them needs no re-render.
#pragma once

#include "core/film/film.h"
#include "core/render/thread_pool.h"
#include "core/scene/render_scene.h"

namespace inkray {

// `pool` runs the filter's rows in parallel when given; the result is the same
// without it. The settings may differ from those the film was rendered with:
// that is how a line colour or filter edit shows without a re-render.
RgbImage resolve_final(const Film& film, const RenderSettings& settings, const OutlineDesc& outlines,
                       ThreadPool* pool = nullptr);
inline RgbImage resolve_final(const Film& film, const RenderScene& scene, ThreadPool* pool = nullptr) {
  return resolve_final(film, scene.settings, scene.outlines, pool);
}

}  // namespace inkray
