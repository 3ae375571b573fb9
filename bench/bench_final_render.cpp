// inkray-bench-final: what splitting a final render costs. Renders a still once,
// then as scripts/farm splits it (the line decisions written once, K sample slices
// reading them, inkray-merge), and prints the CPU time (user + sys, from wait4) of
// each and the overhead; then renders an animation's frames
// and prints frames per hour. Runs the inkray-render and inkray-merge built next
// to it, as a render farm would.
#include "bench/bench_stats.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <spawn.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

extern char** environ;

namespace {

namespace fs = std::filesystem;

struct Usage {
  double cpu = 0.0;   // user + sys seconds
  double wall = 0.0;  // seconds
  Usage& operator+=(const Usage& o) {
    cpu += o.cpu;
    wall += o.wall;
    return *this;
  }
};

// Runs one program to its end; exits on failure.
Usage run(const fs::path& program, const std::vector<std::string>& args) {
  std::vector<std::string> all = {program.string()};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) {
    std::fprintf(stderr, "error: cannot run %s\n", argv[0]);
    std::exit(1);
  }
  int status = 0;
  rusage ru{};
  wait4(pid, &status, 0, &ru);
  Usage u;
  u.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  u.cpu = double(ru.ru_utime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec) + double(ru.ru_stime.tv_sec) +
          1e-6 * double(ru.ru_stime.tv_usec);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::string line;
    for (const std::string& a : all) line += a + " ";
    std::fprintf(stderr, "error: failed: %s\n", line.c_str());
    std::exit(1);
  }
  return u;
}

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

using inkray::bench::median;

}  // namespace

int main(int argc, char** argv) {
  std::string scene = "scenes/cornell_outlines.json", frame_scene;
  int width = 600, height = 600, spp = 256, slices = 4, threads = 2, runs = 1;
  int frames = 4, frame_spp = 16, frame_width = 960, frame_height = 540;
  const std::pair<std::string_view, int*> numbers[] = {
      {"--width", &width},     {"--height", &height}, {"--spp", &spp},       {"--slices", &slices},
      {"--threads", &threads}, {"--runs", &runs},     {"--frames", &frames}, {"--frame-spp", &frame_spp}};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto number =
        std::find_if(std::begin(numbers), std::end(numbers), [&](const auto& n) { return n.first == a; });
    if (number != std::end(numbers))
      *number->second = i + 1 < argc ? std::atoi(argv[++i]) : 0;
    else if (a == "--frame-scene" && i + 1 < argc)
      frame_scene = argv[++i];
    else if (a == "-h" || a == "--help") {
      std::printf(
          "usage: inkray-bench-final [SCENE.json] [--width W] [--height H] [--spp N] [--slices K]\n"
          "       [--threads T] [--runs N] [--frames F] [--frame-spp N] [--frame-scene SCENE.json]\n"
          "A still as one run and as K slices + inkray-merge (CPU time, user + sys), then F frames\n"
          "at 960x540 of the frame scene (default: SCENE) with --frames (frames per hour).\n");
      return 0;
    } else
      scene = a;
  }
  if (frame_scene.empty()) frame_scene = scene;
  if (slices < 1 || spp < slices || runs < 1 || frames < 1) {
    std::fprintf(stderr, "error: need 1 <= slices <= spp, runs >= 1, frames >= 1\n");
    return 2;
  }
  const fs::path bin = fs::read_symlink("/proc/self/exe").parent_path();
  const fs::path render = bin / "inkray-render", merge = bin / "inkray-merge";
  const fs::path work = fs::temp_directory_path() / ("inkray-bench-final-" + std::to_string(getpid()));
  fs::create_directories(work);
  const std::vector<std::string> common = {scene,
                                           "--width",
                                           std::to_string(width),
                                           "--height",
                                           std::to_string(height),
                                           "--threads",
                                           std::to_string(threads),
                                           "-q"};
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = common;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };

  std::printf("%s at %dx%d, %d spp, %d threads; %d slices; median of %d runs\n", scene.c_str(), width, height,
              spp, threads, slices, runs);
  std::vector<double> one_cpu, one_wall, split_cpu, split_wall, decide_cpu, merge_cpu;
  bool identical = true;
  for (int r = 0; r < runs; ++r) {
    const Usage one = run(render, with({"--spp", std::to_string(spp), "-o", (work / "one.png").string()}));
    one_cpu.push_back(one.cpu);
    one_wall.push_back(one.wall);
    const fs::path decisions = work / "line_decisions.bin";
    Usage split = slices > 1 ? run(render, with({"--decide-lines", decisions.string()})) : Usage{};
    decide_cpu.push_back(split.cpu);
    std::vector<std::string> merge_args = {(work / "merged.png").string(), "-q"};
    for (int k = 0; k < slices; ++k) {
      const int a = spp * k / slices, b = spp * (k + 1) / slices;
      const fs::path part = work / ("slice_" + std::to_string(k) + ".exr");
      std::vector<std::string> args = {"--samples", std::to_string(a), std::to_string(b), "-o",
                                       part.string()};
      if (a > 0) args.insert(args.end(), {"--line-decisions", decisions.string()});
      split += run(render, with(args));
      merge_args.push_back(part.string());
    }
    const Usage merged = run(merge, merge_args);
    merge_cpu.push_back(merged.cpu);
    split += merged;
    split_cpu.push_back(split.cpu);
    split_wall.push_back(split.wall);
    identical = identical && bytes_of(work / "one.png") == bytes_of(work / "merged.png");
  }
  const double overhead = median(split_cpu) / median(one_cpu) - 1.0;
  std::printf("%-28s %10s %10s\n", "", "CPU s", "wall s");
  std::printf("%-28s %10.2f %10.2f\n", "one run", median(one_cpu), median(one_wall));
  std::printf("%-28s %10.2f %10.2f\n", "slices + merge", median(split_cpu), median(split_wall));
  std::printf("%-28s %10.2f\n", "  of which line decisions", median(decide_cpu));
  std::printf("%-28s %10.2f\n", "  of which inkray-merge", median(merge_cpu));
  std::printf("CPU overhead of %d slices: %+.1f%% (target: at most +5%%); merged PNG %s the one run's\n",
              slices, 100.0 * overhead, identical ? "is byte for byte" : "DIFFERS from");

  // Frames: one process for them all, as a farm task with --chunk does.
  std::vector<double> frame_wall, frame_cpu;
  for (int r = 0; r < runs; ++r) {
    const Usage u = run(render, {frame_scene, "--width", std::to_string(frame_width), "--height",
                                 std::to_string(frame_height), "--threads", std::to_string(threads), "-q",
                                 "--spp", std::to_string(frame_spp), "--frames",
                                 "1-" + std::to_string(frames), "-o", (work / "frame_####.png").string()});
    frame_wall.push_back(u.wall);
    frame_cpu.push_back(u.cpu);
  }
  const double per_frame = median(frame_wall) / double(frames);
  std::printf(
      "%s: %d frames at %dx%d, %d spp, %d threads: %.2f s a frame (CPU %.2f s), %.0f frames per hour\n",
      frame_scene.c_str(), frames, frame_width, frame_height, frame_spp, threads, per_frame,
      median(frame_cpu) / double(frames), 3600.0 / per_frame);
  fs::remove_all(work);
  return 0;
}
