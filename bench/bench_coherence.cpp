// inkray-bench-coherence: do lines, strokes and toon shading hold still from frame to
// frame? A scene's camera orbits (its own animation, or a quarter turn added here);
// each frame is compared with the next after motion compensation: every pixel of frame
// f+1 is carried back to frame f through its depth and the two cameras, and the
// layers are compared where the same object is seen at the same depth. The reference
// is noise: frame f+1 rendered with two seeds and compared through the same bilinear
// resampling the warp uses (at the warp's sub-pixel offsets), so a ratio near 1 means
// the layer changes between frames no more than sampling noise does.
// Layers: lines (the outline AOV's opacity; with line sets, the alpha of the styled
// strokes drawn from the film's chains), strokes (luminance on painted objects'
// pixels), surfaces (luminance on every other object's pixels).
#include "core/compiler/compile.h"
#include "core/document/animation.h"
#include "core/document/json_io.h"
#include "core/film/film_chains.h"
#include "core/film/resolve.h"
#include "core/npr/lines/stroke_raster.h"
#include "core/render/batch_render.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace {

using namespace inkray;

struct Options {
  std::string scene = "scenes/animation.json";
  int frames = 48, width = 480, height = 270, spp = 64, threads = 0;
  bool keep_objects_moving = false;  // default: only the camera moves (a still scene)
  // A control: strokes grown anew every frame (the emitter seed follows the frame), as
  // strokes that popped would be; the measure must tell it from steady strokes.
  bool reseed_strokes = false;
};

struct FrameImages {
  RgbImage color, lines, ids, depth;
  Camera camera;
  int width = 0, height = 0;
};

float luminance(const Color& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// The line sets' strokes as an alpha layer: drawn in white over black with no display
// curve, so a pixel holds the strokes' coverage there.
RgbImage stroke_alpha(const Film& film, const ResolveSettings& resolve) {
  RgbImage alpha{film.width(), film.height(),
                 std::vector<Color>(size_t(film.width()) * size_t(film.height()))};
  std::vector<LineSet> sets = resolve.sets;
  for (LineSet& set : sets) set.style.color = set.style.color_end = Color(1.f);
  const std::vector<Chain> chains =
      chains_to_draw(film_chains(film, resolve.material_paths), resolve, film.width());
  draw_strokes(stroke_chains(chains, sets, film.height()), DisplayEncoding{0.f, ViewTransform::raw}, alpha);
  return alpha;
}

FrameImages render_frame(SceneCompiler& compiler, SceneDesc desc, double frame, int seed, const Options& o) {
  desc.render.frame = float(frame);
  desc.render.seed = seed;
  if (o.reseed_strokes)
    for (StrokeEmitterDesc& e : desc.strokes) e.seed = int(frame);
  const CompileResult c = compiler.compile(desc);
  if (!c.scene) {
    std::fprintf(stderr, "error: %s\n", c.errors.empty() ? "compile failed" : c.errors.front().c_str());
    std::exit(1);
  }
  AovSet aovs;
  aovs.add(Aov::depth);
  aovs.add(Aov::object_id);
  if (c.scene->lines.active) aovs.add(Aov::outline);
  RenderSession session(o.threads);
  session.set_scene(c.scene, aovs);
  render_batch(session, {o.spp, 0.0});
  FrameImages f;
  f.width = desc.render.width;
  f.height = desc.render.height;
  f.color = session.film().resolve();
  f.ids = session.film().resolve_aov(Aov::object_id);
  f.depth = session.film().resolve_aov(Aov::depth);
  if (aovs.has(Aov::outline)) f.lines = session.film().resolve_aov(Aov::outline);
  if (c.scene->lines.active && !c.scene->resolve.sets.empty())
    f.lines = stroke_alpha(session.film(), c.scene->resolve);
  f.camera = c.scene->camera;
  return f;
}

struct Layers {
  std::set<int> strokes;  // ids of the objects strokes are painted on
};

// Bilinear lookup of a grey layer at film position p (pixel centres at +0.5).
float bilinear(const std::vector<float>& layer, int w, int h, Vec2 p) {
  const float x = std::clamp(p.x - 0.5f, 0.f, float(w - 1)), y = std::clamp(p.y - 0.5f, 0.f, float(h - 1));
  const int x0 = int(x), y0 = int(y), x1 = std::min(x0 + 1, w - 1), y1 = std::min(y0 + 1, h - 1);
  const float fx = x - float(x0), fy = y - float(y0);
  const auto at = [&](int xx, int yy) { return layer[size_t(yy) * size_t(w) + size_t(xx)]; };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) +
         fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
}

