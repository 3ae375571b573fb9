// The viewport's scheduler, driven without threads or a scene: what the editor's
// renderer does after a submit, an edit, a view change, a region, a pause and a
// limit, piece of work by piece of work (docs/architecture.md, "The viewport loop").
#include "core/render/viewport_schedule.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace inkray {
namespace {

using Kind = ViewportWork::Kind;

std::string describe(const ViewportWork& w) {
  switch (w.kind) {
    case Kind::wait:
      return w.wake_to_render ? "wait to render" : "wait";
    case Kind::stop:
      return "stop";
    case Kind::compile:
      return "compile";
    case Kind::restart:
      return "restart/" + std::to_string(w.divisor);
    case Kind::restart_region:
      return "restart region";
    case Kind::keep_film:
      return "keep film";
    case Kind::publish:
      return w.finished ? "publish finished" : "publish";
    case Kind::pass:
      return "pass/" + std::to_string(w.divisor);
    case Kind::refine:
      return "refine/" + std::to_string(w.divisor);
  }
  return "?";
}

using Trace = std::vector<std::string>;

// The schedule beside a film that does what its work says, as RenderSession would.
struct Driver {
  ViewportSchedule schedule;
  ViewportFilm film;
  ViewportRequests ui;  // what the UI holds besides the flags of one request
  CompileOutcome compile_outcome = CompileOutcome::new_scene;
  double pass_ms = 1.0;

  Driver() { ui.limits = {2, 0.0, 0.0}; }

  ViewportWork next() { return schedule.next(film); }

  // Does `w` with the outcomes set above; a wait takes no request.
  void execute(const ViewportWork& w) {
    switch (w.kind) {
      case Kind::wait:
        return schedule.taken(ui);
      case Kind::compile:
        return schedule.compiled(compile_outcome);
      case Kind::restart:
      case Kind::refine:
        film.divisor = w.divisor;
        film.stats = {};
        return;
      case Kind::restart_region:
        film.stats = {};
        return;
      case Kind::pass:
        ++film.stats.passes;
        ++film.stats.spp;
        return schedule.passed(pass_ms);
      case Kind::publish:
        return schedule.published(true);
      case Kind::keep_film:
      case Kind::stop:
        return;
    }
  }

  // Does the work handed out until the next wait, takes `request` (the UI's state with
  // some of its flags set) there, then does the work handed out until the schedule
  // waits for a request (a wait that only wakes to render goes on, as an unpaused
  // worker does). Returns the work after the request.
  Trace run(ViewportRequests request) {
    Trace trace;
    for (ViewportWork w = next(); w.kind != Kind::wait; w = next()) execute(w);
    schedule.taken(request);
    for (int steps = 0; steps < 100; ++steps) {
      const ViewportWork w = next();
      if (w.kind == Kind::wait && !(w.wake_to_render && !ui.paused)) {
        trace.push_back(describe(w));
        return trace;
      }
      if (w.kind != Kind::wait) trace.push_back(describe(w));
      execute(w);
    }
    ADD_FAILURE() << "the schedule never idled";
    return trace;
  }

