// Small helpers for tests that render: compile a SceneDesc and render it.
#pragma once

#include "core/render/batch_render.h"
#include "core/compiler/compile.h"
#include "core/film/resolve.h"

#include <algorithm>

#include <gtest/gtest.h>

namespace inkray::testing {

inline ObjectDesc make_object(std::string name, ShapeVariant shape, std::string material) {
  ObjectDesc o;
  o.name = std::move(name);
  o.shape = std::move(shape);
  o.material = std::move(material);
  return o;
}

// Which of the common line types draw; unnamed ones keep OutlineDesc's defaults.
struct LineTypesOn {
  bool silhouette = true, object = true, crease = false, depth = false;
};

// Outlines on, `width` pixels wide in an image `reference_height` tall, the line types `on`.
inline void draw_outlines(OutlineDesc& outlines, float width, float reference_height, LineTypesOn on) {
  outlines.enabled = true;
  outlines.width = width;
  outlines.reference_height = reference_height;
  outlines.silhouette.enabled = on.silhouette;
  outlines.object.enabled = on.object;
  outlines.crease.enabled = on.crease;
  outlines.depth.enabled = on.depth;
}

// A compiled scene rendered for `spp` passes, kept with its session so tests
// can read the film's AOVs.
struct RenderedFilm {
  std::shared_ptr<const RenderScene> scene;
  std::unique_ptr<RenderSession> session;
  RgbImage aov(Aov a) const { return session->film().resolve_aov(a); }
};

inline RenderedFilm render_film(const SceneDesc& desc, int spp, AovSet aovs = {}) {
  const CompileResult c = compile_scene(desc);
  EXPECT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
  RenderedFilm r{c.scene, std::make_unique<RenderSession>(2)};
  if (!c.scene) return r;
  r.session->set_scene(c.scene, aovs);
  render_batch(*r.session, {spp, 0.0});
  return r;
}

// One pass of a compiled scene on one thread, resolved: the same scene renders the
// same pixels, so an incremental compile is compared with one from scratch by these.
inline RgbImage render_one_pass(const std::shared_ptr<const RenderScene>& scene) {
  RenderSession session(1);
  session.set_scene(scene);
  render_batch(session, {1, 0.0});
  return resolve_final(session.film(), *scene);
}

// Pixels that differ between two images of one size; all of them when the sizes differ.
inline size_t differing_pixels(const RgbImage& a, const RgbImage& b) {
  if (a.pixels.size() != b.pixels.size()) return std::max(a.pixels.size(), b.pixels.size());
  size_t n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i];
  return n;
}

// An empty scene of width x height pixels, its other settings the defaults.
inline SceneDesc sized_scene(int width, int height) {
  SceneDesc d;
  d.render.width = width;
  d.render.height = height;
  return d;
}

inline SceneDesc small_scene(int width, int height) {
  SceneDesc d = sized_scene(width, height);
  d.render.max_depth = 64;
  return d;
}

// A unit sphere "ball" of material "m": a scene to hang one feature on.
inline SceneDesc one_sphere_scene(int width, int height) {
  SceneDesc d = small_scene(width, height);
  d.materials = {{"m", DiffuseDesc{}, {}}};
  ObjectDesc o;
  o.name = "ball";
  o.material = "m";
  d.objects = {o};
  return d;
}

// Inside a closed white sphere at 1024 bounces: every path runs to the end, so one
// pass takes long (tests of time limits and cancelling).
inline SceneDesc white_room_scene(int width, int height) {
  SceneDesc d = small_scene(width, height);
  d.render.max_depth = 1024;
  d.camera.look_from = Point3(0.f);
  d.camera.look_at = Point3(0.f, 0.f, -1.f);
  d.materials = {{"white", DiffuseDesc{Color(1.f)}, {}}};
  ObjectDesc room;
  room.name = "room";
  room.material = "white";
  room.shape = SphereDesc{Point3(0.f), 10.f};
  d.objects = {room};
  return d;
}

inline RgbImage render_scene(const SceneDesc& desc, int spp, int threads = 2, RenderStats* stats = nullptr) {
  const CompileResult c = compile_scene(desc);
  EXPECT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
  if (!c.scene) return {};
  RenderSession session(threads);
  session.set_scene(c.scene);
  render_batch(session, {spp, 0.0});
  if (stats) *stats = session.stats();
  return session.film().resolve();
}

inline Color mean_color(const RgbImage& img, int x0, int y0, int x1, int y1) {
  glm::dvec3 sum(0.0);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) sum += glm::dvec3(img.at(x, y));
  return Color(sum / double((x1 - x0) * (y1 - y0)));
}

inline Color mean_color(const RgbImage& img) { return mean_color(img, 0, 0, img.width, img.height); }

}  // namespace inkray::testing
