// inkray-render: the headless renderer for final renders and render farms.
#include "app/render_cli.h"
#include "core/compiler/compile.h"
#include "core/compiler/compile_view.h"
#include "core/document/graph_reference.h"
#include "core/document/json_io.h"
#include "core/document/scene_hash.h"
#include "core/film/denoise.h"
#include "core/film/film_partial.h"
#include "core/film/line_decisions_file.h"
#include "core/film/partial_merge.h"
#include "core/film/resolve.h"
#include "core/render/batch_render.h"
#include "core/io/atomic_file.h"
#include "core/render/render_outputs.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include <unistd.h>

namespace {

using namespace inkray;
namespace fs = std::filesystem;

void print_progress(const RenderStats& s, const BatchLimits& limits) {
  double frac = double(s.spp) / double(limits.spp);
  if (limits.time_seconds > 0.0) frac = std::max(frac, s.elapsed_seconds / limits.time_seconds);
  frac = std::min(frac, 1.0);
  const int width = 30, filled = int(frac * width + 0.5);
  std::fprintf(stderr, "\r[%.*s%*s] %3d%%  %u spp  %.1f s  error %.4f", filled,
               "##############################", width - filled, "", int(frac * 100.0 + 0.5), s.spp,
               s.elapsed_seconds, s.relative_error);
  std::fflush(stderr);
}

// Checkpoints at powers of two and the final pass keep the table short.
void print_table(const std::vector<PassRecord>& history) {
  std::printf("%8s %8s %12s %14s\n", "pass", "spp", "seconds", "rel. error");
  for (size_t i = 0; i < history.size(); ++i) {
    const PassRecord& r = history[i];
    const bool power_of_two = (r.pass & (r.pass - 1)) == 0;
    if (power_of_two || i + 1 == history.size())
      std::printf("%8u %8u %12.3f %14.5f\n", r.pass, r.spp, r.elapsed_seconds, r.relative_error);
  }
}

int write_scene_file(const SceneDesc& desc, const fs::path& file) {
  std::string error;
  if (!save_scene_as(desc, file, &error)) {
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return 1;
  }
  return 0;
}

double seconds_since(Cancel::Clock::time_point start) {
  return std::chrono::duration<double>(Cancel::Clock::now() - start).count();
}

Cancel::Clock::time_point deadline_after(Cancel::Clock::time_point start, double seconds) {
  if (seconds <= 0.0) return Cancel::Clock::time_point::max();
  return start + std::chrono::duration_cast<Cancel::Clock::duration>(std::chrono::duration<double>(seconds));
}

// What stays the same from frame to frame: the compiler reuses what a frame's
// changes leave valid, and the session its threads.
struct Renderer {
  const RenderCliOptions& opt;
  SceneCompiler compiler;
  RenderSession session;
  bool checkpoint_failed = false;  // makes the run exit 1 once every frame is rendered
  explicit Renderer(const RenderCliOptions& o) : opt(o), session(o.threads.value_or(0)) {}
};

// One frame's files.
struct FrameFiles {
  std::optional<int> frame;  // set with --frames
  fs::path output, checkpoint;
  std::vector<AovFile> aovs;
  LineFiles lines;
  bool all_exist() const {
    std::error_code ec;
    if (!fs::exists(output, ec)) return false;
    for (const AovFile& a : aovs)
      if (!fs::exists(a.file, ec)) return false;
    for (const fs::path& file : {lines.svg, lines.pdf})
      if (!file.empty() && !fs::exists(file, ec)) return false;
    return true;
  }
};

FrameFiles frame_files(const RenderCliOptions& opt, std::optional<int> frame) {
  FrameFiles f;
  f.frame = frame;
  f.output = frame ? expand_frame_pattern(opt.output, *frame) : opt.output;
  f.checkpoint = checkpoint_path(f.output);
  for (const auto& a : opt.aovs)
    if (!a.file.empty())
      f.aovs.push_back({*aov_from_name(a.name), frame ? expand_frame_pattern(a.file, *frame) : a.file});
  const auto framed = [&](const fs::path& file) {
    return frame && !file.empty() ? expand_frame_pattern(file, *frame) : file;
  };
  f.lines = {framed(opt.lines_svg), framed(opt.lines_pdf), opt.lines_svg_image};
  return f;
}

// The film's state as a partial: passes [first, next) and the pass in progress.
PartialInfo film_info(const RenderSession& session, const SceneDesc& desc, const PixelWindow& window) {
  PartialInfo info;
  info.width = desc.render.width;
  info.height = desc.render.height;
  info.window = window;
  info.first_pass = session.first_pass();
  info.end_pass = session.stats().passes;
  const auto& tiles = session.tiles_done();
  if (std::any_of(tiles.begin(), tiles.end(), [](uint8_t t) { return t != 0; })) info.tiles_done = tiles;
  info.frame = desc.render.frame;
  info.seed = desc.render.seed;
  info.scene = scene_to_string(desc);
  info.assets = hash_scene_assets(desc);  // merge, --resume and --line-decisions compare them
  info.aovs = session.film().aovs().first_hit();
  info.lines = session.film().has_lines();
  info.nonfinite = session.film().nonfinite_samples();
  return info;
}

// --decide-lines: the decisions of the scene's frame, traced over the whole image,
// written atomically.
int write_line_decisions(const RenderCliOptions& opt, const SceneDesc& desc,
                         Cancel::Clock::time_point start) {
  const double time_limit = opt.time_seconds.value_or(desc.render.time_limit);
  CompileOptions options;
  options.cancel = Cancel(nullptr, deadline_after(start, time_limit));
  options.memory_limit = opt.memory_limit.value_or(0);
  SceneCompiler compiler;
  const CompileResult compiled = compiler.compile(desc, options);
  if (compiled.cancelled) {
    std::fprintf(stderr,
                 "error: %s: the time limit of %g s ran out while building the scene; nothing was written\n",
                 opt.scene.c_str(), time_limit);
    return 1;
  }
  if (!compiled.scene) {
    for (const auto& e : compiled.errors)
      std::fprintf(stderr, "error: %s: %s\n", opt.scene.c_str(), e.c_str());
    return 1;
  }
  RenderSession session(opt.threads.value_or(0));
  session.set_scene(compiled.scene);
  const LineDecisions decisions = session.decide_lines();
  PartialInfo info = film_info(session, desc, PixelWindow{0, 0, desc.render.width, desc.render.height});
  std::string error;
  if (!write_file_atomically(opt.decide_lines, encode_line_decisions(decisions, info), &error)) {
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return 1;
  }
  if (!opt.quiet)
    std::printf("%s: line decisions of %dx%d pixels, made by sample %u, written to %s\n", opt.scene.c_str(),
                decisions.width, decisions.height, decisions.decided_at, opt.decide_lines.c_str());
  return 0;
}

// --line-decisions: the file's decisions, when they are of this render (else an error line).
bool read_matching_decisions(const RenderCliOptions& opt, const PartialInfo& expected,
                             LineDecisions* decisions) {
  PartialInfo info;
  std::string error;
  if (!read_line_decisions(opt.line_decisions, &info, decisions, &error)) {
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return false;
  }
  PartialInfo render = expected;
  render.aovs = {};  // the decisions hold no AOVs: any the slice keeps are its own
  if (const std::string problem = partial_mismatch(info, render); !problem.empty()) {
    std::fprintf(stderr, "error: %s: line decisions of another render: %s\n", opt.line_decisions.c_str(),
                 problem.c_str());
    return false;
  }
  return true;
}

// Renders one frame (or the still) and writes its files. `start` is when this frame's
// time began (for the first, before the scene was read).
int render_frame(Renderer& r, SceneDesc desc, const FrameFiles& files, Cancel::Clock::time_point start) {
  const RenderCliOptions& opt = r.opt;
  const std::string label = files.frame ? "frame " + std::to_string(*files.frame) : opt.scene.string();
  const auto out_of_time = [&](double limit, const char* phase) {
    std::fprintf(stderr,
                 "error: %s: the time limit of %g s ran out while %s (after %.1f s); nothing was written\n",
                 label.c_str(), limit, phase, seconds_since(start));
    return 1;
  };
  if (files.frame) desc.render.frame = float(*files.frame);

  // --resume: a checkpoint continues; without one, a render whose files all exist is done.
  PartialInfo resumed;
  std::unique_ptr<Film> resumed_film;
  std::error_code ec;
  if (opt.resume && fs::exists(files.checkpoint, ec)) {
    std::string error;
    if (!read_partial(files.checkpoint, &resumed, &resumed_film, &error)) {
      std::fprintf(stderr, "error: cannot resume: %s\n", error.c_str());
      return 1;
    }
  } else if (opt.resume && files.all_exist()) {
    if (!opt.quiet) std::printf("%s: %s exists, skipped\n", label.c_str(), files.output.c_str());
    return 0;
  }

  const double time_limit = opt.time_seconds.value_or(desc.render.time_limit);
  const Cancel deadline(nullptr, deadline_after(start, time_limit));
  CompileOptions options;
  options.cancel = deadline;
  options.memory_limit = opt.memory_limit.value_or(0);
  const CompileResult compiled = r.compiler.compile(desc, options);
  if (compiled.cancelled) return out_of_time(time_limit, "building the scene");
  if (!compiled.scene) {
    for (const auto& e : compiled.errors)
      std::fprintf(stderr, "error: %s: %s\n", opt.scene.c_str(), e.c_str());
    return 1;
  }

  AovSet aovs;
  for (const auto& a : opt.aovs) aovs.add(*aov_from_name(a.name));
  if (opt.denoise) aovs.bits |= denoise_aovs().bits;
  RenderSession& session = r.session;
  session.set_scene(compiled.scene, aovs);
  const PixelWindow whole{0, 0, desc.render.width, desc.render.height};
  const PixelWindow window = opt.crop.value_or(whole);
  session.set_region(opt.crop ? window : PixelWindow{});
  const bool partial = opt.samples.has_value();
  const uint32_t first = partial ? opt.samples->first : 0;
  const uint32_t end = partial ? opt.samples->second : uint32_t(opt.spp.value_or(desc.render.spp));

  if (resumed_film) {
    PartialInfo expected = film_info(session, desc, window);
    expected.first_pass = first;
    std::string problem = partial_mismatch(resumed, expected);
    if (problem.empty() && resumed.window != window)
      problem =
          "it holds pixels " + describe_window(resumed.window) + ", this render " + describe_window(window);
    if (problem.empty() && resumed.first_pass != first)
      problem = "it starts at sample " + std::to_string(resumed.first_pass) + ", this render at " +
                std::to_string(first);
    if (problem.empty() &&
        (resumed.end_pass > end || (resumed.end_pass == end && !resumed.tiles_done.empty())))
      problem = "it holds samples " + describe_range(resumed.first_pass, resumed.end_pass) +
                ", more than the " + describe_range(first, end) + " asked for";
    if (!problem.empty()) {
      std::fprintf(stderr, "error: %s: cannot resume this render from it: %s (remove it to start again)\n",
                   files.checkpoint.c_str(), problem.c_str());
      return 1;
    }
  }
  LineDecisions decisions;
  if (!opt.line_decisions.empty() &&
      !read_matching_decisions(opt, film_info(session, desc, window), &decisions))
    return 1;
  const LineDecisions* decided = opt.line_decisions.empty() ? nullptr : &decisions;
  if (resumed_film) {
    session.load_film(*resumed_film);
    resumed_film.reset();
    session.continue_from(first, resumed.end_pass, resumed.tiles_done, decided);
  } else {
    session.continue_from(first, first, {}, decided);
  }

  if (opt.noise_threshold) session.set_adaptive({*opt.noise_threshold, uint32_t(opt.min_spp.value_or(16))});

  // --time is a budget (docs/final-renders.md, "Time limits"): the render gets what
  // reading and building left of it, less what the painterly filter and the denoiser,
  // measured on this machine, will need after it. They then run to the end whatever
  // the clock says, so a render that finished a pass always writes its image.
  double render_seconds = 0.0;
  if (time_limit > 0.0) {
    double filter_seconds = 0.0;
    if (!partial) {
      filter_seconds =
          1.25 * estimate_painterly_seconds(compile_resolve_settings(desc.render, desc.outlines),
                                            desc.render.width, desc.render.height, &session.pool());
      if (opt.denoise)
        filter_seconds += 1.25 * estimate_denoise_seconds(window.width(), window.height(), &session.pool());
    }
    render_seconds = time_limit - seconds_since(start) - filter_seconds;
    if (render_seconds <= 0.0) {
      std::fprintf(
          stderr,
          "error: %s: %s alone takes about %.1f s at %dx%d, more than the time limit of %g s leaves; "
          "nothing was written\n",
          label.c_str(), opt.denoise ? "the painterly filter with the denoiser" : "the painterly filter",
          filter_seconds / 1.25, desc.render.width, desc.render.height, time_limit);
      return 1;
    }
  }
  const BatchLimits limits{int(end - first), render_seconds};
  const bool progress = !opt.quiet && isatty(fileno(stderr));
  // A checkpoint that cannot be written is an error: the render goes on and its files are
  // written, but the exit status says the render could not have been resumed.
  std::string checkpoint_error;
  const auto write_checkpoint = [&] {
    const PartialInfo info = film_info(session, desc, window);
    if (info.end_pass == info.first_pass && info.tiles_done.empty()) return;  // nothing rendered yet
    std::string error;
    if (write_partial_file(session.film(), info, files.checkpoint, &error)) return;
    if (checkpoint_error.empty())
      std::fprintf(stderr, "%serror: checkpoint %s not written (the render goes on): %s\n",
                   progress ? "\n" : "", files.checkpoint.c_str(), error.c_str());
    checkpoint_error = error;
  };
  auto last_checkpoint = Cancel::Clock::now();
  const auto history = render_batch(session, limits, [&](const RenderStats& s) {
    if (progress) print_progress(s, limits);
    if (opt.checkpoint_minutes && s.spp < uint32_t(limits.spp) &&
        seconds_since(last_checkpoint) >= *opt.checkpoint_minutes * 60.0) {
      write_checkpoint();
      last_checkpoint = Cancel::Clock::now();
    }
  });
  if (progress) std::fprintf(stderr, "\n");
  const bool complete = session.stats().passes >= end;
  if (!complete && opt.checkpoint_minutes) write_checkpoint();
  if (session.stats().spp == 0) return out_of_time(time_limit, "rendering the first sample of every pixel");

  std::string error;
  double denoise_seconds = 0.0;
  std::optional<Denoised> denoised;
  if (partial) {
    if (!complete) {
      std::fprintf(stderr,
                   "error: %s: the time limit of %g s ran out at sample %u of %u-%u; the partial %s was not "
                   "written%s\n",
                   label.c_str(), time_limit, session.stats().passes, first, end, files.output.c_str(),
                   !opt.checkpoint_minutes    ? ""
                   : checkpoint_error.empty() ? " (--resume continues from the checkpoint)"
                                              : " (and the checkpoint could not be written)");
      return 1;
    }
    if (!write_partial_file(session.film(), film_info(session, desc, window), files.output, &error)) {
      std::fprintf(stderr, "error: %s\n", error.c_str());
      return 1;
    }
  } else {
    if (opt.denoise) {
      const auto t0 = Cancel::Clock::now();
      denoised = denoise(session.film(), &session.pool());
      denoise_seconds = seconds_since(t0);
    }
    // Every output is staged before any is replaced: a failed AOV leaves no image behind.
    switch (write_render_outputs(session, files.output, files.aovs, &error, Cancel{},
                                 opt.crop ? window : PixelWindow{}, denoised ? &denoised->image : nullptr,
                                 files.lines)) {
      case OutputsWritten::all:
        break;
      case OutputsWritten::cancelled:
        return out_of_time(time_limit, "applying the painterly filter");
      case OutputsWritten::failed:
        std::fprintf(stderr, "error: %s\n", error.c_str());
        return 1;
    }
  }
  if (complete && fs::exists(files.checkpoint, ec)) fs::remove(files.checkpoint, ec);
  if (complete) remove_stale_temporaries(files.checkpoint);  // a killed run's, when none was written
  if (!checkpoint_error.empty()) {
    std::fprintf(stderr, "error: %s: checkpoint %s could not be written (%s); %s\n", label.c_str(),
                 files.checkpoint.c_str(), checkpoint_error.c_str(),
                 complete ? "the render completed and its files were written"
                          : "the image of the samples done was written, but --resume cannot continue it");
    r.checkpoint_failed = true;
  }

  if (opt.quiet) return 0;
  const RenderStats& s = session.stats();
  if (files.frame) {
    std::printf("frame %d: %s, %u spp, %.3f s\n", *files.frame, files.output.c_str(), s.spp,
                seconds_since(start));
    std::fflush(stdout);
    return 0;
  }
  print_table(history);
  std::printf("%s: ", files.output.c_str());
  if (partial) std::printf("partial, samples %u-%u of ", first, end);
  std::printf("%dx%d", desc.render.width, desc.render.height);
  if (opt.crop) std::printf(" (pixels %d,%d-%d,%d)", window.x0, window.y0, window.x1, window.y1);
  std::printf(", %u spp, %.3f s, %d threads, %.2f M rays/s, %.2f M paths/s", s.spp, s.elapsed_seconds,
              session.threads(), double(s.rays) / s.elapsed_seconds * 1e-6,
              double(s.paths) / s.elapsed_seconds * 1e-6);
  if (s.nonfinite_samples)
    std::printf(", %llu non-finite samples dropped", (unsigned long long)s.nonfinite_samples);
  std::printf("\n");
  if (opt.noise_threshold)
    std::printf(
        "adaptive sampling: %u of %u tiles below %g when the render ended; %.1f samples per pixel on "
        "average\n",
        s.tiles - s.active_tiles, s.tiles, *opt.noise_threshold,
        double(s.paths) / (double(window.width()) * double(window.height())));
  if (denoised)
    std::printf("denoised in %.3f s: estimated rel. error %.5f denoised (%s), %.5f raw (%s)\n",
                denoise_seconds, denoised->relative_error, files.output.c_str(), s.relative_error,
                raw_image_path(files.output).c_str());
  return 0;
}

// --time is a budget for the whole run: the clock starts before the scene is read.
// Reading and building stop at the deadline (a half-built scene would be a wrong
// render: nothing is written); the render stops there too, even mid-pass, keeping the
// passes done; the painterly filter and the denoiser, whose time was kept back before
// rendering, then run to the end. So an image is written whenever a pass finished.
// With --frames it bounds each frame, the first with the reading.
int run(const RenderCliOptions& opt, Cancel::Clock::time_point start) {
  // Before the scene is read only --time is known; its render.time_limit applies after.
  const double cli_limit = opt.time_seconds.value_or(0.0);
  // --write-scene reads as the editor does: a scene that cannot render yet is still saved.
  const ReadFor purpose = opt.write_scene.empty() ? ReadFor::rendering : ReadFor::editing;
  SceneLoadResult loaded = load_scene(opt.scene, purpose, Cancel(nullptr, deadline_after(start, cli_limit)));
  if (loaded.cancelled) {
    std::fprintf(stderr,
                 "error: %s: the time limit of %g s ran out while reading the scene (after %.1f s); nothing "
                 "was written\n",
                 opt.scene.c_str(), cli_limit, seconds_since(start));
    return 1;
  }
  if (!loaded) {
    for (const auto& e : loaded.errors) std::fprintf(stderr, "error: %s\n", e.c_str());
    return 1;
  }
  for (const auto& w : loaded.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  SceneDesc desc = std::move(*loaded.scene);
  if (!opt.write_scene.empty()) return write_scene_file(desc, opt.write_scene);
  if (opt.width) desc.render.width = *opt.width;
  if (opt.height) desc.render.height = *opt.height;
  if (opt.seed) desc.render.seed = *opt.seed;
  if (int64_t(desc.render.width) * desc.render.height > int64_t(8192) * 8192) {
    std::fprintf(stderr, "error: %dx%d is larger than the 8192x8192 pixels inkray renders at once\n",
                 desc.render.width, desc.render.height);
    return 1;
  }
  if (opt.crop && (opt.crop->x1 > desc.render.width || opt.crop->y1 > desc.render.height)) {
    std::fprintf(stderr, "inkray-render: --crop %d %d %d %d: the window is not inside the %dx%d image\n",
                 opt.crop->x0, opt.crop->y0, opt.crop->x1, opt.crop->y1, desc.render.width,
                 desc.render.height);
    return 2;
  }
  if (!opt.decide_lines.empty()) return write_line_decisions(opt, desc, start);
  std::vector<std::optional<int>> frames;
  if (!opt.frames) {
    frames.push_back(std::nullopt);  // the still: the scene's current frame
  } else {
    FrameRange range = *opt.frames;
    if (range.all) {
      range.first = desc.render.frame_start;
      range.last = desc.render.frame_end;
      if (range.last < range.first) {
        std::fprintf(stderr, "error: %s: --frames all: the scene's frames %d-%d are no range\n",
                     opt.scene.c_str(), range.first, range.last);
        return 1;
      }
    }
    for (int f = range.first; f <= range.last; f += range.step) frames.push_back(f);
    if (frames.size() > 1 && !has_frame_pattern(opt.output)) {
      std::fprintf(stderr,
                   "inkray-render: --frames all renders frames %d-%d: -o needs a run of '#' for the frame "
                   "number (e.g. out_####.png)\n",
                   range.first, range.last);
      return 2;
    }
    if (const std::string problem = check_frame_names(opt, frames_of(range)); !problem.empty()) {
      std::fprintf(stderr, "inkray-render: --frames %d-%d: %s\n", range.first, range.last, problem.c_str());
      return 2;
    }
  }
  Renderer renderer(opt);
  for (size_t i = 0; i < frames.size(); ++i) {
    const auto frame_start = i == 0 ? start : Cancel::Clock::now();
    if (const int status = render_frame(renderer, desc, frame_files(opt, frames[i]), frame_start);
        status != 0)
      return status;
  }
  return renderer.checkpoint_failed ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string error;
  const auto options = inkray::parse_render_cli(argc, argv, &error);
  if (!options) {
    std::fprintf(stderr, "inkray-render: %s\n", error.c_str());
    return 2;
  }
  if (options->help) {
    std::fputs(inkray::kRenderCliHelp, stdout);
    return 0;
  }
  if (options->node_reference) {
    std::fputs(inkray::node_reference_markdown().c_str(), stdout);
    return 0;
  }
  try {
    return run(*options, inkray::Cancel::Clock::now());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inkray-render: %s\n", e.what());
    return 1;
  }
}
