// inkray-bench: render a scene for a while and print error against time
// (RMSE against a cached converged reference), ray rates beside Embree's bare
// rate for the same kind of rays, thread scaling, AOV cost and peak memory.
#include "core/geometry/embree_scene.h"
#include "core/image/image_io.h"
#include "core/render/batch_render.h"
#include "core/sampling/sampler.h"
#include "core/sampling/warp.h"
#include "core/math/frame.h"
#include "core/compiler/compile.h"
#include "core/film/denoise.h"
#include "core/document/json_io.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

namespace {

using namespace inkray;
using Clock = std::chrono::steady_clock;

struct Options {
  std::filesystem::path scene = "scenes/cornell.json";
  double seconds = 8.0;
  int threads = 2;
  int reference_spp = 8192;
  std::filesystem::path cache = "bench/cache";
  bool scaling = true;
  bool denoise = false;   // --denoise: also the denoised image's error at every checkpoint
  double adaptive = 0.0;  // --adaptive E: adaptive sampling at threshold E
};

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// RMSE over pixels and channels of two images, as a display shows them:
// clamped to [0,1] and sRGB-encoded (the PNG a person looks at).
double rmse_display(const RgbImage& a, const RgbImage& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(linear_to_srgb(a.pixels[i][c])) - double(linear_to_srgb(b.pixels[i][c]));
      sum += d * d;
    }
  return std::sqrt(sum / double(3 * a.pixels.size()));
}
// The same on linear values clamped to [0,1].
double rmse_linear(const RgbImage& a, const RgbImage& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d =
          std::clamp(double(a.pixels[i][c]), 0.0, 1.0) - std::clamp(double(b.pixels[i][c]), 0.0, 1.0);
      sum += d * d;
    }
  return std::sqrt(sum / double(3 * a.pixels.size()));
}

RgbImage reference_image(const Options& opt, const std::shared_ptr<const RenderScene>& scene) {
  const auto& s = scene->sampling;
  std::filesystem::create_directories(opt.cache);
  const auto file = opt.cache / (opt.scene.stem().string() + "-" + std::to_string(s.width) + "x" +
                                 std::to_string(s.height) + "-" + std::to_string(opt.reference_spp) +
                                 "spp-seed" + std::to_string(s.seed) + ".pfm");
  RgbImage ref;
  std::string error;
  if (std::filesystem::exists(file) && read_pfm(file, &ref, &error)) {
    std::printf("reference: %s (cached)\n", file.c_str());
    return ref;
  }
  std::printf("reference: rendering %d spp into %s ...\n", opt.reference_spp, file.c_str());
  std::fflush(stdout);
  RenderSession session(opt.threads);
  const auto t0 = Clock::now();
  session.set_scene(scene);
  render_batch(session, {opt.reference_spp, 0.0});
  ref = session.film().resolve();
  if (!write_image(file, ref, &error)) std::fprintf(stderr, "warning: %s\n", error.c_str());
  std::printf("reference: %.1f s\n", seconds_since(t0));
  return ref;
}

// Embree alone on the same kind of rays a diffuse path tracer traces: camera
// rays, cosine-distributed bounces and one shadow ray per bounce towards a
// random scene point. Returns rays per second.
double bare_embree_rate(const RenderScene& scene, int threads, double seconds) {
  ThreadBudget pool(threads);
  const int w = scene.sampling.width, h = scene.sampling.height;
  std::vector<uint64_t> rays(size_t(pool.size()), 0);
  const auto t0 = Clock::now();
  uint32_t pass = 0;
  while (seconds_since(t0) < seconds) {
    pool.parallel_for(h, [&](int y, int worker) {
      uint64_t count = 0;
      for (int x = 0; x < w; ++x) {
        const Sampler sampler(uint32_t(x), uint32_t(y), pass, 77);
        Ray ray = scene.camera.generate_ray(Vec2(float(x) + 0.5f, float(y) + 0.5f), Vec2(0.5f));
        for (int depth = 0; depth < 5; ++depth) {
          Hit hit;
          ++count;
          if (!scene.world->geometry.intersect(ray, kInfinity, &hit)) break;
          const SurfaceInteraction si = scene.world->geometry.interaction(ray, hit);
          const Normal3 n = glm::dot(si.ng, ray.d) < 0.f ? si.ng : -si.ng;
          const Frame frame = Frame::from_z(n);
          const Point3 target = scene.world->scene_center +
                                0.3f * scene.world->scene_radius *
                                    sample_uniform_sphere(sampler.get_pair(2 + 2 * uint32_t(depth)));
          ++count;
          scene.world->geometry.occluded(spawn_ray_to(si.p, si.p_error, n, target, Vec3(0.f), Vec3(0.f)),
                                         kShadowTMax);
          ray =
              spawn_ray(si.p, si.p_error, n,
                        frame.to_world(sample_cosine_hemisphere(sampler.get_pair(3 + 2 * uint32_t(depth)))));
        }
      }
      rays[size_t(worker)] += count;
    });
    ++pass;
  }
  uint64_t total = 0;
  for (uint64_t r : rays) total += r;
  return double(total) / seconds_since(t0);
}

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

