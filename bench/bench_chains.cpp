// inkray-bench-chains: what drawing lines as strokes costs on a rendered film. Renders
// a scene (at --width x --height, --spp samples), then times, as medians of --runs:
// chaining its lines (film_chains), the image resolved with plain pixel lines, and the
// image resolved with the scene's line sets (chaining, styling and drawing), and
// prints the chains' count and length.
#include "bench/bench_scene.h"
#include "bench/bench_stats.h"
#include "core/compiler/compile.h"
#include "core/document/json_io.h"
#include "core/film/film_chains.h"
#include "core/film/resolve.h"
#include "core/render/batch_render.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace inkray;
  std::string scene_file = "scenes/lines_ink.json";
  int spp = 16, runs = 5, width = 1920, height = 1080, threads = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto next = [&] { return i + 1 < argc ? std::atoi(argv[++i]) : 0; };
    if (a == "--spp")
      spp = next();
    else if (a == "--runs")
      runs = next();
    else if (a == "--width")
      width = next();
    else if (a == "--height")
      height = next();
    else if (a == "--threads")
      threads = next();
    else if (a == "-h" || a == "--help") {
      std::printf(
          "usage: inkray-bench-chains [SCENE.json] [--width W] [--height H] [--spp N] [--runs N] [--threads "
          "N]\n");
      return 0;
    } else
      scene_file = a;
  }
  const std::shared_ptr<const RenderScene> scene = bench::compile_at_size_or_exit(scene_file, width, height);
  RenderSession session(threads);
  session.set_scene(scene);
  render_batch(session, {spp, 0.0});
  const Film& film = session.film();
  const ResolveSettings& styled = scene->resolve;
  ResolveSettings plain = styled;
  plain.sets.clear();

  std::vector<Chain> chains;
  const double chain_ms = bench::median_ms(runs, [&] { chains = film_chains(film, styled.material_paths); });
  double length = 0.0;
  for (const Chain& ch : chains) length += chain_length(ch);
  const double plain_ms = bench::median_ms(runs, [&] { resolve_final(film, plain); });
  const double styled_ms = bench::median_ms(runs, [&] { resolve_final(film, styled); });
  std::printf("%s at %dx%d, %d spp, %d sets, median of %d runs\n", scene_file.c_str(), width, height, spp,
              int(styled.sets.size()), runs);
  std::printf("chains: %zu, %.0f px long in all\n", chains.size(), length);
  std::printf("film_chains            %8.1f ms\n", chain_ms);
  std::printf("resolve, plain lines   %8.1f ms\n", plain_ms);
  std::printf("resolve, line sets     %8.1f ms\n", styled_ms);
  return 0;
}
