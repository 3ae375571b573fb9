// Outlines on synthetic scenes: line pixels exactly where the silhouette is,
// the flush-light case, width scaling, resolution independence, lines in
// mirrors, overrides and the zero-cost path when no line type is on.
#include "core/compiler/compile_view.h"
#include "core/film/resolve.h"
#include "core/npr/outlines/line_detector.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inkray {
namespace {

using testing::draw_outlines;
using testing::small_scene;

using Rendered = testing::RenderedFilm;

Rendered render(const SceneDesc& desc, int spp) { return testing::render_film(desc, spp); }

// Camera on +z looking at the origin; a grey backdrop quad at z = 0 and a
// smaller quad at z = 2 in front of it, covering x in [-1, 1] (its left and
// right edges are vertical lines in the image).
SceneDesc quad_in_front_of_quad(int width, int height) {
  SceneDesc d = small_scene(width, height);
  d.camera.look_from = {0.f, 0.f, 10.f};
  d.camera.vfov = 30.f;
  d.materials.push_back({"grey", DiffuseDesc{Color(0.5f)}, {}});
  d.objects.push_back(
      {"back", QuadDesc{{-20.f, -20.f, 0.f}, {40.f, 0.f, 0.f}, {0.f, 40.f, 0.f}}, {}, "grey", true, {}});
  d.objects.push_back(
      {"front", QuadDesc{{-1.f, -20.f, 2.f}, {2.f, 0.f, 0.f}, {0.f, 40.f, 0.f}}, {}, "grey", true, {}});
  // Widths in this image's own pixels.
  draw_outlines(d.outlines, 4.f, float(height), {.silhouette = true, .object = false});
  d.outlines.quality = 4;
  return d;
}

// The x of the front quad's right edge on the film.
float right_edge_x(const RenderScene& scene) {
  Vec2 film;
  EXPECT_TRUE(scene.camera.project(Point3(1.f, 0.f, 2.f), &film));
  return film.x;
}

// Opacity along the middle row.
std::vector<float> row(const RgbImage& img) {
  std::vector<float> r;
  for (int x = 0; x < img.width; ++x) r.push_back(img.at(x, img.height / 2).x);
  return r;
}

// Width of the line at half opacity around pixel x_edge, in pixels.
float half_opacity_width(const std::vector<float>& r, float x_edge) {
  float width = 0.f;
  for (int x = int(x_edge) - 20; x <= int(x_edge) + 20; ++x)
    if (x >= 0 && x < int(r.size())) width += r[size_t(x)] >= 0.5f ? 1.f : 0.f;
  return width;
}

TEST(Outlines, SilhouetteLinePixelsAreExactlyAtTheEdge) {
  const SceneDesc desc = quad_in_front_of_quad(160, 80);
  const Rendered r = render(desc, 32);
  const float edge = right_edge_x(*r.scene);
  const RgbImage lines = r.aov(Aov::outline_silhouette);
  const float width = desc.outlines.width;
  for (int y = 0; y < lines.height; ++y) {
    for (int x = 0; x < lines.width; ++x) {
      const float centre = float(x) + 0.5f;
      // Distance to the nearer of the quad's two vertical edges (at +-edge from the middle).
      const float d = std::min(std::abs(centre - edge), std::abs(centre - (float(lines.width) - edge)));
      const float o = lines.at(x, y).x;
      if (d < 0.2f * width) {
        EXPECT_GT(o, 0.9f) << x << "," << y;
      }
      if (d > 0.8f * width + 1.f) {
        EXPECT_EQ(o, 0.f) << x << "," << y;
      }
    }
  }
}

TEST(Outlines, DoublingTheWidthDoublesTheLine) {
  SceneDesc desc = quad_in_front_of_quad(200, 60);
  const Rendered thin = render(desc, 32);
  desc.outlines.width = 8.f;
  const Rendered wide = render(desc, 32);
  const float edge = right_edge_x(*thin.scene);
  const float w4 = half_opacity_width(row(thin.aov(Aov::outline)), edge);
  const float w8 = half_opacity_width(row(wide.aov(Aov::outline)), edge);
  // The line is `width` pixels wide at half opacity, to a pixel.
  EXPECT_NEAR(w4, 4.f, 1.f);
  EXPECT_NEAR(w8, 8.f, 1.f);
}

TEST(Outlines, TwiceTheResolutionKeepsTheLook) {
  // Widths in pixels at a fixed reference height scale with the image.
  SceneDesc desc = quad_in_front_of_quad(120, 60);
  desc.outlines.reference_height = 60.f;
  const RgbImage low = render(desc, 32).aov(Aov::outline);
  desc.render.width = 240;
  desc.render.height = 120;
  const RgbImage high = render(desc, 32).aov(Aov::outline);
  double diff = 0.0;
  for (int y = 0; y < low.height; ++y)
    for (int x = 0; x < low.width; ++x) {
      const float h = 0.25f * (high.at(2 * x, 2 * y).x + high.at(2 * x + 1, 2 * y).x +
                               high.at(2 * x, 2 * y + 1).x + high.at(2 * x + 1, 2 * y + 1).x);
      diff += std::abs(h - low.at(x, y).x);
    }
  // Mean absolute difference of the opacity over the image, after a 2x box downsample.
  EXPECT_LT(diff / double(low.width * low.height), 0.01);
}

// A ceiling with a light flush against it: same plane, same normal, so only
// the object-id comparison finds its border.
SceneDesc flush_light(bool object_lines) {
  SceneDesc d = small_scene(96, 96);
  d.camera.look_from = {0.f, -5.f, 0.f};
  d.camera.look_at = {0.f, 0.f, 0.f};
  d.camera.up = {0.f, 0.f, 1.f};
  d.camera.vfov = 60.f;
  d.materials.push_back({"white", DiffuseDesc{Color(0.7f)}, {}});
  d.materials.push_back({"light", EmissiveDesc{Color(1.f), 5.f, true}, {}});
  d.objects.push_back(
      {"ceiling", QuadDesc{{-10.f, 0.f, -10.f}, {20.f, 0.f, 0.f}, {0.f, 0.f, 20.f}}, {}, "white", true, {}});
  d.objects.push_back(
      {"lamp", QuadDesc{{-1.f, -0.001f, -1.f}, {2.f, 0.f, 0.f}, {0.f, 0.f, 2.f}}, {}, "light", true, {}});
  draw_outlines(d.outlines, 3.f, 96.f,
                {.silhouette = true, .object = object_lines, .crease = true, .depth = true});
  return d;
}

TEST(Outlines, FlushLightGetsItsOutline) {
  const Rendered with = render(flush_light(true), 16);
  const Rendered without = render(flush_light(false), 16);
  Vec2 a, b;
  ASSERT_TRUE(with.scene->camera.project(Point3(-1.f, 0.f, 0.f), &a));
  ASSERT_TRUE(with.scene->camera.project(Point3(1.f, 0.f, 0.f), &b));
  const int y = 48;
  const RgbImage lines = with.aov(Aov::outline);
  EXPECT_GT(lines.at(int(a.x), y).x, 0.9f);
  EXPECT_GT(lines.at(int(b.x), y).x, 0.9f);
  EXPECT_EQ(lines.at(48, y).x, 0.f);  // the middle of the light
  EXPECT_EQ(lines.at(5, y).x, 0.f);   // the ceiling away from it
  // Normal and depth comparisons alone see nothing there.
  const RgbImage none = without.aov(Aov::outline);
  for (const Color& c : none.pixels) ASSERT_EQ(c.x, 0.f);
}

// A mirror quad facing the camera, reflecting a sphere behind the camera.
SceneDesc mirror_scene(bool stop_lines) {
  SceneDesc d = small_scene(64, 64);
  d.camera.look_from = {0.f, 0.f, 5.f};
  d.camera.vfov = 40.f;
  d.materials.push_back({"mirror", ConductorDesc{Color(0.9f), 0.f}, {}});
  d.materials.back().lines.stop_lines = stop_lines;
  d.materials.push_back({"white", DiffuseDesc{Color(0.7f)}, {}});
  d.objects.push_back(
      {"mirror", QuadDesc{{-10.f, -10.f, 0.f}, {20.f, 0.f, 0.f}, {0.f, 20.f, 0.f}}, {}, "mirror", true, {}});
  d.objects.push_back({"ball", SphereDesc{{0.f, 0.f, 8.f}, 1.f}, {}, "white", true, {}});
  draw_outlines(d.outlines, 2.f, 64.f, {.silhouette = true});
  return d;
}

float total(const RgbImage& img) {
  float sum = 0.f;
  for (const Color& c : img.pixels) sum += c.x;
  return sum;
}

TEST(Outlines, LinesAppearInMirrorsUnlessStopped) {
  const float reflected = total(render(mirror_scene(false), 8).aov(Aov::outline));
  const float stopped = total(render(mirror_scene(true), 8).aov(Aov::outline));
  // The reflected ball's outline is a ring about 2 * pi * 8 pixels long, 2 pixels wide.
  EXPECT_GT(reflected, 50.f);
  EXPECT_EQ(stopped, 0.f);
}

TEST(Outlines, ExcludedObjectsDrawNoLines) {
  SceneDesc d = quad_in_front_of_quad(80, 40);
  d.objects[1].lines.exclude = true;
  EXPECT_EQ(total(render(d, 4).aov(Aov::outline)), 0.f);
}

TEST(Outlines, ColourIsAppliedAtResolveWithoutRetracing) {
  SceneDesc d = quad_in_front_of_quad(160, 80);
  d.outlines.silhouette.color = Color(1.f, 0.f, 0.f);
  const Rendered r = render(d, 16);
  const int x = int(right_edge_x(*r.scene)), y = 40;
  EXPECT_EQ(resolve_final(r.session->film(), *r.scene).at(x, y), Color(1.f, 0.f, 0.f));
  // A colour edit only needs a new resolve of the same film.
  OutlineDesc recoloured = d.outlines;
  recoloured.silhouette.color = Color(0.f, 0.f, 1.f);
  EXPECT_EQ(resolve_final(r.session->film(), compile_resolve_settings(d.render, recoloured)).at(x, y),
            Color(0.f, 0.f, 1.f));
}

TEST(Outlines, ObjectOverrideColourWins) {
  SceneDesc d = quad_in_front_of_quad(160, 80);
  d.objects[1].lines.override_color = true;
  d.objects[1].lines.color = Color(0.f, 1.f, 0.f);
  const Rendered r = render(d, 16);
  const int x = int(right_edge_x(*r.scene)), y = 40;
  const Color c = resolve_final(r.session->film(), *r.scene).at(x, y);
  EXPECT_NEAR(c.g, 1.f, 1e-5f);
  EXPECT_NEAR(c.r, 0.f, 1e-5f);
}

TEST(Outlines, NoLineTypeMeansNoLineWork) {
  SceneDesc d = quad_in_front_of_quad(32, 16);
  d.outlines.silhouette.enabled = false;
  const Rendered r = render(d, 2);
  EXPECT_FALSE(r.session->film().has_lines());
  // Camera rays plus at most two bounces with a shadow ray each: no stencil rays.
  EXPECT_FALSE(r.scene->lines.active);
  SceneDesc master_off = quad_in_front_of_quad(32, 16);
  master_off.outlines.enabled = false;
  EXPECT_FALSE(render(master_off, 1).session->film().has_lines());
}

TEST(Outlines, DebugViewsSeparateTheTypes) {
  SceneDesc d = quad_in_front_of_quad(120, 60);
  d.materials.push_back({"other", DiffuseDesc{Color(0.3f)}, {}});
  d.objects[1].material = "other";
  d.outlines.material.enabled = true;
  d.outlines.crease.enabled = true;
  const Rendered r = render(d, 8);
  EXPECT_GT(total(r.aov(Aov::outline_silhouette)), 0.f);
  EXPECT_GT(total(r.aov(Aov::outline_material)), 0.f);
  EXPECT_EQ(total(r.aov(Aov::outline_crease)), 0.f);  // flat quads have no creases
  EXPECT_EQ(total(r.aov(Aov::outline_object)), 0.f);  // not enabled
}

TEST(Outlines, CoverageIsTheSameAtAnyThreadCount) {
  const SceneDesc d = quad_in_front_of_quad(64, 32);
  const CompileResult c = compile_scene(d);
  RenderSession one(1), two(2);
  one.set_scene(c.scene);
  two.set_scene(c.scene);
  render_batch(one, {4, 0.0});
  render_batch(two, {4, 0.0});
  EXPECT_EQ(one.film().resolve_aov(Aov::outline).pixels, two.film().resolve_aov(Aov::outline).pixels);
}

}  // namespace
}  // namespace inkray
