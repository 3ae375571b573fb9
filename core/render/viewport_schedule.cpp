#include "core/render/viewport_schedule.h"

#include <algorithm>
#include <utility>

namespace inkray {
namespace {

// The first preview is this much coarser than the image (per axis): 1/64 of
// the pixels, so it is ready within a UI frame or two even on one thread;
// each following stage halves it. A scene whose first preview takes longer than
// kFirstPreviewBudgetMs starts one step coarser from then on, down to
// kCoarsestPreviewDivisor, and one whose next step finer would take under half of it
// one step finer.
constexpr int kFirstPreviewDivisor = 8;
constexpr int kCoarsestPreviewDivisor = 32;
constexpr double kFirstPreviewBudgetMs = 8.0;

}  // namespace

int adapt_first_preview(int first_divisor, int divisor, double ms) {
  if (ms > kFirstPreviewBudgetMs && divisor < kCoarsestPreviewDivisor) return divisor * 2;
  // One step finer has four times the pixels: taken only while that stays well within
  // the budget, so the divisor does not swing between two steps.
  if (4.0 * ms < 0.5 * kFirstPreviewBudgetMs && divisor > kFirstPreviewDivisor) return divisor / 2;
  return first_divisor;
}

void ViewportSchedule::taken(const ViewportRequests& requests) {
  requests_ = requests;
  // A view that needs an AOV the film lacks restarts it, whatever else was asked.
  if (requests.view_changed && requests.aovs == FilmAovs::missing) {
    change_ = FilmChange::restart;
  } else if (requests.region_changed) {
    change_ = FilmChange::region;
  } else {
    change_ = requests.view_changed ? FilmChange::show : FilmChange::none;
  }
  // What a request taken with a cancelled compile asked of the film still holds.
  change_ = std::max(change_, std::exchange(carried_, FilmChange::none));
  step_ = requests.stop ? Step::stop : requests.document ? Step::compile : Step::film;
}

void ViewportSchedule::compiled(CompileOutcome outcome) {
  if (outcome == CompileOutcome::cancelled) {
    // A newer document is waiting; a region or view taken with this one goes with it.
    carried_ = std::max(carried_, change_);
    step_ = Step::take;
    return;
  }
  if (outcome == CompileOutcome::failed) {
    step_ = Step::film;  // the last good scene stays, under the region and view taken with it
    return;
  }
  // Line colours, the painterly filter and render limits are read when the film
  // is resolved: the samples so far stay, and the image is composited again.
  const bool keep = has_scene_ && change_ < FilmChange::region && outcome == CompileOutcome::resolve_only;
  change_ = keep ? FilmChange::keep : FilmChange::restart;
  has_scene_ = true;
  step_ = Step::film;
}

void ViewportSchedule::passed(std::optional<double> ms) {
  if (!ms) {
    step_ = Step::take;  // cancelled: a newer request is waiting
    return;
  }
  if (first_publish_ && current_.divisor > 1)
    first_divisor_ = adapt_first_preview(first_divisor_, current_.divisor, *ms);
  step_ = Step::after_pass;
}

void ViewportSchedule::published(bool shown) {
  if (shown) first_publish_ = false;
  step_ = after_publish_;
}

bool ViewportSchedule::limits_reached(const ViewportFilm& film) const {
  const RenderStats& s = film.stats;
  const ViewportLimits& limits = requests_.limits;
  if (limits.spp > 0 && int(s.spp) >= limits.spp) return true;
  if (limits.time_seconds > 0.0 && s.elapsed_seconds >= limits.time_seconds) return true;
  return noise_target_reached(s, limits.noise_target) || film.converged;
}

ViewportWork ViewportSchedule::publish(bool finished, Step then) {
  step_ = Step::publish;
  after_publish_ = then;
  current_ = {.kind = ViewportWork::Kind::publish, .finished = finished};
  return current_;
}

ViewportWork ViewportSchedule::next(const ViewportFilm& film) {
  using Kind = ViewportWork::Kind;
  for (;;) {
    switch (step_) {
      case Step::take:
        current_ = {.kind = Kind::wait, .wake_to_render = active_};
        return current_;
      case Step::stop:
        return {.kind = Kind::stop};
      case Step::compile:
        current_ = {.kind = Kind::compile};
        return current_;
      case Step::film:
        if (!has_scene_) {
          step_ = Step::take;
          continue;
        }
        step_ = Step::render;
        if (change_ == FilmChange::region && !requests_.region_empty && film.divisor == 1 &&
            requests_.aovs == FilmAovs::same) {
          // A region over the full-resolution film: the pixels around it keep their samples.
          ++accumulation_;
          active_ = true;
          return {.kind = Kind::restart_region};
        }
        if (change_ >= FilmChange::region) {
          first_publish_ = true;
          ++accumulation_;
          active_ = true;
          return {.kind = Kind::restart, .divisor = requests_.region_empty ? first_divisor_ : 1};
        }
        if (change_ == FilmChange::none) continue;
        active_ = true;  // a raised limit lets a finished render continue; limits_reached decides
        step_ = Step::show;
        if (change_ == FilmChange::keep) return {.kind = Kind::keep_film};
        continue;
      case Step::show:
        if (film.stats.passes > 0) return publish(false, Step::render);
        step_ = Step::render;
        continue;
      case Step::render:
        if (!active_ || requests_.paused) {
          step_ = Step::take;
          continue;
        }
        if (film.divisor == 1 && film.stats.passes > 0 && limits_reached(film)) {
          active_ = false;
          return publish(true, Step::take);
        }
        step_ = Step::pass;
        // Only the full-resolution film samples adaptively; each preview is one pass.
        current_ = {.kind = Kind::pass,
                    .divisor = film.divisor,
                    .noise_target = film.divisor == 1 ? requests_.limits.noise_target : 0.0};
        return current_;
      case Step::pass:
      case Step::publish:
        return current_;  // its outcome is not reported yet
      case Step::after_pass: {
        const bool done = film.divisor == 1 && limits_reached(film);
        if (done) active_ = false;
        return publish(done, film.divisor > 1 ? Step::refine : Step::take);
      }
      case Step::refine:
        step_ = Step::take;
        ++accumulation_;
        return {.kind = Kind::refine, .divisor = film.divisor / 2};
    }
  }
}

}  // namespace inkray
