// inkray-bench-strokes: what painterly strokes cost. One fixed scene (a sphere,
// or the torus knot mesh, on a ground under a sun) with 0, 1k, 10k and 100k
// strokes sized to keep the object covered; per count: stroke build time (and
// its placement and growth + mesh parts), triangles, stroke geometry memory,
// render time per spp at 960x540 and peak RSS.
#include "core/base/parallel.h"
#include "core/npr/strokes/brush.h"
#include "core/npr/strokes/stroke_color.h"
#include "core/npr/strokes/stroke_mesh.h"
#include "core/npr/strokes/stroke_placement.h"
#include "core/render/render_session.h"
#include "core/compiler/compile.h"
#include "core/document/json_io.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace inkray;
using Clock = std::chrono::steady_clock;

struct Options {
  int threads = 2;        // render threads
  int build_threads = 0;  // stroke build threads; 0: one per hardware thread
  int passes = 5;         // timed 1-spp passes per count (after one warm-up)
  int repeats = 3;        // compiles per count; the median is reported
  bool mesh = false;      // strokes on the torus knot instead of the sphere
  std::filesystem::path scenes = "scenes";  // where meshes/torus_knot.obj lives
  std::vector<int> counts = {0, 1000, 10000, 100000};
};

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

// The scene, with `count` strokes whose size shrinks as 1/sqrt(count) so the
// painted object stays covered about twice over at every count.
SceneDesc bench_scene(const Options& opt, int count) {
  const char* object = opt.mesh
      ? R"({"name": "thing", "material": "paint", "shape": {"type": "mesh", "path": "meshes/torus_knot.obj"},
           "transform": {"scale": [0.45, 0.45, 0.45], "rotate": [{"axis": [1, 0, 0], "degrees": 90}], "translate": [0, 1.1, 0]}})"
      : R"({"name": "thing", "material": "paint", "shape": {"type": "sphere", "center": [0, 1, 0], "radius": 1}})";
  const std::string text = std::string(R"({
    "format": "inkray-scene", "version": 1,
    "camera": {"look_from": [0, 2, 5.5], "look_at": [0, 1, 0], "vfov": 32},
    "render": {"width": 960, "height": 540, "spp": 1, "max_depth": 6},
    "environment": {"type": "gradient", "zenith": [0.3, 0.4, 0.6], "horizon": [0.7, 0.68, 0.65], "nadir": [0.2, 0.2, 0.2]},
    "materials": [{"name": "ground", "type": "diffuse", "albedo": [0.4, 0.4, 0.38]},
                  {"name": "paint", "type": "diffuse", "albedo": [0.8, 0.35, 0.12]}],
    "objects": [{"name": "ground", "material": "ground",
                 "shape": {"type": "quad", "corner": [-8, 0, -8], "edge_u": [0, 0, 16], "edge_v": [16, 0, 0]}},
                )") + object + R"(],
    "lights": [{"name": "sun", "type": "directional", "direction": [-0.5, -1, -0.6], "intensity": 2.5}]
  })";
  const SceneLoadResult loaded = parse_scene(text, opt.scenes, "bench scene");
  if (!loaded) {
    for (const auto& e : loaded.errors) std::fprintf(stderr, "error: %s\n", e.c_str());
    std::exit(1);
  }
  SceneDesc desc = *loaded.scene;
  if (count > 0) {
    StrokeEmitterDesc e;
    e.name = "strokes";
    e.object = "thing";
    e.count = count;
    const float s = std::sqrt(1000.f / float(count));
    e.width_min = 0.06f * s;
    e.width_max = 0.1f * s;
    e.length_min = 0.2f * s;
    e.length_max = 0.4f * s;
    desc.strokes.push_back(e);
  }
  return desc;
}

std::shared_ptr<const RenderScene> compile_or_exit(ThreadBudget& build, const SceneDesc& desc, double* seconds) {
  const auto t0 = Clock::now();
  CompileResult c = build.run([&] { return compile_scene(desc); });
  *seconds = seconds_since(t0);
  if (!c.scene) {
    for (const auto& e : c.errors) std::fprintf(stderr, "error: %s\n", e.c_str());
    std::exit(1);
  }
  return c.scene;
}

template <class T> size_t bytes_of(const std::vector<T>& v) { return v.capacity() * sizeof(T); }

size_t stroke_bytes(const RenderScene& scene, size_t* triangles) {
  size_t bytes = 0;
  *triangles = 0;
  for (uint32_t i = 0; i < scene.geometry.shape_count(); ++i) {
    const AlphaMask* mask = scene.geometry.alpha_mask(i);
    if (!mask) continue;
    const auto& m = std::get<TriangleMesh>(scene.geometry.shape(i));
    *triangles += m.triangle_count();
    bytes += bytes_of(m.positions) + bytes_of(m.normals) + bytes_of(m.uvs) + bytes_of(m.colors) +
             bytes_of(m.indices) + mask->memory_bytes();
  }
  return bytes;
}

// The brush bake, placement and growth + meshing timed on their own, outside compile_scene.
void time_parts(const RenderScene& scene, const StrokeEmitterDesc& e, double* brush_s, double* place_s,
                double* grow_s) {
  uint32_t object = 0;
  while (scene.objects[object].name != e.object) ++object;
  std::string error;
  const auto surface = StrokeSurface::from_shape(scene.geometry.shape(object), &error);
  const auto tb = Clock::now();
  const auto mask = make_brush_mask(e, {}, &error);
  *brush_s = seconds_since(tb);
  const auto t0 = Clock::now();
  const std::vector<SurfacePoint> roots = place_roots(*surface, size_t(e.count), uint32_t(e.seed));
  *place_s = seconds_since(t0);
  const std::vector<Color> colors = stroke_colors(scene.materials, scene.objects[object].material, roots, e);
  const auto t1 = Clock::now();
  const StrokeGeometry g = build_stroke_mesh(*surface, roots, colors, e);
  *grow_s = seconds_since(t1);
}