double time_for_spp(const std::shared_ptr<const RenderScene>& scene, int threads, int spp, AovSet aovs = {}) {
  RenderSession session(threads);
  session.set_scene(scene, aovs);
  render_batch(session, {spp, 0.0});
  return session.stats().elapsed_seconds;
}

int run(const Options& opt) {
  auto loaded = load_scene(opt.scene);
  if (!loaded) {
    for (const auto& e : loaded.errors) std::fprintf(stderr, "error: %s\n", e.c_str());
    return 1;
  }
  SceneDesc desc = *loaded.scene;
  const auto t_compile = Clock::now();
  const CompileResult compiled = compile_scene(desc);
  if (!compiled.scene) {
    for (const auto& e : compiled.errors) std::fprintf(stderr, "error: %s\n", e.c_str());
    return 1;
  }
  std::printf("scene: %s, %dx%d, compiled in %.1f ms, %d threads\n", opt.scene.c_str(), desc.render.width,
              desc.render.height, 1e3 * seconds_since(t_compile), opt.threads);

  // The reference uses another seed, so its noise is independent of the measured render's.
  SceneDesc ref_desc = desc;
  ref_desc.render.seed = desc.render.seed + 1000;
  const RgbImage reference = reference_image(opt, compile_scene(ref_desc).scene);

  RenderSession session(opt.threads);
  session.set_scene(compiled.scene, opt.denoise ? denoise_aovs() : AovSet{});
  if (opt.adaptive > 0.0) session.set_adaptive({opt.adaptive, 16});
  const double pixels = double(desc.render.width) * double(desc.render.height);
  std::printf("\n%10s %8s %12s %12s %14s %14s %12s", "seconds", "spp", "Mpaths/s", "Mrays/s", "RMSE display",
              "RMSE linear", "est. error");
  if (opt.denoise)
    std::printf(" %10s %14s %14s %12s %14s %14s", "denoise s", "RMSE disp. dn", "RMSE lin. dn", "est. dn",
                "edge RMSE raw", "edge RMSE dn");
  std::printf("\n");
  // Pixels within 2 of an object id edge or a toon band edge (of 16 passes of first hits):
  // where a denoiser that blurred across ids or bands would show.
  std::vector<uint8_t> near_edge;
  if (opt.denoise) {
    RenderSession edges(opt.threads);
    AovSet a;
    a.add(Aov::object_id);
    a.add(Aov::toon_band);
    edges.set_scene(compiled.scene, a);
    render_batch(edges, {16, 0.0});
    const RgbImage id = edges.film().resolve_aov(Aov::object_id),
                   band = edges.film().resolve_aov(Aov::toon_band);
    const int w = id.width, h = id.height;
    near_edge.assign(size_t(w) * size_t(h), 0);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx) {
            const int qx = std::clamp(x + dx, 0, w - 1), qy = std::clamp(y + dy, 0, h - 1);
            if (id.at(qx, qy).x != id.at(x, y).x || std::abs(band.at(qx, qy).x - band.at(x, y).x) > 0.25f)
              near_edge[size_t(y) * size_t(w) + size_t(x)] = 1;
          }
  }
  const auto edge_rmse = [&](const RgbImage& img) {
    double sum = 0.0, n = 0.0;
    for (size_t i = 0; i < img.pixels.size(); ++i) {
      if (!near_edge[i]) continue;
      for (int c = 0; c < 3; ++c) {
        const double d = double(linear_to_srgb(std::clamp(img.pixels[i][c], 0.f, 1.f))) -
                         double(linear_to_srgb(std::clamp(reference.pixels[i][c], 0.f, 1.f)));
        sum += d * d;
      }
      n += 3.0;
    }
    return n > 0.0 ? std::sqrt(sum / n) : 0.0;
  };
  double next_checkpoint = 0.25;
  while (session.stats().elapsed_seconds < opt.seconds && !session.converged()) {
    session.render_pass();
    const RenderStats& s = session.stats();
    if (s.elapsed_seconds >= next_checkpoint || s.elapsed_seconds >= opt.seconds || session.converged()) {
      const RgbImage img = session.film().resolve();
      std::printf("%10.2f %8.1f %12.3f %12.3f %14.5f %14.5f %12.5f", s.elapsed_seconds,
                  double(s.paths) / pixels, double(s.paths) / s.elapsed_seconds * 1e-6,
                  double(s.rays) / s.elapsed_seconds * 1e-6, rmse_display(img, reference),
                  rmse_linear(img, reference), s.relative_error);
      if (opt.denoise) {
        const auto t0 = Clock::now();
        const Denoised d = denoise(session.film(), &session.pool());
        const double denoise_seconds = seconds_since(t0);
        std::printf(" %10.3f %14.5f %14.5f %12.5f %14.5f %14.5f", denoise_seconds,
                    rmse_display(d.image, reference), rmse_linear(d.image, reference), d.relative_error,
                    edge_rmse(img), edge_rmse(d.image));
      }
      std::printf("\n");
      std::fflush(stdout);
      while (next_checkpoint <= s.elapsed_seconds) next_checkpoint *= 2.0;
    }
  }
  const RenderStats& s = session.stats();
  if (opt.adaptive > 0.0)
    std::printf("adaptive sampling at %g: %u of %u tiles stopped, %.1f samples per pixel on average\n",
                opt.adaptive, s.tiles - s.active_tiles, s.tiles, double(s.paths) / pixels);
  if (opt.denoise) {
    // The median of five runs on the final film: one run is at the mercy of the machine.
    std::vector<double> times;
    for (int run = 0; run < 5; ++run) {
      const auto t0 = Clock::now();
      denoise(session.film(), &session.pool());
      times.push_back(seconds_since(t0));
    }
    std::sort(times.begin(), times.end());
    std::printf("denoiser: median of 5 runs %.3f s for %.2f Mpixels on %d threads: %.3f s per Mpixel\n",
                times[2], pixels * 1e-6, session.threads(), times[2] / (pixels * 1e-6));
  }
  const double full_rate = double(s.rays) / s.elapsed_seconds;
  const double bare_rate = bare_embree_rate(*compiled.scene, opt.threads, 3.0);
  std::printf("\nray rate: full shading %.3f Mrays/s, bare Embree %.3f Mrays/s (%.0f%%)\n", full_rate * 1e-6,
              bare_rate * 1e-6, 100.0 * full_rate / bare_rate);

  if (opt.scaling) {
    const int spp = std::max(4, int(s.spp / 2));
    const double t1 = time_for_spp(compiled.scene, 1, spp);
    const double t2 = time_for_spp(compiled.scene, 2, spp);
    std::printf("threads: %d spp in %.3f s on 1 thread, %.3f s on 2 threads: %.2fx\n", spp, t1, t2, t1 / t2);
    AovSet all;
    for (size_t a = 0; a < kAovNames.size(); ++a) all.add(Aov(a));
    const double off = time_for_spp(compiled.scene, opt.threads, spp);
    const double on = time_for_spp(compiled.scene, opt.threads, spp, all);
    std::printf("AOVs: %d spp in %.3f s with none, %.3f s with all five (%+.1f%%)\n", spp, off, on,
                100.0 * (on / off - 1.0));
  }
  std::printf("peak memory: %.1f MiB\n", peak_rss_mib());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s: missing value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--time")
      opt.seconds = std::atof(next());
    else if (a == "--threads")
      opt.threads = std::atoi(next());
    else if (a == "--reference-spp")
      opt.reference_spp = std::atoi(next());
    else if (a == "--cache")
      opt.cache = next();
    else if (a == "--no-scaling")
      opt.scaling = false;
    else if (a == "--denoise")
      opt.denoise = true;
    else if (a == "--adaptive")
      opt.adaptive = std::atof(next());
    else if (a == "-h" || a == "--help") {
      std::printf(
          "usage: inkray-bench [SCENE.json] [--time S] [--threads N] [--reference-spp N] [--cache DIR] "
          "[--no-scaling] [--denoise] [--adaptive E]\n");
      return 0;
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "unknown option %s\n", a.c_str());
      return 2;
    } else
      opt.scene = a;
  }
  if (opt.seconds <= 0.0 || opt.threads < 1 || opt.reference_spp < 1) {
    std::fprintf(stderr, "--time, --threads and --reference-spp must be positive\n");
    return 2;
  }
  return run(opt);
}
