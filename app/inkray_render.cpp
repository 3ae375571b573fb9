// inkray-render: the headless renderer for final renders and render farms.
#include "core/document/graph_reference.h"
#include "app/render_cli.h"
#include "core/film/resolve.h"
#include "core/render/batch_render.h"
#include "core/render/render_outputs.h"
#include "core/compiler/compile.h"
#include "core/document/json_io.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include <unistd.h>

namespace {

using namespace inkray;

void print_progress(const RenderStats& s, const BatchLimits& limits) {
  double frac = double(s.spp) / double(limits.spp);
  if (limits.time_seconds > 0.0) frac = std::max(frac, s.elapsed_seconds / limits.time_seconds);
  frac = std::min(frac, 1.0);
  const int width = 30, filled = int(frac * width + 0.5);
  std::fprintf(stderr, "\r[%.*s%*s] %3d%%  %u spp  %.1f s  error %.4f", filled, "##############################",
               width - filled, "", int(frac * 100.0 + 0.5), s.spp, s.elapsed_seconds, s.relative_error);
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

int write_scene_file(const SceneDesc& desc, const std::filesystem::path& file) {
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

// --time bounds the whole run: the clock starts before the scene is read, and reading,
// building, rendering and the painterly filter all stop at the deadline. Only the
// render itself ends in an image; any other phase cut short is an error that writes
// nothing (a half-built scene or half-filtered image would be a wrong render).
int run(const RenderCliOptions& opt, Cancel::Clock::time_point start) {
  const auto out_of_time = [&](double limit, const char* phase) {
    std::fprintf(stderr, "error: %s: the time limit of %g s ran out while %s (after %.1f s); nothing was written\n",
                 opt.scene.c_str(), limit, phase, seconds_since(start));
    return 1;
  };
  // Before the scene is read only --time is known; its render.time_limit applies after.
  const double cli_limit = opt.time_seconds.value_or(0.0);
  // --write-scene reads as the editor does: a scene that cannot render yet is still saved.
  const ReadFor purpose = opt.write_scene.empty() ? ReadFor::rendering : ReadFor::editing;
  SceneLoadResult loaded = load_scene(opt.scene, purpose, Cancel(nullptr, deadline_after(start, cli_limit)));
  if (loaded.cancelled) return out_of_time(cli_limit, "reading the scene");
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
  const double time_limit = opt.time_seconds.value_or(desc.render.time_limit);
  const Cancel deadline(nullptr, deadline_after(start, time_limit));
  CompileOptions options;
  options.cancel = deadline;
  options.memory_limit = opt.memory_limit.value_or(0);
  const CompileResult compiled = compile_scene(desc, options);
  if (compiled.cancelled) return out_of_time(time_limit, "building the scene");
  if (!compiled.scene) {
    for (const auto& e : compiled.errors) std::fprintf(stderr, "error: %s: %s\n", opt.scene.c_str(), e.c_str());
    return 1;
  }

  AovSet aovs;
  for (const auto& a : opt.aovs) aovs.add(*aov_from_name(a.name));
  RenderSession session(opt.threads.value_or(0));
  session.set_scene(compiled.scene, aovs);
  // The render gets what reading and building left of the time, less what the painterly
  // filter will need after it.
  double render_seconds = 0.0;
  if (time_limit > 0.0) {
    const double filter_seconds =
        1.25 * estimate_painterly_seconds(desc.render, desc.render.width, desc.render.height, &session.pool());
    render_seconds = time_limit - seconds_since(start) - filter_seconds;
    if (render_seconds <= 0.0) {
      std::fprintf(stderr,
                   "error: %s: the painterly filter alone takes about %.1f s at %dx%d, more than the time limit of "
                   "%g s leaves; nothing was written\n",
                   opt.scene.c_str(), filter_seconds / 1.25, desc.render.width, desc.render.height, time_limit);
      return 1;
    }
  }
  const BatchLimits limits{opt.spp.value_or(desc.render.spp), render_seconds};
  const bool progress = !opt.quiet && isatty(fileno(stderr));
  const auto history = render_batch(session, limits, [&](const RenderStats& s) {
    if (progress) print_progress(s, limits);
  });
  if (progress) std::fprintf(stderr, "\n");
  if (history.empty()) return out_of_time(time_limit, "rendering the first sample of every pixel");

  // Every output is staged before any is replaced: a failed AOV leaves no image behind.
  std::vector<AovFile> aov_files;
  for (const auto& a : opt.aovs) aov_files.push_back({*aov_from_name(a.name), a.file});
  std::string error;
  switch (write_render_outputs(session, opt.output, aov_files, &error, deadline)) {
    case OutputsWritten::all: break;
    case OutputsWritten::cancelled: return out_of_time(time_limit, "applying the painterly filter");
    case OutputsWritten::failed: std::fprintf(stderr, "error: %s\n", error.c_str()); return 1;
  }
  if (!opt.quiet) {
    print_table(history);
    const RenderStats& s = session.stats();
    std::printf("%s: %dx%d, %u spp, %.3f s, %d threads, %.2f M rays/s, %.2f M paths/s", opt.output.c_str(),
                desc.render.width, desc.render.height, s.spp, s.elapsed_seconds, session.threads(),
                double(s.rays) / s.elapsed_seconds * 1e-6, double(s.paths) / s.elapsed_seconds * 1e-6);
    if (s.nonfinite_samples) std::printf(", %llu non-finite samples dropped", (unsigned long long)s.nonfinite_samples);
    std::printf("\n");
  }
  return 0;
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