  ViewportRequests with(bool ViewportRequests::*flag) const {
    ViewportRequests r = ui;
    r.*flag = true;
    return r;
  }
  Trace submit() { return run(with(&ViewportRequests::document)); }
  // Takes a document with the limits far off and does the work handed out until the
  // pass at `divisor`, which it hands back undone.
  ViewportWork submit_until_pass(int divisor) {
    ui.limits.spp = 100;
    schedule.taken(with(&ViewportRequests::document));
    ViewportWork w = next();
    for (; !(w.kind == Kind::pass && w.divisor == divisor); w = next()) execute(w);
    return w;
  }
  Trace change_view() { return run(with(&ViewportRequests::view_changed)); }
  Trace change_region() { return run(with(&ViewportRequests::region_changed)); }
  // A region set over the film and a document, taken together.
  ViewportRequests region_and_document() {
    ui.region_empty = false;
    ViewportRequests both = with(&ViewportRequests::region_changed);
    both.document = true;
    return both;
  }
};

const Trace kPreviewsToTwoSamples = {
    "compile", "restart/8", "pass/8",   "publish", "refine/4", "pass/4", "publish",          "refine/2",
    "pass/2",  "publish",   "refine/1", "pass/1",  "publish",  "pass/1", "publish finished", "wait"};

TEST(ViewportSchedule, ASubmitCompilesPreviewsAndRefinesToTheLimitThenIdles) {
  Driver d;
  EXPECT_EQ(d.next(), ViewportWork{});  // nothing to do: wait, not even for an unpause
  EXPECT_EQ(d.submit(), kPreviewsToTwoSamples);
  EXPECT_EQ(d.film.divisor, 1);
  EXPECT_EQ(d.film.stats.spp, 2u);
  EXPECT_EQ(d.schedule.accumulation(), 4u);  // the first preview, then three refinements
}

TEST(ViewportSchedule, ARequestWithoutADocumentRendersNothing) {
  Driver d;
  EXPECT_EQ(d.change_view(), Trace{"wait"});
  EXPECT_EQ(d.change_region(), Trace{"wait"});
}

TEST(ViewportSchedule, AFailedOrCancelledCompileKeepsTheLastScene) {
  Driver d;
  d.compile_outcome = CompileOutcome::failed;
  EXPECT_EQ(d.submit(), (Trace{"compile", "wait"}));  // nothing to show yet
  d.compile_outcome = CompileOutcome::new_scene;
  d.submit();
  const uint64_t accumulation = d.schedule.accumulation();
  for (CompileOutcome o : {CompileOutcome::failed, CompileOutcome::cancelled}) {
    d.compile_outcome = o;
    EXPECT_EQ(d.submit(), (Trace{"compile", "wait"}));
    EXPECT_EQ(d.schedule.accumulation(), accumulation);
  }
}

// A region taken with a document whose compile a newer one cancelled is not lost: it
// holds with the newer document, even one that changes only the resolve.
TEST(ViewportSchedule, ARegionTakenWithACancelledCompileHoldsForTheNextDocument) {
  Driver d;
  d.submit();
  d.compile_outcome = CompileOutcome::cancelled;
  const ViewportRequests both = d.region_and_document();
  EXPECT_EQ(d.run(both), (Trace{"compile", "wait"}));
  // Without the region the film would be kept ("keep film"); with it, it restarts, as a
  // region and a document taken together do.
  d.compile_outcome = CompileOutcome::resolve_only;
  EXPECT_EQ(d.submit().at(1), "restart/1");
}

// A document that fails to compile leaves the last scene, under the region taken with it.
TEST(ViewportSchedule, ARegionTakenWithAFailedCompileStillApplies) {
  Driver d;
  d.submit();
  d.compile_outcome = CompileOutcome::failed;
  const ViewportRequests both = d.region_and_document();
  const uint64_t accumulation = d.schedule.accumulation();
  EXPECT_EQ(d.run(both),
            (Trace{"compile", "restart region", "pass/1", "publish", "pass/1", "publish finished", "wait"}));
  EXPECT_EQ(d.schedule.accumulation(), accumulation + 1);
}

TEST(ViewportSchedule, AnEditOfTheResolveKeepsTheAccumulation) {
  Driver d;
  d.submit();
  const uint64_t accumulation = d.schedule.accumulation();
  d.compile_outcome = CompileOutcome::resolve_only;
  EXPECT_EQ(d.submit(), (Trace{"compile", "keep film", "publish", "publish finished", "wait"}));
  EXPECT_EQ(d.schedule.accumulation(), accumulation);
  EXPECT_EQ(d.film.stats.spp, 2u);
}

TEST(ViewportSchedule, TheFirstDocumentRestartsEvenIfOnlyItsResolveDiffers) {
  Driver d;
  d.compile_outcome = CompileOutcome::resolve_only;  // as the compiler reports a first compile
  EXPECT_EQ(d.submit(), kPreviewsToTwoSamples);
}

TEST(ViewportSchedule, AnEditThatNeedsNewSamplesRestartsAtAPreview) {
  Driver d;
  d.submit();
  const uint64_t accumulation = d.schedule.accumulation();
  EXPECT_EQ(d.submit(), kPreviewsToTwoSamples);
  EXPECT_GT(d.schedule.accumulation(), accumulation);
}

TEST(ViewportSchedule, AViewChangeOnlyPublishesAgain) {
  Driver d;
  d.submit();
  const uint64_t accumulation = d.schedule.accumulation();
  EXPECT_EQ(d.change_view(), (Trace{"publish", "publish finished", "wait"}));
  EXPECT_EQ(d.schedule.accumulation(), accumulation);
}

TEST(ViewportSchedule, AViewThatNeedsAnAovTheFilmLacksRestarts) {
  Driver d;
  d.submit();
  d.ui.aovs = FilmAovs::missing;
  EXPECT_EQ(d.change_view().at(0), "restart/8");
  // A view that needs fewer AOVs than the film keeps is shown from it.
  d.ui.aovs = FilmAovs::fewer;
  EXPECT_EQ(d.change_view(), (Trace{"publish", "publish finished", "wait"}));
}

TEST(ViewportSchedule, ARaisedLimitContinuesAFinishedRender) {
  Driver d;
  d.submit();
  d.ui.limits.spp = 3;
  EXPECT_EQ(d.change_view(), (Trace{"publish", "pass/1", "publish finished", "wait"}));
  EXPECT_EQ(d.film.stats.spp, 3u);
}

TEST(ViewportSchedule, ANewDocumentMidPassRestarts) {
  Driver d;
  d.submit_until_pass(1);
  d.schedule.passed(std::nullopt);  // submit() cancelled it
  const uint64_t accumulation = d.schedule.accumulation();
  EXPECT_EQ(d.next(), (ViewportWork{.kind = Kind::wait, .wake_to_render = true}));
  d.schedule.taken(d.with(&ViewportRequests::document));
  EXPECT_EQ(describe(d.next()), "compile");
  d.schedule.compiled(CompileOutcome::new_scene);
  EXPECT_EQ(describe(d.next()), "restart/8");
  EXPECT_EQ(d.schedule.accumulation(), accumulation + 1);
}

TEST(ViewportSchedule, ACancelledPassResumesAfterTheRequestThatCancelledIt) {
  Driver d;
  d.submit_until_pass(1);
  d.schedule.passed(std::nullopt);  // set_view() cancelled it
  d.schedule.taken(d.with(&ViewportRequests::view_changed));
  EXPECT_EQ(describe(d.next()), "pass/1");  // no full pass yet: nothing to publish again
}

TEST(ViewportSchedule, ARegionOverTheFullResolutionFilmKeepsThePixelsAroundIt) {
  Driver d;
  d.submit();
  d.ui.region_empty = false;
  EXPECT_EQ(d.change_region(),
            (Trace{"restart region", "pass/1", "publish", "pass/1", "publish finished", "wait"}));
  // Cleared, the region restarts the whole image at a preview.
  d.ui.region_empty = true;
  EXPECT_EQ(d.change_region().at(0), "restart/8");
}

TEST(ViewportSchedule, ARegionRestartsAtFullResolutionOtherwise) {
  Driver d;
  d.submit_until_pass(8);
  d.schedule.passed(std::nullopt);
  d.ui.region_empty = false;
  d.schedule.taken(d.with(&ViewportRequests::region_changed));  // over a preview
  const ViewportWork restart = d.next();
  EXPECT_EQ(describe(restart), "restart/1");
  d.execute(restart);

  d.ui.limits.spp = 1;
  d.submit();
  d.ui.aovs = FilmAovs::fewer;  // the film keeps an AOV the view no longer shows
  EXPECT_EQ(d.change_region().at(0), "restart/1");
  d.ui.aovs = FilmAovs::same;
  EXPECT_EQ(d.submit().at(1), "restart/1");  // a document with a region set
}

TEST(ViewportSchedule, PausedRendersNothingUntilResumed) {
  Driver d;
  d.ui.paused = true;
  EXPECT_EQ(d.submit(), (Trace{"compile", "restart/8", "wait to render"}));
  d.ui.paused = false;
  EXPECT_EQ(d.run(d.ui).at(0), "pass/8");
}

TEST(ViewportSchedule, OnlyTheFullResolutionFilmSamplesAdaptively) {
  Driver d;
  d.ui.limits = {100, 0.0, 0.05};
  d.schedule.taken(d.with(&ViewportRequests::document));
  for (ViewportWork w = d.next(); w.kind != Kind::pass || w.divisor > 1; w = d.next()) {
    if (w.kind == Kind::pass) {
      EXPECT_EQ(w.noise_target, 0.0);
    }
    d.execute(w);
  }
  EXPECT_EQ(d.next().noise_target, 0.05);
}

TEST(ViewportSchedule, FinishesAtTheTimeOrNoiseLimitOrWhenEveryTileStopped) {
  const auto finishes_at_once = [](ViewportFilm reached) {
    Driver d;
    d.ui.limits = {100, 1.0, 0.05};
    d.submit_until_pass(1);
    reached.divisor = 1;
    d.film = reached;
    d.schedule.passed(1.0);
    return d.next().finished;
  };
  ViewportFilm timed;
  timed.stats.passes = 1;
  timed.stats.elapsed_seconds = 1.0;
  EXPECT_TRUE(finishes_at_once(timed));
  ViewportFilm clean;
  clean.stats.passes = 4;  // the estimate counts from the fourth pass
  clean.stats.relative_error = 0.04;
  EXPECT_TRUE(finishes_at_once(clean));
  clean.stats.passes = 3;
  EXPECT_FALSE(finishes_at_once(clean));
  ViewportFilm converged;
  converged.stats.passes = 1;
  converged.converged = true;
  EXPECT_TRUE(finishes_at_once(converged));
}

TEST(ViewportSchedule, AFirstPreviewOverItsBudgetStartsTheNextDocumentCoarser) {
  Driver d;
  d.pass_ms = 20.0;
  d.submit();
  EXPECT_EQ(d.schedule.first_divisor(), 16);  // only the first preview's time counts
  d.pass_ms = 0.5;
  EXPECT_EQ(d.submit().at(1), "restart/16");
  EXPECT_EQ(d.schedule.first_divisor(), 8);  // the next step finer is well within it
}

TEST(ViewportSchedule, AFirstPreviewAdaptsWithinItsRange) {
  EXPECT_EQ(adapt_first_preview(8, 8, 9.0), 16);
  EXPECT_EQ(adapt_first_preview(16, 16, 9.0), 32);
  EXPECT_EQ(adapt_first_preview(32, 32, 9.0), 32);  // the coarsest
  EXPECT_EQ(adapt_first_preview(16, 16, 0.9), 8);
  EXPECT_EQ(adapt_first_preview(8, 8, 0.1), 8);     // the finest
  EXPECT_EQ(adapt_first_preview(16, 16, 1.5), 16);  // four times 1.5 ms is not well within 8
}

TEST(ViewportSchedule, APreviewWhosePublishWasCutShortStillCountsAsTheFirst) {
  Driver d;
  d.submit_until_pass(8);
  d.film.stats.passes = 1;
  d.schedule.passed(20.0);
  EXPECT_EQ(d.schedule.first_divisor(), 16);
  EXPECT_EQ(describe(d.next()), "publish");
  d.schedule.published(false);  // a newer document cut the resolve short
  EXPECT_EQ(describe(d.next()), "refine/4");
  d.execute(d.next());  // the wait: it wakes to render
  d.film.divisor = 4;
  EXPECT_EQ(describe(d.next()), "pass/4");
  d.schedule.passed(20.0);  // so this one's time adapts the first divisor too
  EXPECT_EQ(d.schedule.first_divisor(), 8);
}

TEST(ViewportSchedule, StopsWhenAsked) {
  Driver d;
  d.submit();
  d.schedule.taken({.stop = true});
  EXPECT_EQ(d.next().kind, Kind::stop);
}

}  // namespace
}  // namespace inkray
