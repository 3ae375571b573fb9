// The alpha test during traversal: rays pass through a brush's transparent
// texels, stop at its opaque ones, and shadow rays through partial coverage
// are blocked as often as the coverage says.
#include "core/geometry/embree_scene.h"
#include "core/math/hash.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace inkray {
namespace {

// A unit quad in z = 0 (uv = xy) under a mask of one constant per half:
// left (u < 0.5) and right.
std::shared_ptr<AlphaMask> halves(uint8_t left, uint8_t right) {
  auto mask = std::make_shared<AlphaMask>();
  mask->width = 8;
  mask->height = 4;
  mask->texels.resize(32);
  for (int v = 0; v < 4; ++v)
    for (int u = 0; u < 8; ++u) mask->at(0, u, v) = u < 4 ? left : right;
  return mask;
}

struct Layer {
  EmbreeScene scene;
  uint32_t quad = 0, wall = 0;
  explicit Layer(std::shared_ptr<AlphaMask> mask) {
    quad = scene.add(make_quad(Point3(0.f), {1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, Transform{}), std::move(mask));
    // An opaque wall behind it.
    wall = scene.add(make_quad(Point3(-1.f, -1.f, -1.f), {3.f, 0.f, 0.f}, {0.f, 3.f, 0.f}, Transform{}));
    scene.commit();
  }
};

TEST(StrokeAlphaTest, TransparentTexelsLetRaysThroughOpaqueOnesStopThem) {
  Layer layer(halves(0, 255));
  for (int i = 0; i < 64; ++i) {
    const float y = (float(i) + 0.5f) / 64.f;
    Hit hit;
    ASSERT_TRUE(layer.scene.intersect(Ray{{0.2f, y, 1.f}, {0.f, 0.f, -1.f}}, kInfinity, &hit));
    EXPECT_EQ(hit.geometry, layer.wall);
    ASSERT_TRUE(layer.scene.intersect(Ray{{0.8f, y, 1.f}, {0.f, 0.f, -1.f}}, kInfinity, &hit));
    EXPECT_EQ(hit.geometry, layer.quad);
    EXPECT_FALSE(layer.scene.occluded(Ray{{0.2f, y, 1.f}, {0.f, 0.f, -1.f}}, 1.5f));
    EXPECT_TRUE(layer.scene.occluded(Ray{{0.8f, y, 1.f}, {0.f, 0.f, -1.f}}, 1.5f));
  }
}

TEST(StrokeAlphaTest, ShadowRaysSeePartialCoverage) {
  const uint8_t texel = 77;  // alpha 0.302
  Layer layer(halves(texel, texel));
  const int n = 20000;
  int blocked = 0, hits = 0;
  for (int i = 0; i < n; ++i) {
    // Rays from random points above to random points on the quad.
    const auto u = [&](uint32_t d) { return u32_to_unit_float(hash_combine(uint32_t(i), d, 0x51u)); };
    const Point3 from(u(0) * 2.f - 0.5f, u(1) * 2.f - 0.5f, 1.f + u(2));
    const Point3 to(0.05f + 0.9f * u(3), 0.05f + 0.9f * u(4), 0.f);
    const Ray ray{from, to - from};
    blocked += layer.scene.occluded(ray, 1.f) ? 1 : 0;
    Hit hit;
    hits += layer.scene.intersect(ray, kInfinity, &hit) && hit.geometry == layer.quad ? 1 : 0;
  }
  const double alpha = texel / 255.0, sigma = std::sqrt(alpha * (1.0 - alpha) / n);
  EXPECT_NEAR(double(blocked) / n, alpha, 4.0 * sigma);
  EXPECT_NEAR(double(hits) / n, alpha, 4.0 * sigma);
}

TEST(StrokeAlphaTest, RaysStartingInsideTheLayerIgnoreIt) {
  auto mask = halves(255, 255);
  mask->layer_thickness = 0.01f;
  Layer layer(mask);
  // From just below the layer (the surface it is painted on) up through it.
  EXPECT_FALSE(layer.scene.occluded(Ray{{0.5f, 0.5f, -0.005f}, {0.f, 0.f, 1.f}}, 10.f));
  // From farther away the layer blocks.
  EXPECT_TRUE(layer.scene.occluded(Ray{{0.5f, 0.5f, -0.5f}, {0.f, 0.f, 1.f}}, 10.f));
}

TEST(StrokeAlphaTest, CoverageIsBilinearAndClamped) {
  const auto mask = halves(0, 255);
  EXPECT_EQ(mask->coverage({0.f, 0.5f}, 0), 0.f);
  EXPECT_EQ(mask->coverage({1.f, 0.5f}, 0), 1.f);
  EXPECT_NEAR(mask->coverage({0.5f, 0.5f}, 0), 0.5f, 1e-6f);
  EXPECT_EQ(mask->coverage({-3.f, 7.f}, 0), 0.f);
  EXPECT_EQ(mask->coverage({std::nanf(""), 0.5f}, 0), 0.f);
}

}  // namespace
}  // namespace inkray
