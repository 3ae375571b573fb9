#include "core/render/viewport_resolver.h"

#include "core/film/denoise.h"

#include <algorithm>
#include <utility>

namespace inkray {

void ViewportResolver::invalidate(ResolveChange why) {
  const Stale stale =
      why == ResolveChange::new_samples || why == ResolveChange::denoise_toggled ? Stale::base : Stale::lines;
  stale_ = std::max(stale_, stale);
}

RgbImage ViewportResolver::final_radiance(const Film& film, bool denoise, const FilmProgress& progress,
                                          ThreadBudget& pool, const Cancel& cancel) {
  if (!denoise || film.width() == 0) return film.resolve();
  // Denoising again costs a few passes' time at most: once its cost is small beside
  // the time since, at a new accumulation, and when the render finishes.
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - denoised_.at).count();
  const bool due = denoised_.accumulation != progress.accumulation || progress.finished ||
                   (progress.spp != denoised_.spp && since >= std::max(0.5, 4.0 * denoised_.seconds));
  if (due) {
    Denoised d = inkray::denoise(film, &pool, cancel);
    if (d.image.pixels.empty()) return {};
    denoised_.image = std::move(d.image);
    denoised_.error = d.relative_error;
    denoised_.accumulation = progress.accumulation;
    denoised_.spp = progress.spp;
    denoised_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - now).count();
    denoised_.at = std::chrono::steady_clock::now();
  }
  return denoised_.image;
}

const RgbImage* ViewportResolver::resolve(const Film& film, const RenderScene& scene,
                                          const DisplayEncoding& display, bool denoise,
                                          const FilmProgress& progress, ThreadBudget& pool,
                                          const Cancel& cancel) {
  if (denoise != base_denoised_) invalidate(ResolveChange::denoise_toggled);
  // Only an edit of the resolve stage changes the settings under the same samples; a
  // line edit composites the cached base again, a filter edit filters anew.
  if (stale_ == Stale::lines && !same_base(base_settings_, scene.resolve)) stale_ = Stale::base;
  if (stale_ == Stale::base) {
    RgbImage radiance = final_radiance(film, denoise, progress, pool, cancel);
    if (radiance.pixels.empty()) return nullptr;  // cut short: the newer document is waiting
    base_ = resolve_base(std::move(radiance), scene.resolve, film.height(), &pool, cancel);
    if (base_.pixels.empty()) return nullptr;
    base_denoised_ = denoise;
    lines_ = gather_lines(film, scene.resolve);
    base_settings_ = scene.resolve;
    stale_ = Stale::lines;
  }
  if (!film.has_lines()) {
    resolved_ = {};
    return &base_;
  }
  if (!(resolved_for_ == display)) invalidate(ResolveChange::display);
  if (stale_ == Stale::lines) {
    // The first line set, or new material paths, chain the same samples' lines anew.
    if (!lines_.serve(scene.resolve)) lines_ = gather_lines(film, scene.resolve);
    resolved_ = base_;  // reuses its pixels' storage
    composite_lines(lines_, scene.resolve, display, resolved_);
    resolved_for_ = display;
    stale_ = Stale::none;
  }
  return &resolved_;
}

}  // namespace inkray