double seconds_per_spp(const std::shared_ptr<const RenderScene>& scene, const Options& opt) {
  RenderSession session(opt.threads);
  session.set_scene(scene);
  session.render_pass();  // warm-up: first touches of the film and the BVH
  std::vector<double> times;
  for (int p = 0; p < opt.passes; ++p) {
    const auto t0 = Clock::now();
    session.render_pass();
    times.push_back(seconds_since(t0));
  }
  return median(times) / std::max(1u, session.stats().spp / session.stats().passes);
}

int run(const Options& opt) {
  // Compiles (stroke build and BVH) and the timed parts run within this budget.
  ThreadBudget build(opt.build_threads);
  std::printf("strokes on a %s at 960x540; render threads %d, stroke build threads %d, compile median of %d, "
              "render median of %d passes\n\n",
              opt.mesh ? "torus knot mesh" : "sphere", opt.threads, build.size(), opt.repeats, opt.passes);
  std::printf("%8s %10s %10s %10s %10s %10s %10s %10s %10s %10s %10s\n", "strokes", "build ms", "brush ms",
              "place ms", "grow ms", "compile ms", "recompile", "triangles", "geom MiB", "ms/spp", "peak MiB");
  double base_compile = 0.0;
  for (int count : opt.counts) {
    const SceneDesc desc = bench_scene(opt, count);
    std::vector<double> compiles;
    std::shared_ptr<const RenderScene> scene;
    // Compiles keep the strokes they built for the next compile of the same
    // emitter (compile_strokes.cpp); a new seed per repeat times a fresh build,
    // and one more compile of the same document times the edit-elsewhere case.
    SceneDesc fresh = desc;
    for (int r = 0; r < opt.repeats; ++r) {
      for (StrokeEmitterDesc& e : fresh.strokes) e.seed = desc.strokes.empty() ? 0 : desc.strokes.front().seed + r;
      double s = 0.0;
      scene = compile_or_exit(build, fresh, &s);
      compiles.push_back(s);
    }
    double recompile_s = 0.0;
    scene = compile_or_exit(build, fresh, &recompile_s);
    const double compile_s = median(compiles);
    if (count == 0) base_compile = compile_s;
    double brush_s = 0.0, place_s = 0.0, grow_s = 0.0;
    if (count > 0) build.run([&] { time_parts(*scene, desc.strokes.front(), &brush_s, &place_s, &grow_s); });
    size_t triangles = 0;
    const size_t bytes = stroke_bytes(*scene, &triangles);
    const double spp_s = seconds_per_spp(scene, opt);
    std::printf("%8d %10.1f %10.1f %10.1f %10.1f %10.1f %10.1f %10zu %10.2f %10.1f %10.1f\n", count,
                1e3 * std::max(0.0, compile_s - base_compile), 1e3 * brush_s, 1e3 * place_s, 1e3 * grow_s, 1e3 * compile_s,
                1e3 * recompile_s,
                triangles, double(bytes) / (1024.0 * 1024.0), 1e3 * spp_s, peak_rss_mib());
    std::fflush(stdout);
  }
  std::printf("\nbuild = compile - compile with 0 strokes (brush, placement, colours, growth, mesh, BVH); brush, "
              "place and grow are timed again on their own; geom = stroke mesh + brush mask; peak = process peak RSS so far\n");
  return 0;
}

std::vector<int> parse_counts(std::string list) {
  std::vector<int> counts;
  while (!list.empty()) {
    const size_t comma = list.find(',');
    counts.push_back(std::atoi(list.substr(0, comma).c_str()));
    list = comma == std::string::npos ? "" : list.substr(comma + 1);
  }
  return counts;
}

constexpr const char* kUsage =
    "usage: inkray-bench-strokes [--threads N] [--build-threads N] [--passes N] [--repeats N] [--mesh]\n"
    "                            [--scenes DIR] [--counts 0,1000,10000,100000]\n"
    "Run from the repository root (or pass --scenes) when using --mesh.\n";

// Applies option argv[i] (and its value, advancing i); false on an unknown
// option or a missing value.
bool apply_option(int argc, char** argv, int& i, Options& opt) {
  const std::string a = argv[i];
  if (a == "--mesh") return opt.mesh = true;
  if (i + 1 >= argc) return false;
  const char* value = argv[++i];
  if (a == "--threads") opt.threads = std::atoi(value);
  else if (a == "--build-threads") opt.build_threads = std::atoi(value);
  else if (a == "--passes") opt.passes = std::atoi(value);
  else if (a == "--repeats") opt.repeats = std::atoi(value);
  else if (a == "--scenes") opt.scenes = value;
  else if (a == "--counts") opt.counts = parse_counts(value);
  else return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "-h" || std::string(argv[i]) == "--help") {
      std::printf("%s", kUsage);
      return 0;
    }
    if (!apply_option(argc, argv, i, opt)) {
      std::fprintf(stderr, "bad option %s\n%s", argv[i], kUsage);
      return 2;
    }
  }
  if (opt.threads < 1 || opt.build_threads < 0 || opt.passes < 1 || opt.repeats < 1 || opt.counts.empty() ||
      std::any_of(opt.counts.begin(), opt.counts.end(), [](int c) { return c < 0; })) {
    std::fprintf(stderr, "--threads, --passes and --repeats must be positive, counts not negative\n");
    return 2;
  }
  return run(opt);
}
