// inkray-bench-export: how an editor export scales with threads. Exports a scene
// through ExportJob (compile, render to the sample count, write a PNG) on one thread
// and on every hardware thread, interleaved, and prints each run's seconds (and of
// them the passes' part, the rest being the compile and the file), the medians and
// the speed-up. On a machine shared with other work the wall-clock speed-up says
// little, so it also prints the CPU seconds each export used: their ratio is the
// parallel efficiency, which free cores turn into a speed-up of threads x efficiency.
#include "core/document/json_io.h"
#include "core/render/export_job.h"
#include "bench/bench_stats.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

namespace {

using namespace inkray;
namespace fs = std::filesystem;

using bench::median;

struct Timing {
  double total = 0.0, passes = 0.0, cpu = 0.0;
};

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

Timing export_seconds(const SceneDesc& scene, int spp, int threads, const fs::path& output) {
  ExportRequest r;
  r.scene = scene;
  r.output = output;
  r.spp = spp;
  r.threads = threads;
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = cpu_seconds();
  ExportJob job(r);
  while (!job.done()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!job.error().empty()) {
    std::fprintf(stderr, "inkray-bench-export: %s\n", job.error().c_str());
    std::exit(1);
  }
  return {seconds, job.progress().render_seconds, cpu_seconds() - cpu0};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: inkray-bench-export SCENE.json [SPP=256] [RUNS=1] [WIDTH=800 HEIGHT=450]\n");
    return 2;
  }
  const int spp = argc > 2 ? std::atoi(argv[2]) : 256;
  const int runs = argc > 3 ? std::max(std::atoi(argv[3]), 1) : 1;
  const int width = argc > 5 ? std::atoi(argv[4]) : 800, height = argc > 5 ? std::atoi(argv[5]) : 450;
  const auto loaded = load_scene(argv[1]);
  if (!loaded.scene) {
    std::fprintf(stderr, "inkray-bench-export: %s\n",
                 loaded.errors.empty() ? argv[1] : loaded.errors.front().c_str());
    return 1;
  }
  SceneDesc scene = *loaded.scene;
  scene.render.width = width;
  scene.render.height = height;
  const int all = export_threads(false);
  const fs::path output =
      fs::temp_directory_path() / ("inkray_bench_export_" + std::to_string(::getpid()) + ".png");
  std::printf("%s at %dx%d, %d spp, 1 thread vs %d, %d interleaved run(s)\n", argv[1], width, height, spp,
              all, runs);
  std::fflush(stdout);
  std::vector<double> one, many, ratio, one_passes, many_passes, efficiency;
  for (int r = 0; r < runs; ++r) {  // interleaved, so drifts in the machine's speed hit both
    const Timing a = export_seconds(scene, spp, 1, output), b = export_seconds(scene, spp, all, output);
    one.push_back(a.total);
    many.push_back(b.total);
    one_passes.push_back(a.passes);
    many_passes.push_back(b.passes);
    ratio.push_back(a.total / b.total);
    efficiency.push_back(a.cpu / b.cpu);
    std::printf(
        "run %d: 1 thread %.2f s (passes %.2f s, CPU %.2f s), %d threads %.2f s (passes %.2f s, CPU %.2f s), "
        "speed-up %.2fx, CPU efficiency %.3f\n",
        r + 1, a.total, a.passes, a.cpu, all, b.total, b.passes, b.cpu, ratio.back(), efficiency.back());
    std::fflush(stdout);
  }
  std::printf(
      "median: 1 thread %.2f s (passes %.2f s), %d threads %.2f s (passes %.2f s), speed-up %.2fx, "
      "CPU efficiency %.3f\n",
      median(one), median(one_passes), all, median(many), median(many_passes), median(ratio),
      median(efficiency));
  std::error_code ec;
  fs::remove(output, ec);
  return 0;
}
