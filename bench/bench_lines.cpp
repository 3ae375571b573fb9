// inkray-bench-lines: what lines as strokes cost on one core. Synthetic chains over a
// 1920x1080 image (circles, S-curves and wandering lines, 15 to 190 pixels long) are
// styled with each preset (stroke_chains), drawn (draw_strokes) and outlined for the
// vector files (stroke_outline); per preset the median CPU milliseconds of each, the
// strokes made, their samples and the pixels they changed.
#include "bench/bench_stats.h"
#include "core/math/hash.h"
#include "core/document/line_set_desc.h"
#include "core/npr/lines/line_strokes.h"
#include "core/npr/lines/stroke_outline.h"
#include "core/npr/lines/stroke_raster.h"
#include "core/npr/strokes/brush.h"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace inkray;

constexpr int kWidth = 1920, kHeight = 1080;
constexpr float kPi = 3.14159265f;

// A chain along `point(t)` for t in [0, 1], points about a pixel apart.
template <typename Curve>
Chain traced(Curve point, float length, bool closed, Pcg32& rng) {
  Chain c;
  c.closed = closed;
  c.type = LineType(rng.next_u32() % uint32_t(kLineTypeCount));
  const int steps = std::max(4, int(length));
  // Attributes that vary smoothly along the chain, as a surface's do.
  const float depth = 2.f + 10.f * rng.next_float(), phase = 6.f * rng.next_float();
  for (int k = 0; k < (closed ? steps : steps + 1); ++k) {
    ChainPoint q;
    q.p = point(float(k) / float(steps));
    const float wave = 0.5f + 0.5f * std::sin(phase + float(k) / 15.f);
    q.opacity = 0.6f + 0.4f * wave;
    q.depth = depth + wave;
    q.light = wave;
    c.points.push_back(q);
  }
  return c;
}

std::vector<Chain> synthetic_chains(int count) {
  Pcg32 rng(7);
  std::vector<Chain> chains;
  for (int i = 0; i < count; ++i) {
    const Vec2 at(40.f + rng.next_float() * float(kWidth - 80),
                  40.f + rng.next_float() * float(kHeight - 80));
    const float size = 5.f + 25.f * rng.next_float();
    switch (i % 3) {
      case 0:
        chains.push_back(
            traced([&](float t) { return at + size * Vec2(std::cos(2 * kPi * t), std::sin(2 * kPi * t)); },
                   2.f * kPi * size, true, rng));
        break;
      case 1:
        chains.push_back(
            traced([&](float t) { return at + Vec2(size * std::sin(2 * kPi * t), 2.f * size * t); },
                   3.f * size, false, rng));
        break;
      default: {
        const float heading = 2.f * kPi * rng.next_float(), bend = rng.next_float() - 0.5f;
        chains.push_back(traced(
            [&](float t) {
              const float a = heading + 3.f * bend * t;
              return at + 4.f * size * t * Vec2(std::cos(a), std::sin(a));
            },
            4.f * size, false, rng));
      }
    }
  }
  return chains;
}

// This thread's CPU time, so other work on a shared machine does not count.
double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

}  // namespace

int main(int argc, char** argv) {
  int chains_count = 3000, runs = 5;
  std::string only;  // one preset, else all
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--chains") && i + 1 < argc) {
      chains_count = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--preset") && i + 1 < argc) {
      only = argv[++i];
    } else {
      std::fprintf(stderr, "usage: inkray-bench-lines [--chains N] [--runs N] [--preset NAME]\n");
      return 2;
    }
  }
  const std::vector<Chain> chains = synthetic_chains(chains_count);
  std::string error;
  const std::shared_ptr<const AlphaTexture> bristles = make_brush_mask(StrokeEmitterDesc{}, {}, &error);
  std::printf("%d chains, %dx%d, %d runs (medians, CPU ms of one thread)\n", chains_count, kWidth, kHeight,
              runs);
  std::printf(
      "| preset | strokes | samples | pixels drawn | stroke_chains | draw_strokes | stroke_outline |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  for (std::string_view name : kLinePresetNames) {
    if (!only.empty() && name != only) continue;
    LineSet set;
    set.name = std::string(name);
    LineSetStyleDesc preset;
    ParamPresets<LineSetStyleDesc>::apply(name, preset);
    static_cast<LineStyleParams&>(set.style) = preset;
    if (name == "brush") set.style.brush = bristles;
    std::vector<double> style_ms, draw_ms, outline_ms;
    size_t strokes_made = 0, samples = 0, drawn = 0;
    for (int run = 0; run < runs; ++run) {
      double t = cpu_ms();
      const std::vector<LineStroke> strokes = stroke_chains(chains, {set}, kHeight);
      style_ms.push_back(cpu_ms() - t);
      RgbImage image{kWidth, kHeight, std::vector<Color>(size_t(kWidth) * kHeight, Color(0.8f))};
      t = cpu_ms();
      draw_strokes(strokes, DisplayEncoding{}, image);
      draw_ms.push_back(cpu_ms() - t);
      drawn = size_t(std::count_if(image.pixels.begin(), image.pixels.end(),
                                   [](const Color& c) { return c != Color(0.8f); }));
      t = cpu_ms();
      size_t shapes = 0;
      for (const LineStroke& s : strokes) shapes += stroke_outline(s).size();
      outline_ms.push_back(cpu_ms() - t);
      strokes_made = strokes.size(), samples = 0;
      for (const LineStroke& s : strokes) samples += s.samples.size();
      if (shapes == 0 && !strokes.empty()) std::printf("(no outlines)\n");
    }
    std::printf("| %s | %zu | %zu | %zu | %.1f | %.1f | %.1f |\n", set.name.c_str(), strokes_made, samples,
                drawn, bench::median(style_ms), bench::median(draw_ms), bench::median(outline_ms));
  }
  return 0;
}
