// The viewport's final image from its film, cached between snapshots: the film's
// image without lines (mean or denoised radiance, painterly filter), its lines, and
// the two composited for a display. Each is made again only when what it depends
// on changed (docs/architecture.md, "The viewport loop").
#pragma once

#include "core/base/cancel.h"
#include "core/base/parallel.h"
#include "core/film/film.h"
#include "core/film/resolve.h"
#include "core/image/view_transform.h"
#include "core/world/render_scene.h"

#include <chrono>
#include <cstdint>

namespace inkray {

// Why the cached image is stale.
enum class ResolveChange {
  new_samples,       // the film changed: everything is made again
  resolve_settings,  // an edit of the resolve stage: lines composited again, filtered again if the filter
                     // changed
  display,           // another exposure or view transform: lines composited again
  denoise_toggled,   // the base is made from the other radiance
};

// The film's place in its render, which decides when the denoiser runs again.
struct FilmProgress {
  uint64_t accumulation = 0;
  uint32_t spp = 0;
  bool finished = false;
};

class ViewportResolver {
 public:
  void invalidate(ResolveChange why);
  // The film's final image for `display`, denoised when asked; null when `cancel`
  // cut the denoiser or the filter short. Valid until the next call.
  const RgbImage* resolve(const Film& film, const RenderScene& scene, const DisplayEncoding& display,
                          bool denoise, const FilmProgress& progress, ThreadBudget& pool,
                          const Cancel& cancel);
  // Of the last denoised radiance: the film's samples then, and its estimated relative error.
  uint32_t denoised_spp() const { return denoised_.spp; }
  double denoised_error() const { return denoised_.error; }

 private:
  // The film's mean radiance as the final image starts from: denoised when asked.
  RgbImage final_radiance(const Film& film, bool denoise, const FilmProgress& progress, ThreadBudget& pool,
                          const Cancel& cancel);

  // What must be made again, least first: the lines composited, the base as well.
  enum class Stale { none, lines, base };
  Stale stale_ = Stale::base;
  // The film's image without lines (mean and painterly filter) and its lines,
  // and what the base was made with: an edit of lines only keeps it. Lines are
  // composited in display space, so a new exposure or view transform composites
  // them again over the same base (core/film/resolve.h), without filtering again.
  RgbImage base_;
  FilmLines lines_;
  ResolveSettings base_settings_;
  bool base_denoised_ = false;
  // The base with the lines composited for `resolved_for_` (empty without lines).
  RgbImage resolved_;
  DisplayEncoding resolved_for_;
  // The last denoised radiance, of accumulation `accumulation` at `spp`, and what
  // denoising it cost.
  struct DenoiseCache {
    RgbImage image;
    uint64_t accumulation = ~uint64_t(0);
    uint32_t spp = 0;
    double error = 0.0, seconds = 0.0;
    std::chrono::steady_clock::time_point at;
  } denoised_;
};

}  // namespace inkray
