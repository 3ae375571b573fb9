// inkray-bench-bands: are toon bands settled at a few samples? Renders each scene's
// toon_band AOV (per pixel, the mean over its samples of the band a toon surface shows)
// at --spp and at --reference-spp, and prints the share of toon pixels where the two
// agree within --tolerance band units. Pixels at an object's edge (a 3x3 neighbourhood
// with another object, or a pixel whose samples saw several) are left out: their mean
// mixes surfaces at any sample count. Where the light level is estimated by sampling
// (area lights, the sky), a per-sample band is noise at few samples, and its mean
// converges to a blend rather than a band.
#include "bench/bench_scene.h"
#include "core/compiler/compile.h"
#include "core/film/film.h"
#include "core/render/batch_render.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using namespace inkray;

struct Bands {
  RgbImage band, ids;
};

Bands render_bands(const std::shared_ptr<const RenderScene>& scene, int spp, int threads) {
  AovSet aovs;
  aovs.add(Aov::toon_band);
  aovs.add(Aov::object_id);
  RenderSession session(threads);
  session.set_scene(scene, aovs);
  render_batch(session, {spp, 0.0});
  return {session.film().resolve_aov(Aov::toon_band), session.film().resolve_aov(Aov::object_id)};
}

// One object's inside: the pixel and its 8 neighbours saw the same single object.
bool inside_one_object(const RgbImage& ids, int x, int y) {
  const float id = ids.pixels[size_t(y) * size_t(ids.width) + size_t(x)].r;
  if (id < 0.f) return false;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int u = x + dx, v = y + dy;
      if (u < 0 || v < 0 || u >= ids.width || v >= ids.height) return false;
      if (ids.pixels[size_t(v) * size_t(ids.width) + size_t(u)].r != id) return false;
    }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> scenes;
  int width = 320, height = 180, spp = 8, reference_spp = 1024, threads = 0;
  float tolerance = 0.1f;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto next = [&] { return i + 1 < argc ? argv[++i] : "0"; };
    if (a == "--width")
      width = std::atoi(next());
    else if (a == "--height")
      height = std::atoi(next());
    else if (a == "--spp")
      spp = std::atoi(next());
    else if (a == "--reference-spp")
      reference_spp = std::atoi(next());
    else if (a == "--threads")
      threads = std::atoi(next());
    else if (a == "--tolerance")
      tolerance = float(std::atof(next()));
    else if (a == "-h" || a == "--help") {
      std::printf(
          "usage: inkray-bench-bands [SCENE.json...] [--width W] [--height H] [--spp N] [--reference-spp N]\n"
          "                          [--tolerance T] [--threads N]\n"
          "default scenes: scenes/toon.json scenes/graph_toon_rim.json scenes/cad_creases.json\n");
      return 0;
    } else {
      scenes.push_back(a);
    }
  }
  if (scenes.empty()) scenes = {"scenes/toon.json", "scenes/graph_toon_rim.json", "scenes/cad_creases.json"};

  std::printf("%d spp against %d spp, %dx%d, agreement within %.2f band units\n", spp, reference_spp, width,
              height, double(tolerance));
  std::printf("%-32s %12s %12s %10s\n", "scene", "toon pixels", "agreeing", "share");
  for (const std::string& file : scenes) {
    const std::shared_ptr<const RenderScene> scene = bench::compile_at_size_or_exit(file, width, height);
    const Bands low = render_bands(scene, spp, threads);
    const Bands reference = render_bands(scene, reference_spp, threads);
    size_t counted = 0, agreeing = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const size_t i = size_t(y) * size_t(width) + size_t(x);
        if (reference.band.pixels[i].r < 0.f || !inside_one_object(reference.ids, x, y)) continue;
        ++counted;
        agreeing += std::abs(low.band.pixels[i].r - reference.band.pixels[i].r) <= tolerance;
      }
    std::printf("%-32s %12zu %12zu %9.2f%%\n", file.c_str(), counted, agreeing,
                counted ? 100.0 * double(agreeing) / double(counted) : 0.0);
  }
  return 0;
}
