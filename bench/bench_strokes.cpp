// inkray-bench-strokes: what painterly strokes cost. One fixed scene (a sphere,
// or the torus knot mesh, on a ground under a sun) with 0, 1k, 10k and 100k
// strokes sized to keep the object covered, and 150 big ones; per row: stroke
// build time (and its brush, placement and growth + mesh parts), the recompile
// after an edit elsewhere and after a repaint, triangles, stroke memory (mesh,
// alpha data, brush, roots and Embree's BVH), render time per spp at 960x540
// against the same scene without strokes, and the row's peak RSS. Each row runs
// in a process of its own, so its peak is its own.
#include "core/base/parallel.h"
#include "core/npr/strokes/brush.h"
#include "core/npr/strokes/stroke_color.h"
#include "core/npr/strokes/stroke_mesh.h"
#include "core/npr/strokes/stroke_placement.h"
#include "core/render/render_session.h"
#include "core/compiler/compile.h"
#include "core/document/json_io.h"
#include "bench/bench_stats.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace inkray;
using Clock = std::chrono::steady_clock;

struct Options {
  int threads = 2;                          // render threads
  int build_threads = 0;                    // stroke build threads; 0: one per hardware thread
  int passes = 5;                           // timed 1-spp passes per row (after one warm-up)
  int repeats = 3;                          // compiles per row; the median is reported
  bool mesh = false;                        // strokes on the torus knot instead of the sphere
  bool big = true;                          // a row of 150 big strokes after the counts
  std::filesystem::path scenes = "scenes";  // where meshes/torus_knot.obj lives
  std::vector<int> counts = {0, 1000, 10000, 100000};
  std::string row;  // set in a row's own process: "N" strokes or "big"
};

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

using bench::median;

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

constexpr double kMiB = 1024.0 * 1024.0;

// The scene, with `count` strokes whose size shrinks as 1/sqrt(count) so the
// painted object stays covered about twice over at every count; `big` puts
// scenes/strokes_150.json's 150 big strokes on it instead.
SceneDesc bench_scene(const Options& opt, int count, bool big) {
  const char* object =
      opt.mesh
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
                )") + object +
                           R"(],
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
    if (big) {
      e.width_min = 0.3f;
      e.width_max = 0.45f;
      e.length_min = 0.7f;
      e.length_max = 1.1f;
      e.flow = {0.35f, 1.f, 0.15f};
      e.rotation_jitter = 25.f;
      e.bristles = 14.f;
      e.pressure = 0.6f;
      e.segments = 12;
    } else {
      const float s = std::sqrt(1000.f / float(count));
      e.width_min = 0.06f * s;
      e.width_max = 0.1f * s;
      e.length_min = 0.2f * s;
      e.length_max = 0.4f * s;
    }
    desc.strokes.push_back(e);
  }
  return desc;
}

CompileResult compile_or_exit(ThreadBudget& build, SceneCompiler& compiler, const SceneDesc& desc,
                              double* seconds) {
  const auto t0 = Clock::now();
  CompileResult c = build.run([&] { return compiler.compile(desc); });
  *seconds = seconds_since(t0);
  if (!c.scene) {
    for (const auto& e : c.errors) std::fprintf(stderr, "error: %s\n", e.c_str());
    std::exit(1);
  }
  return c;
}

