// What the editor's viewport renderer does next, decided from plain state: the
// scheduler half of ProgressiveRenderer, which does the work it is given
// (docs/architecture.md, "The viewport loop"). No threads, scene or film here.
#pragma once

#include "core/render/render_session.h"

#include <cstdint>
#include <optional>

namespace inkray {

struct ViewportLimits {
  int spp = 64;
  double time_seconds = 0.0;  // 0: none
  // Stop when the estimated relative error is below; 0: none. Tiles below it stop
  // taking samples before that (adaptive sampling, core/render/adaptive_sampling.h).
  double noise_target = 0.0;
};

// The AOVs the view needs, beside those the film keeps.
enum class FilmAovs { same, fewer, missing };  // fewer: the film keeps more than the view needs

// What the UI asked for since the worker last looked, as the worker took it.
struct ViewportRequests {
  bool stop = false;
  bool document = false;        // a new document waits to be compiled
  bool region_changed = false;  // the film restarts inside the region
  bool view_changed = false;    // the view or the limits: the film is shown again
  bool paused = false;
  bool region_empty = true;
  FilmAovs aovs = FilmAovs::same;  // of the view taken, beside the film's
  ViewportLimits limits{};
};

// The session's film as the next piece of work finds it.
struct ViewportFilm {
  int divisor = 1;
  RenderStats stats{};
  bool converged = false;  // RenderSession::converged
};

// What the compiler made of the document taken.
enum class CompileOutcome {
  cancelled,     // a newer document is waiting
  failed,        // errors: the last good scene stays
  resolve_only,  // a change only the film's resolve reads (or none): the samples can stay
  new_scene,     // the samples are stale
};

// One piece of work, as Cycles' RenderScheduler hands its Session a RenderWork.
struct ViewportWork {
  enum class Kind {
    wait,            // take the UI's requests, sleeping until there are some
    stop,            // the renderer is going away
    compile,         // the document taken
    restart,         // a new film at `divisor` (the region's pixels at full resolution)
    restart_region,  // the region's pixels start again; the film around them keeps its samples
    keep_film,       // the compiled scene replaces the session's; the film stays
    publish,         // resolve the film and publish a snapshot
    pass,            // one pass over the film
    refine,          // the next preview: a new film at `divisor`
  };
  Kind kind = Kind::wait;
  int divisor = 1;              // restart, refine: the new film's; pass: the film's
  double noise_target = 0.0;    // pass: adaptive sampling's threshold, 0 for every tile
  bool finished = false;        // publish: a limit was reached and the worker idles after it
  bool wake_to_render = false;  // wait: passes remain, so being unpaused is reason to wake
  bool operator==(const ViewportWork&) const = default;
};

class ViewportSchedule {
 public:
  // The work to do next. Work with an outcome (wait, compile, pass, publish) is handed out
  // again until its outcome is reported; the rest counts as done once handed out.
  ViewportWork next(const ViewportFilm& film);
  void taken(const ViewportRequests& requests);
  void compiled(CompileOutcome outcome);
  void passed(std::optional<double> ms);  // the pass's time; none when it was cancelled
  void published(bool shown);             // shown: not cut short by a newer document

  // Which accumulation of samples the film holds: it changes whenever the film restarts.
  uint64_t accumulation() const { return accumulation_; }
  // The divisor a document's first preview starts at.
  int first_divisor() const { return first_divisor_; }

 private:
  // What the requests taken and the compile ask of the film, strongest last: show it
  // again, keep it under a new scene, restart a region, restart it.
  enum class FilmChange { none, show, keep, region, restart };
  // Where next() is: the film step decides what the changes ask, render whether to take
  // a pass; pass and publish wait for their outcome.
  enum class Step { take, compile, film, show, render, pass, after_pass, refine, publish, stop };
  bool limits_reached(const ViewportFilm& film) const;
  ViewportWork publish(bool finished, Step then);

  Step step_ = Step::take;
  Step after_publish_ = Step::take;
  ViewportWork current_;  // handed out and waiting for its outcome
  ViewportRequests requests_;
  FilmChange change_ = FilmChange::none;
  FilmChange carried_ = FilmChange::none;  // taken with a compile that was cancelled
  bool has_scene_ = false;
  bool active_ = false;  // passes remain: no limit reached since the last change
  // No snapshot since the last restart: the first preview's time adapts first_divisor_.
  bool first_publish_ = true;
  int first_divisor_ = 8;  // kFirstPreviewDivisor, then adapt_first_preview's
  uint64_t accumulation_ = 0;
};

// After a document's first preview, which took `ms` at `divisor`: the divisor the
// next document's first preview starts at, from the one it started at now.
int adapt_first_preview(int first_divisor, int divisor, double ms);

}  // namespace inkray