enum Layer { kLines, kStrokes, kSurfaces, kLayerCount };
constexpr const char* kLayerNames[] = {"lines", "strokes", "surfaces"};

std::vector<float> grey(const FrameImages& f, Layer layer) {
  std::vector<float> out(size_t(f.width) * size_t(f.height), 0.f);
  for (size_t i = 0; i < out.size(); ++i) {
    if (layer == kLines)
      out[i] = f.lines.pixels.empty() ? 0.f : f.lines.pixels[i].x;
    else
      out[i] = luminance(f.color.pixels[i]);
  }
  return out;
}

// Every compared pixel's difference, per layer: the mean says how much a layer
// shimmers, the 99.9th percentile whether anything pops (a stroke or a line segment
// appearing or vanishing moves a few pixels a lot and the mean little).
struct Sums {
  std::vector<float> diffs[kLayerCount];
  void add(Layer l, double d) { diffs[l].push_back(float(d)); }
  double count(Layer l) const { return double(diffs[l].size()); }
  double mean(Layer l) const {
    double sum = 0.0;
    for (float d : diffs[l]) sum += d;
    return diffs[l].empty() ? 0.0 : sum / double(diffs[l].size());
  }
  double percentile(Layer l, double q) {
    std::vector<float>& v = diffs[l];
    if (v.empty()) return 0.0;
    const auto at = v.begin() + std::ptrdiff_t(q * double(v.size() - 1));
    std::nth_element(v.begin(), at, v.end());
    return *at;
  }
};

