// Lines on data they were not tuned on: a bumpy glass refractor over a plain
// ground (no line may come from the refractor's own scattering) next to a
// smooth glass ball (the lines behind it stay), sub-pixel widths, width 0,
// mesh creases from feature edges, depth lines on a receding plane, wide lines
// at few samples, resolution independence of line darkness, and adaptive line
// sampling converging to the lines of full sampling.
#include "core/film/resolve.h"
#include "core/npr/outlines/line_detector.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace inkray {
namespace {

using testing::small_scene;

using Rendered = testing::RenderedFilm;
using testing::draw_outlines;
using testing::make_object;

Rendered render(const SceneDesc& desc, int spp, AovSet aovs = {}) {
  return testing::render_film(desc, spp, aovs);
}

AovSet with_object_ids() {
  AovSet a;
  a.add(Aov::object_id);
  return a;
}

// Mean of the outline AOV over the pixels whose first hit is object `id`.
double mean_inside(const Rendered& r, int id, int* pixels = nullptr) {
  const RgbImage ids = r.aov(Aov::object_id), lines = r.aov(Aov::outline);
  double sum = 0.0;
  int n = 0;
  for (size_t i = 0; i < ids.pixels.size(); ++i)
    if (int(ids.pixels[i].x) == id) {
      // Stay clear of the object's own outline: only pixels whose 5x5
      // neighbourhood is all the object.
      const int x = int(i % size_t(ids.width)), y = int(i / size_t(ids.width));
      bool interior = true;
      for (int dy = -2; dy <= 2 && interior; ++dy)
        for (int dx = -2; dx <= 2 && interior; ++dx) {
          const int xx = std::clamp(x + dx, 0, ids.width - 1), yy = std::clamp(y + dy, 0, ids.height - 1);
          interior = int(ids.at(xx, yy).x) == id;
        }
      if (!interior) continue;
      sum += lines.pixels[i].x;
      ++n;
    }
  if (pixels) *pixels = n;
  return n ? sum / n : 0.0;
}

// A bumpy glass blob (scenes/meshes/bumpy_blob.obj, 20k triangles) on the
// left and a smooth glass ball on the right, over a ground plane and a sky;
// behind the ball only, an outlined box.
SceneDesc glass_scene(float smooth_angle) {
  SceneDesc d = small_scene(240, 120);
  d.base_dir = INKRAY_SOURCE_DIR "/scenes";
  d.camera.look_from = {0.f, 1.2f, 7.f};
  d.camera.look_at = {0.f, 0.8f, 0.f};
  d.camera.vfov = 30.f;
  d.environment = GradientEnvironmentDesc{Color(0.5f, 0.6f, 0.8f), Color(0.9f), Color(0.3f)};
  d.materials.push_back({"ground", DiffuseDesc{Color(0.8f)}, {}});
  d.materials.push_back({"glass", DielectricDesc{}, {}});
  d.materials.push_back({"orange", DiffuseDesc{Color(0.9f, 0.45f, 0.1f)}, {}});
  d.objects.push_back(
      make_object("ground", QuadDesc{{-60.f, 0.f, -60.f}, {0.f, 0.f, 120.f}, {120.f, 0.f, 0.f}}, "ground"));
  ObjectDesc blob = make_object("blob", MeshDesc{"meshes/bumpy_blob.obj", smooth_angle}, "glass");
  blob.transform.scale = Vec3(0.8f);
  blob.transform.translate = {-1.3f, 0.95f, 0.f};
  d.objects.push_back(blob);
  d.objects.push_back(make_object("ball", SphereDesc{{1.3f, 0.9f, 0.f}, 0.9f}, "glass"));
  d.objects.push_back(make_object("box", BoxDesc{{0.9f, 0.f, -3.f}, {2.1f, 1.6f, -2.f}}, "orange"));
  draw_outlines(d.outlines, 2.f, 120.f, {.silhouette = true, .object = true, .crease = true});
  return d;
}

// Before lines were weighed by how coherent the chain is, about half of the
// blob's pixels were line (at quality 1 and 4 alike). Now what remains is the
// few lines the blob's smoother regions still show coherently.
TEST(LineQuality, BumpyRefractorDrawsNoMessWhileASmoothBallKeepsItsLines) {
  for (const float smooth_angle : {30.f, 0.f}) {
    for (const int quality : {1, 4}) {
      SceneDesc d = glass_scene(smooth_angle);
      d.outlines.quality = quality;
      const Rendered r = render(d, 16, with_object_ids());
      int blob_pixels = 0, ball_pixels = 0;
      const double blob = mean_inside(r, 1, &blob_pixels);
      const double ball = mean_inside(r, 2, &ball_pixels);
      SCOPED_TRACE(::testing::Message() << "smooth_angle " << smooth_angle << ", quality " << quality
                                        << ": blob " << blob << ", ball " << ball);
      ASSERT_GT(blob_pixels, 800);
      ASSERT_GT(ball_pixels, 800);
      EXPECT_LT(blob, 0.08);
      // The box behind the ball is outlined through it, and the horizon too.
      EXPECT_GT(ball, 0.04);
    }
  }
}

// Camera on +z looking at the origin; a grey backdrop quad at z = 0 and a
// smaller quad at z = 2 in front of it, covering x in [-1, 1].
SceneDesc quad_in_front_of_quad(int width, int height, float width_px) {
  SceneDesc d = small_scene(width, height);
  d.camera.look_from = {0.f, 0.f, 10.f};
  d.camera.vfov = 30.f;
  d.materials.push_back({"grey", DiffuseDesc{Color(0.5f)}, {}});
  d.objects.push_back(
      make_object("back", QuadDesc{{-20.f, -20.f, 0.f}, {40.f, 0.f, 0.f}, {0.f, 40.f, 0.f}}, "grey"));
  d.objects.push_back(
      make_object("front", QuadDesc{{-1.f, -20.f, 2.f}, {2.f, 0.f, 0.f}, {0.f, 40.f, 0.f}}, "grey"));
  // Widths in this image's own pixels.
  draw_outlines(d.outlines, width_px, float(height), {.silhouette = true, .object = false});
  return d;
}

double total(const RgbImage& img) {
  double sum = 0.0;
  for (const Color& c : img.pixels) sum += c.x;
  return sum;
}

float max_value(const RgbImage& img) {
  float m = 0.f;
  for (const Color& c : img.pixels) m = std::max(m, c.x);
  return m;
}

// A 0.1-pixel line is a faint continuous line, not dots: no pixel darker than
// a fifth, and its ink (summed opacity) a tenth of a 1-pixel line's.
TEST(LineQuality, SubPixelWidthsFadeInsteadOfLeavingDots) {
  const Rendered thin = render(quad_in_front_of_quad(160, 80, 0.1f), 32);
  const Rendered one = render(quad_in_front_of_quad(160, 80, 1.f), 32);
  const RgbImage a = thin.aov(Aov::outline), b = one.aov(Aov::outline);
  EXPECT_LT(max_value(a), 0.2f);
  EXPECT_NEAR(total(a) / total(b), 0.1, 0.02);
  // Every row of the image has its share of the line: the two edges run top to bottom.
  for (int y = 0; y < a.height; ++y) {
    double row = 0.0;
    for (int x = 0; x < a.width; ++x) row += a.at(x, y).x;
    EXPECT_GT(row, 0.02) << "row " << y;
  }
}

TEST(LineQuality, WidthZeroDrawsNothing) {
  SceneDesc d = quad_in_front_of_quad(80, 40, 0.f);
  const Rendered r = render(d, 4);
  EXPECT_FALSE(r.scene->lines.active);
  EXPECT_EQ(total(r.aov(Aov::outline)), 0.0);
  d.outlines.width = 2.f;
  d.outlines.silhouette.width = 0.f;  // the only type on, at width 0
  EXPECT_FALSE(render(d, 1).scene->lines.active);
}

// Mean line darkness (opacity over the whole image) of the same scene at
// 400x300 and at 1600x1200 averaged down 4x4, for lines 2 pixels wide at 1080
// lines: 0.56 pixels at 300 lines, 2.2 at 1200.
TEST(LineQuality, LineDarknessDoesNotDependOnResolution) {
  auto scene = [](int w, int h) {
    SceneDesc d = quad_in_front_of_quad(w, h, 2.f);
    d.outlines.reference_height = 1080.f;
    d.objects.push_back(make_object("ball", SphereDesc{{0.f, 0.f, 3.f}, 0.6f}, "grey"));
    return d;
  };
  const double coarse = total(render(scene(400, 300), 64).aov(Aov::outline)) / (400.0 * 300.0);
  const double fine = total(render(scene(1600, 1200), 16).aov(Aov::outline)) / (1600.0 * 1200.0);
  EXPECT_NEAR(coarse / fine, 1.0, 0.05) << "coarse " << coarse << ", fine " << fine;
}

// Depth lines are occlusions with a depth gap: a ground plane receding to the
// horizon has none, a box standing on it does.
TEST(LineQuality, DepthLinesDoNotFloodARecedingPlane) {
  SceneDesc d = small_scene(160, 90);
  d.camera.look_from = {0.f, 1.f, 8.f};
  d.camera.look_at = {0.f, 0.5f, 0.f};
  d.materials.push_back({"grey", DiffuseDesc{Color(0.5f)}, {}});
  d.objects.push_back(
      make_object("ground", QuadDesc{{-500.f, 0.f, -500.f}, {0.f, 0.f, 1000.f}, {1000.f, 0.f, 0.f}}, "grey"));
  draw_outlines(d.outlines, 2.f, 90.f, {.silhouette = false, .object = false, .depth = true});
  EXPECT_EQ(total(render(d, 8).aov(Aov::outline_depth)), 0.0);
  d.objects.push_back(make_object("box", BoxDesc{{-1.f, 0.f, -1.f}, {1.f, 2.f, 1.f}}, "grey"));
  EXPECT_GT(total(render(d, 8).aov(Aov::outline_depth)), 50.0);
}

// A mesh alone, seen from `eye`, with only crease lines on.
SceneDesc crease_scene(const char* base_dir, const char* mesh, Point3 eye, float threshold) {
  SceneDesc d = small_scene(160, 160);
  d.base_dir = base_dir;
  d.camera.look_from = eye;
  d.camera.look_at = {0.f, 0.f, 0.f};
  d.camera.vfov = 40.f;
  d.materials.push_back({"grey", DiffuseDesc{Color(0.5f)}, {}});
  d.objects.push_back(make_object("mesh", MeshDesc{mesh, 30.f}, "grey"));
  draw_outlines(d.outlines, 1.5f, 160.f, {.silhouette = false, .object = false, .crease = true});
  d.outlines.crease.threshold = threshold;
  return d;
}

// Creases on a mesh come from its feature edges: on a cube whose edges are
// bevelled at 45 degrees, a 30-degree threshold draws every bevel's two edges;
// 60 draws none. (Comparing sample normals would draw the bevelled cube
// alike, but speckle on a noisy scan wherever two facets bend past the threshold.)
// On that scan, feature edges at 30 degrees draw far fewer line pixels.
TEST(LineQuality, MeshCreasesFollowFeatureEdges) {
  auto scene = [](float threshold) {
    return crease_scene(INKRAY_SOURCE_DIR "/tests/data", "meshes/bevel_cube.obj", {2.5f, 2.f, 3.f},
                        threshold);
  };
  const Rendered at30 = render(scene(30.f), 16);
  const Rendered at60 = render(scene(60.f), 16);
  const RgbImage creases = at30.aov(Aov::outline_crease);
  EXPECT_EQ(total(at60.aov(Aov::outline_crease)), 0.0);
  // Three faces in view, 60 pixels across: the three bevels between them and
  // the six at the silhouette give about fifteen edges 15 to 40 pixels long.
  int solid = 0;
  for (const Color& c : creases.pixels) solid += c.x > 0.5f;
  EXPECT_GT(solid, 150);
}

TEST(LineQuality, NoisyScanDrawsNoCreaseSpeckle) {
  const SceneDesc d =
      crease_scene(INKRAY_SOURCE_DIR "/scenes", "meshes/scan_noisy.obj", {0.f, 0.5f, 4.f}, 30.f);
  const double meshed = total(render(d, 16).aov(Aov::outline_crease));
  // The 99th percentile of the scan's dihedral angles is 26 degrees: the few
  // edges over 30 are isolated and bound no patch, so nothing is drawn.
  EXPECT_LT(meshed, 20.0);
}

// A wide line at 16 samples: its soft edge gets more stencil rays, so the
// opacity profile is the same in every row within a small noise.
TEST(LineQuality, WideLinesAreSmoothAtFewSamples) {
  SceneDesc d = quad_in_front_of_quad(200, 100, 24.f);
  const Rendered r = render(d, 16);
  const RgbImage a = r.aov(Aov::outline);
  double noise = 0.0;
  int columns = 0;
  for (int x = 0; x < a.width; ++x) {
    double sum = 0.0, sum2 = 0.0;
    for (int y = 0; y < a.height; ++y) sum += a.at(x, y).x, sum2 += sqr(double(a.at(x, y).x));
    const double mean = sum / a.height, var = std::max(sum2 / a.height - mean * mean, 0.0);
    if (mean > 0.05 && mean < 0.95) noise += std::sqrt(var), ++columns;
  }
  ASSERT_GT(columns, 8);
  EXPECT_LT(noise / columns, 0.06);
}

// Adaptive line sampling converges to the lines of full sampling, and traces
// fewer rays doing it.
TEST(LineQuality, AdaptiveSamplingConvergesToFullSampling) {
  SceneDesc d = quad_in_front_of_quad(120, 60, 3.f);
  d.objects.push_back(make_object("ball", SphereDesc{{0.f, 0.f, 3.f}, 0.6f}, "grey"));
  d.outlines.crease.enabled = true;
  const Rendered adaptive = render(d, 256);
  d.outlines.adaptive = false;
  const Rendered full = render(d, 256);
  const RgbImage a = adaptive.aov(Aov::outline), b = full.aov(Aov::outline);
  double diff = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) diff += std::abs(a.pixels[i].x - b.pixels[i].x);
  EXPECT_LT(diff / double(a.pixels.size()), 0.01);
  EXPECT_LT(adaptive.session->stats().rays, full.session->stats().rays);
}

TEST(LineQuality, ChainCoherenceFadesFromCoherentToScattered) {
  EXPECT_EQ(chain_coherence(1.f), 1.f);
  EXPECT_EQ(chain_coherence(6.f), 1.f);
  EXPECT_GT(chain_coherence(20.f), 0.f);
  EXPECT_EQ(chain_coherence(1000.f), 0.f);
  float last = 1.f;
  for (float s = 1.f; s < 200.f; s *= 1.1f) {
    const float c = chain_coherence(s);
    EXPECT_LE(c, last);
    last = c;
  }
}

}  // namespace
}  // namespace inkray
