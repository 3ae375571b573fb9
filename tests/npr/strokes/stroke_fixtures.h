// Surfaces and emitters the stroke tests share.
#pragma once

#include "core/npr/strokes/stroke_mesh.h"
#include "core/npr/strokes/stroke_placement.h"
#include "core/npr/strokes/stroke_surface.h"
#include "core/document/npr_desc.h"

#include <gtest/gtest.h>

namespace inkray::testing {

// A round sphere away from the origin, so float rounding of positions matters.
inline Sphere test_sphere() {
  Sphere s;
  s.center = Point3(0.f);
  s.radius = 1.5f;
  s.to_world = Transform::translate({3.f, -2.f, 5.f});
  return s;
}

// A mesh surface refers to its mesh, so the box lives as long as the tests.
inline const Shape& test_box() {
  static const Shape box = make_box(Point3(-1.f, -0.5f, -0.75f), Point3(1.f, 0.5f, 0.75f), Transform{});
  return box;
}

// The shape must outlive the surface when it is a mesh.
inline StrokeSurface surface_of(const Shape& shape) {
  std::string error;
  auto surface = StrokeSurface::from_shape(shape, &error);
  EXPECT_TRUE(surface) << error;
  return std::move(*surface);
}

inline StrokeEmitterDesc test_emitter(int count, int seed = 1) {
  return {.name = "paint",
          .object = "thing",
          .seed = seed,
          .count = count,
          .width_min = 0.04f,
          .width_max = 0.08f,
          .length_min = 0.15f,
          .length_max = 0.3f,
          .rotation_jitter = 30.f};
}

// Roots placed by the emitter's seed, every stroke mid-grey, ribbons built.
inline StrokeGeometry build_test_strokes(const StrokeSurface& surface, const StrokeEmitterDesc& e) {
  const auto roots = place_roots(surface, size_t(e.count), uint32_t(e.seed));
  const std::vector<Color> colors(roots.size(), Color(0.5f));
  return build_stroke_mesh(surface, roots, colors, e);
}

}  // namespace inkray::testing