// Compares `later` with `earlier`: each pixel of `later` that sees a surface is carried
// into `earlier` through its depth; where `earlier` sees the same object at the same
// depth there, the layers are compared. With `noise` set, `noise` (the same frame as
// `later`, another seed) is read at the same sub-pixel offsets instead of `earlier`.
void compare(const FrameImages& later, const FrameImages& earlier, const FrameImages* noise,
             const Layers& layers, Sums& sums) {
  const int w = later.width, h = later.height;
  std::vector<float> a[kLayerCount], b[kLayerCount];
  const FrameImages& other = noise ? *noise : earlier;
  for (int l = 0; l < kLayerCount; ++l) {
    a[l] = grey(later, Layer(l));
    b[l] = grey(other, Layer(l));
  }
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      const int id = int(std::lround(later.ids.pixels[i].x));
      if (id < 0) continue;
      const Vec2 film(float(x) + 0.5f, float(y) + 0.5f);
      const Ray ray = later.camera.generate_ray(film, Vec2(0.5f));
      const Vec3 d = glm::normalize(ray.d);
      const float along = glm::dot(d, later.camera.forward());
      if (along <= 1e-4f) continue;
      const Point3 world = ray.o + d * (later.depth.pixels[i].x / along);
      Vec2 back;
      if (!earlier.camera.project(world, &back)) continue;
      if (back.x < 1.f || back.y < 1.f || back.x > float(w) - 1.f || back.y > float(h) - 1.f) continue;
      // Seen in the earlier frame too: the same object at the expected depth.
      const size_t j = size_t(int(back.y)) * size_t(w) + size_t(int(back.x));
      if (int(std::lround(earlier.ids.pixels[j].x)) != id) continue;
      const float expected = glm::dot(world - earlier.camera.origin(), earlier.camera.forward());
      if (std::fabs(earlier.depth.pixels[j].x - expected) > 0.02f * expected) continue;
      // The noise reference reads its own frame at this pixel, shifted by the warp's
      // sub-pixel offset, so both go through the same interpolation.
      const Vec2 at = noise ? film + (back - glm::floor(back)) - Vec2(0.5f) : back;
      const bool stroke = layers.strokes.count(id) > 0;
      if (!later.lines.pixels.empty())
        sums.add(kLines, std::fabs(a[kLines][i] - bilinear(b[kLines], w, h, at)));
      sums.add(stroke ? kStrokes : kSurfaces,
               std::fabs(a[stroke ? kStrokes : kSurfaces][i] -
                         bilinear(b[stroke ? kStrokes : kSurfaces], w, h, at)));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto next = [&] { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (a == "--frames")
      o.frames = std::atoi(next().c_str());
    else if (a == "--width")
      o.width = std::atoi(next().c_str());
    else if (a == "--height")
      o.height = std::atoi(next().c_str());
    else if (a == "--spp")
      o.spp = std::atoi(next().c_str());
    else if (a == "--threads")
      o.threads = std::atoi(next().c_str());
    else if (a == "--moving")
      o.keep_objects_moving = true;
    else if (a == "--reseed-strokes")
      o.reseed_strokes = true;
    else if (a == "-h" || a == "--help") {
      std::printf(
          "usage: inkray-bench-coherence [SCENE] [--frames N] [--width W] [--height H] [--spp N] "
          "[--threads N] [--moving] [--reseed-strokes]\n(default scenes/animation.json with only its camera "
          "moving;\n"
          "--moving keeps its objects' tracks too; --reseed-strokes grows new strokes every frame, a "
          "control)\n");
      return 0;
    } else if (!a.empty() && a[0] != '-')
      o.scene = a;
    else {
      std::fprintf(stderr, "unknown option %s\n", a.c_str());
      return 2;
    }
  }
  SceneLoadResult loaded = load_scene(o.scene);
  if (!loaded) {
    for (const auto& e : loaded.errors) std::fprintf(stderr, "error: %s\n", e.c_str());
    return 1;
  }
  SceneDesc desc = *loaded.scene;
  desc.render.width = o.width;
  desc.render.height = o.height;
  desc.render.shutter_open = desc.render.shutter_close = 0.f;  // a sharp picture per frame
  if (!o.keep_objects_moving)
    desc.animation.erase_if([](const TrackDesc& t) { return t.target.rfind("camera/", 0) != 0; });
  if (!find_track(desc, "camera/look_from")) {
    // A quarter turn about look_at, keyed every 6 frames.
    const Vec3 arm = desc.camera.look_from - desc.camera.look_at;
    TrackDesc orbit{"camera/look_from", {}};
    for (int f = 0; f <= o.frames; f += 6) {
      const float a = glm::radians(90.f * float(f) / float(o.frames));
      const Vec3 p = desc.camera.look_at + Vec3(arm.x * std::cos(a) + arm.z * std::sin(a), arm.y,
                                                -arm.x * std::sin(a) + arm.z * std::cos(a));
      orbit.keys.push_back({double(desc.render.frame_start + f), {p.x, p.y, p.z}, Interpolation::bezier});
    }
    desc.animation.push_back(orbit);
  }
  Layers layers;
  // The object id AOV names the document object, strokes their object's: the strokes
  // layer is every pixel of a painted object.
  for (const StrokeEmitterDesc& e : desc.strokes)
    for (size_t i = 0; i < desc.objects.size(); ++i)
      if (desc.objects[i].name == e.object) layers.strokes.insert(int(i));

  std::printf(
      "inkray-bench-coherence %s: %d frames from %d, %dx%d, %d spp; mean absolute difference per pixel\n",
      o.scene.c_str(), o.frames, desc.render.frame_start, o.width, o.height, o.spp);
  SceneCompiler compiler;
  Sums temporal, noise;
  FrameImages previous = render_frame(compiler, desc, desc.render.frame_start, 0, o);
  for (int f = 1; f < o.frames; ++f) {
    const double frame = desc.render.frame_start + f;
    FrameImages current = render_frame(compiler, desc, frame, 0, o);
    compare(current, previous, nullptr, layers, temporal);
    if (f % 8 == 1) {  // the noise reference, on every 8th frame
      const FrameImages reseeded = render_frame(compiler, desc, frame, 1, o);
      compare(current, previous, &reseeded, layers, noise);
    }
    previous = std::move(current);
    std::fprintf(stderr, "\rframe %d/%d", f + 1, o.frames);
  }
  std::fprintf(stderr, "\n");
  std::printf("%-9s %26s %26s %14s %12s\n", "layer", "frame to frame: mean p99.9", "seed to seed: mean p99.9",
              "ratio: mean p99.9", "pixels/frame");
  for (int l = 0; l < kLayerCount; ++l) {
    const Layer layer = Layer(l);
    const double t = temporal.mean(layer), n = noise.mean(layer);
    const double tp = temporal.percentile(layer, 0.999), np = noise.percentile(layer, 0.999);
    std::printf("%-9s %14.5f %11.5f %14.5f %11.5f %7.2f %6.2f %12.0f\n", kLayerNames[l], t, tp, n, np,
                n > 0 ? t / n : 0.0, np > 0 ? tp / np : 0.0,
                temporal.count(layer) / std::max(1, o.frames - 1));
  }
  return 0;
}
