// inkray-bench-outlines: what outlines cost. Renders one scene with lines off
// (the outlines block removed), with every line type switched off but the
// block present (which must cost nothing), with the scene's lines with and
// without adaptive line sampling, and at several stencil qualities, and prints
// seconds per sample per pixel, rays per path and the overhead against lines off.
#include "core/render/batch_render.h"
#include "core/compiler/compile.h"
#include "core/document/json_io.h"
#include "bench/bench_stats.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace inkray {
namespace {

// Median seconds per pass over `runs` renders of `spp` passes each.
double seconds_per_spp(const SceneDesc& desc, int spp, int runs, int threads, uint64_t* rays) {
  const CompileResult c = compile_scene(desc);
  if (!c.scene) {
    std::fprintf(stderr, "error: %s\n", c.errors.front().c_str());
    std::exit(1);
  }
  std::vector<double> times;
  for (int r = 0; r < runs; ++r) {
    RenderSession session(threads);
    session.set_scene(c.scene);
    const auto start = std::chrono::steady_clock::now();
    render_batch(session, {spp, 0.0});
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / spp);
    *rays = session.stats().rays;
  }
  return bench::median(times);
}

}  // namespace
}  // namespace inkray

int main(int argc, char** argv) {
  using namespace inkray;
  std::string scene_file = "scenes/cornell_outlines.json";
  int spp = 8, runs = 3, threads = 0;
  bool all_qualities = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--spp" && i + 1 < argc)
      spp = std::atoi(argv[++i]);
    else if (a == "--runs" && i + 1 < argc)
      runs = std::atoi(argv[++i]);
    else if (a == "--threads" && i + 1 < argc)
      threads = std::atoi(argv[++i]);
    else if (a == "--default-only")
      all_qualities = false;
    else if (a == "-h" || a == "--help") {
      std::printf(
          "usage: inkray-bench-outlines [SCENE.json] [--spp N] [--runs N] [--threads N] [--default-only]\n");
      return 0;
    } else
      scene_file = a;
  }
  const SceneLoadResult loaded = load_scene(scene_file);
  if (!loaded) {
    for (const auto& e : loaded.errors) std::fprintf(stderr, "error: %s\n", e.c_str());
    return 1;
  }
  const SceneDesc base = *loaded.scene;
  std::printf("%s, %dx%d, %d spp, median of %d runs\n", scene_file.c_str(), base.render.width,
              base.render.height, spp, runs);
  std::printf("%-36s %12s %12s %10s\n", "configuration", "s/spp", "rays/path", "overhead");

  uint64_t rays = 0;
  SceneDesc off = base;
  off.outlines = OutlineDesc{};
  const double t_off = seconds_per_spp(off, spp, runs, threads, &rays);
  const double paths = double(base.render.width) * base.render.height * spp;
  auto row = [&](const char* name, double t) {
    std::printf("%-36s %12.4f %12.2f %9.1f%%\n", name, t, double(rays) / paths, 100.0 * (t / t_off - 1.0));
  };
  row("lines off", t_off);

  SceneDesc none = base;
  none.outlines.enabled = true;
  for (auto* style : {&none.outlines.silhouette, &none.outlines.object, &none.outlines.material,
                      &none.outlines.crease, &none.outlines.depth, &none.outlines.intersection})
    style->enabled = false;
  row("block present, no type on", seconds_per_spp(none, spp, runs, threads, &rays));

  for (const bool adaptive : {true, false}) {
    SceneDesc on = base;
    on.outlines.enabled = true;
    on.outlines.adaptive = adaptive;
    const double t = seconds_per_spp(on, spp, runs, threads, &rays);
    const std::string name = "scene's lines, quality " + std::to_string(on.outlines.quality) +
                             (adaptive ? ", adaptive" : ", every ray");
    row(name.c_str(), t);
  }
  if (all_qualities) {
    for (int q : {2, 4, 8}) {
      SceneDesc on = base;
      on.outlines.enabled = true;
      on.outlines.quality = q;
      const std::string name = "scene's lines, quality " + std::to_string(q) + ", adaptive";
      row(name.c_str(), seconds_per_spp(on, spp, runs, threads, &rays));
    }
  }
  return 0;
}