template <class T>
size_t bytes_of(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

struct StrokeMemory {
  size_t triangles = 0;
  size_t geometry = 0;  // ribbon meshes (every painted copy), alpha data, brush masks, roots
  size_t bvh = 0;       // Embree's BVHs over the ribbons
};

StrokeMemory stroke_memory(const RenderScene& scene, size_t roots) {
  StrokeMemory m;
  for (uint32_t i = 0; i < scene.world->geometry.shape_count(); ++i) {
    const AlphaMask* mask = scene.world->geometry.alpha_mask(i);
    if (!mask) continue;
    const ShapeBvh& bvh = scene.world->geometry.bvh(i);
    std::vector<const TriangleMesh*> meshes = {&std::get<TriangleMesh>(bvh.shape())};
    const auto& world = std::get<TriangleMesh>(scene.world->geometry.shape(i));
    if (&world != meshes[0]) meshes.push_back(&world);
    for (const TriangleMesh* mesh : meshes)
      m.geometry += bytes_of(mesh->positions) + bytes_of(mesh->normals) + bytes_of(mesh->uvs) +
                    bytes_of(mesh->colors) + bytes_of(mesh->indices);
    m.triangles += meshes[0]->triangle_count();
    m.geometry += mask->memory_bytes();
    if (const AlphaTexture* brush = scene.world->geometry.alpha_texture(i); brush != mask)
      m.geometry += brush->texels.capacity();
    m.bvh += bvh.bvh_bytes();
  }
  // The roots and each stroke's first vertex, kept for repainting (compile_strokes.cpp).
  m.geometry += roots * (sizeof(SurfacePoint) + sizeof(uint32_t));
  return m;
}

// The brush bake, placement and growth + meshing timed on their own, outside compile_scene.
void time_parts(const RenderScene& scene, const StrokeEmitterDesc& e, double* brush_s, double* place_s,
                double* grow_s, double* bvh_s) {
  uint32_t object = 0;
  while (scene.world->objects[object].name != e.object) ++object;
  std::string error;
  const auto surface = StrokeSurface::from_shape(scene.world->geometry.shape(object), &error);
  const auto tb = Clock::now();
  const auto mask = make_brush_mask(e, {}, &error);
  *brush_s = seconds_since(tb);
  const auto t0 = Clock::now();
  const std::vector<SurfacePoint> roots = place_roots(*surface, size_t(e.count), uint32_t(e.seed));
  *place_s = seconds_since(t0);
  const std::vector<Color> colors =
      stroke_colors(scene.world->materials, scene.world->objects[object].material, roots, e);
  const auto t1 = Clock::now();
  StrokeGeometry g = build_stroke_mesh(*surface, roots, colors, e);
  *grow_s = seconds_since(t1);
  auto alpha = std::make_shared<AlphaMask>(*mask);
  alpha->triangles = std::move(g.alpha);
  alpha->paint = true;
  const auto t2 = Clock::now();
  const ShapeBvh bvh(std::make_shared<const Shape>(std::move(g.mesh)), std::move(alpha));
  *bvh_s = seconds_since(t2);
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

// One row, in its own process: prints "row" and its figures on one line.
int run_row(const Options& opt) {
  const bool big = opt.row == "big";
  const int count = big ? 150 : std::atoi(opt.row.c_str());
  // Compiles (stroke build and BVH) and the timed parts run within this budget.
  ThreadBudget build(opt.build_threads);
  const SceneDesc desc = bench_scene(opt, count, big);
  std::vector<double> compiles, bases;
  // The parts on their own first, on the scene without strokes, so what they
  // build is gone before the scene with strokes is.
  double brush_s = 0.0, place_s = 0.0, grow_s = 0.0, bvh_s = 0.0;
  if (count > 0) {
    SceneCompiler bare;
    double s = 0.0;
    const auto base = compile_or_exit(build, bare, bench_scene(opt, 0, false), &s).scene;
    build.run([&] { time_parts(*base, desc.strokes.front(), &brush_s, &place_s, &grow_s, &bvh_s); });
  }
  // A fresh compiler and a new seed per repeat times a fresh build (the last
  // repeat's scene is let go first, so one is alive at a time); the last
  // compiler then times an edit elsewhere (the light) and a repaint (the paint).
  SceneDesc fresh = desc;
  std::unique_ptr<SceneCompiler> compiler;
  std::shared_ptr<const RenderScene> scene;
  for (int r = 0; r < opt.repeats; ++r) {
    double s = 0.0;
    if (count > 0) {
      SceneCompiler bare;
      compile_or_exit(build, bare, bench_scene(opt, 0, false), &s);
      bases.push_back(s);
    }
    for (StrokeEmitterDesc& e : fresh.strokes) e.seed = desc.strokes.front().seed + r;
    scene.reset();
    compiler = std::make_unique<SceneCompiler>();
    scene = compile_or_exit(build, *compiler, fresh, &s).scene;
    compiles.push_back(s);
  }
  const double build_s = count > 0 ? std::max(0.0, median(compiles) - median(bases)) : 0.0;
  const StrokeMemory memory = stroke_memory(*scene, size_t(count));
  const double spp_s = seconds_per_spp(scene, opt);
  const double peak = peak_rss_mib();  // building and rendering one scene
  double recompile_s = 0.0, repaint_s = 0.0;
  SceneDesc edited = fresh;
  std::get<DirectionalLightDesc>(edited.lights[0].data).intensity *= 1.01f;
  compile_or_exit(build, *compiler, edited, &recompile_s);
  edited.materials[1] = {"paint", DiffuseDesc{Color(0.2f, 0.4f, 0.8f)}, {}};
  compile_or_exit(build, *compiler, edited, &repaint_s);
  std::printf("row %s %.3f %.3f %.3f %.3f %.3f %.3f %.3f %zu %.4f %.4f %.4f %.3f\n",
              big ? "150big" : opt.row.c_str(), 1e3 * build_s, 1e3 * brush_s, 1e3 * place_s, 1e3 * grow_s,
              1e3 * bvh_s, 1e3 * recompile_s, 1e3 * repaint_s, memory.triangles,
              double(memory.geometry) / kMiB, double(memory.bvh) / kMiB, 1e3 * spp_s, peak);
  return 0;
}

struct Row {
  std::string name;
  double build = 0, brush = 0, place = 0, grow = 0, bvh_build = 0, recompile = 0, repaint = 0;
  size_t triangles = 0;
  double geometry = 0, bvh = 0, ms_per_spp = 0, peak = 0;
};

// Runs one row in a child process (this executable again) and reads its line.
bool child_row(const Options& opt, const std::string& row, Row* out) {
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  std::string command = "'" + self + "' --row " + row + " --threads " + std::to_string(opt.threads) +
                        " --build-threads " + std::to_string(opt.build_threads) + " --passes " +
                        std::to_string(opt.passes) + " --repeats " + std::to_string(opt.repeats) +
                        " --scenes '" + opt.scenes.string() + "'" + (opt.mesh ? " --mesh" : "");
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return false;
  char line[512];
  bool found = false;
  while (std::fgets(line, sizeof line, pipe)) {
    char name[64];
    if (std::sscanf(line, "row %63s %lf %lf %lf %lf %lf %lf %lf %zu %lf %lf %lf %lf", name, &out->build,
                    &out->brush, &out->place, &out->grow, &out->bvh_build, &out->recompile, &out->repaint,
                    &out->triangles, &out->geometry, &out->bvh, &out->ms_per_spp, &out->peak) == 13) {
      out->name = name;
      found = true;
    }
  }
  return pclose(pipe) == 0 && found;
}

int run(const Options& opt) {
  ThreadBudget budget(opt.build_threads);
  std::printf(
      "strokes on a %s at 960x540; render threads %d, stroke build threads %d, compile median of %d, "
      "render median of %d passes; each row in its own process\n\n",
      opt.mesh ? "torus knot mesh" : "sphere", opt.threads, budget.size(), opt.repeats, opt.passes);
  std::printf("%8s %9s %7s %7s %7s %7s %9s %8s %10s %9s %8s %9s %8s %7s %8s\n", "strokes", "build ms",
              "brush", "place", "grow", "bvh", "recompile", "repaint", "triangles", "geom MiB", "BVH MiB",
              "strk MiB", "ms/spp", "ratio", "peak MiB");
  std::vector<std::string> rows;
  for (int count : opt.counts) rows.push_back(std::to_string(count));
  if (opt.big) rows.push_back("big");
  double base_spp = 0.0;
  for (const std::string& name : rows) {
    Row r;
    if (!child_row(opt, name, &r)) {
      std::fprintf(stderr, "row %s failed\n", name.c_str());
      return 1;
    }
    if (name == "0") base_spp = r.ms_per_spp;
    const std::string ratio = base_spp > 0.0 ? std::to_string(r.ms_per_spp / base_spp).substr(0, 5) : "";
    std::printf("%8s %9.1f %7.1f %7.1f %7.1f %7.1f %9.1f %8.1f %10zu %9.2f %8.2f %9.2f %8.1f %7s %8.1f\n",
                r.name == "150big" ? "150 big" : r.name.c_str(), r.build, r.brush, r.place, r.grow,
                r.bvh_build, r.recompile, r.repaint, r.triangles, r.geometry, r.bvh, r.geometry + r.bvh,
                r.ms_per_spp, ratio.c_str(), r.peak);
    std::fflush(stdout);
  }
  std::printf(
      "\nbuild = compile - compile with 0 strokes (brush, placement, colours, growth, mesh, BVH); brush, "
      "place and grow (growth + ribbons) are timed again on their own; recompile = after a light edit, "
      "repaint = after an edit of the painted material; geom = ribbon mesh + alpha data + brush + roots, "
      "BVH = Embree's (memory monitor), strk = both; ratio = ms/spp over the 0 row's; peak = the row's "
      "process peak RSS over the parts, the builds and the render (before the recompiles)\n");
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
    "                            [--scenes DIR] [--counts 0,1000,10000,100000] [--no-big]\n"
    "Run from the repository root (or pass --scenes) when using --mesh. The 0 row is the ratio's base.\n";

// Applies option argv[i] (and its value, advancing i); false on an unknown
// option or a missing value.
bool apply_option(int argc, char** argv, int& i, Options& opt) {
  const std::string a = argv[i];
  if (a == "--mesh") return opt.mesh = true;
  if (a == "--no-big") return !(opt.big = false);
  if (i + 1 >= argc) return false;
  const char* value = argv[++i];
  if (a == "--threads")
    opt.threads = std::atoi(value);
  else if (a == "--build-threads")
    opt.build_threads = std::atoi(value);
  else if (a == "--passes")
    opt.passes = std::atoi(value);
  else if (a == "--repeats")
    opt.repeats = std::atoi(value);
  else if (a == "--scenes")
    opt.scenes = value;
  else if (a == "--counts")
    opt.counts = parse_counts(value);
  else if (a == "--row")
    opt.row = value;
  else
    return false;
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
  if (opt.threads < 1 || opt.build_threads < 0 || opt.passes < 1 || opt.repeats < 1 ||
      std::any_of(opt.counts.begin(), opt.counts.end(), [](int c) { return c < 0; })) {
    std::fprintf(stderr, "--threads, --passes and --repeats must be positive, counts not negative\n");
    return 2;
  }
  return opt.row.empty() ? run(opt) : run_row(opt);
}
