// inkray-render: the headless renderer for final renders and render farms.
#include "app/render_cli.h"
#include "core/film/aov_display.h"
#include "core/film/resolve.h"
#include "core/image/image_io.h"
#include "core/render/batch_render.h"
#include "core/scene/compile.h"
#include "core/scene/json_io.h"

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

int run(const RenderCliOptions& opt) {
  SceneLoadResult loaded = load_scene(opt.scene);
  if (!loaded) {
    for (const auto& e : loaded.errors) std::fprintf(stderr, "error: %s\n", e.c_str());
    return 1;
  }
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
  const CompileResult compiled = compile_scene(desc);
  if (!compiled.scene) {
    for (const auto& e : compiled.errors) std::fprintf(stderr, "error: %s: %s\n", opt.scene.c_str(), e.c_str());
    return 1;
  }

  AovSet aovs;
  for (const auto& a : opt.aovs) aovs.add(*aov_from_name(a.name));
  RenderSession session(opt.threads.value_or(0));
  session.set_scene(compiled.scene, aovs);
  const BatchLimits limits{opt.spp.value_or(desc.render.spp), opt.time_seconds.value_or(desc.render.time_limit)};
  const bool progress = !opt.quiet && isatty(fileno(stderr));
  const auto history = render_batch(session, limits, [&](const RenderStats& s) {
    if (progress) print_progress(s, limits);
  });
  if (progress) std::fprintf(stderr, "\n");

  std::string error;
  if (!write_image(opt.output, resolve_final(session.film(), session.scene(), &session.pool()), &error)) {
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return 1;
  }
  for (const auto& a : opt.aovs) {
    const Aov aov = *aov_from_name(a.name);
    RgbImage img = session.film().resolve_aov(aov);
    if (image_format_of(a.file) == ImageFormat::png) img = aov_for_display(aov, img);
    if (!write_image(a.file, img, &error)) {
      std::fprintf(stderr, "error: %s\n", error.c_str());
      return 1;
    }
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
  try {
    return run(*options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inkray-render: %s\n", e.what());
    return 1;
  }
}
