// An alpha-tested BVH shared by instances under different brushes: each instance's
// alpha test reads its own brush (EmbreeScene::add), through a top level or asked
// directly for paint order, and one whose brush is its mask's own texture decides every
// hit as an instance without a brush does.
#include "core/geometry/embree_scene.h"
#include "core/math/hash.h"

#include <gtest/gtest.h>

#include <memory>

namespace inkray {
namespace {

// One texel of coverage `alpha` (255 opaque).
std::shared_ptr<const AlphaTexture> flat_brush(uint8_t alpha) {
  auto brush = std::make_shared<AlphaTexture>();
  brush->width = brush->height = 1;
  brush->texels = {alpha};
  return brush;
}

// A unit quad in z = 0 (uv = xy), alpha-tested under an opaque texture of its own.
std::shared_ptr<const ShapeBvh> quad_bvh(bool paint) {
  auto mask = std::make_shared<AlphaMask>();
  mask->width = mask->height = 1;
  mask->texels = {255};
  mask->paint = paint;
  if (paint) {
    mask->triangles.resize(2);  // any coordinates: the brushes are one texel
    mask->quads = true;
    mask->layer_thickness = 0.01f;
  }
  return std::make_shared<const ShapeBvh>(
      std::make_shared<const Shape>(make_quad(Point3(0.f), {1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, Transform{})),
      std::move(mask));
}

std::shared_ptr<const Shape> placed(const ShapeBvh& bvh, const Transform& t) {
  return std::make_shared<const Shape>(transformed(std::get<TriangleMesh>(bvh.shape()), t));
}

const Ray kDown{{0.5f, 0.5f, 1.f}, {0.f, 0.f, -1.f}};

TEST(InstanceBrush, EachInstanceTestsHitsAgainstItsOwnBrush) {
  const auto bvh = quad_bvh(false);
  const Transform lower = Transform::translate(Vec3(0.f, 0.f, -0.5f));
  EmbreeScene scene;
  const uint32_t clear = scene.add(bvh, Transform{}, bvh->shared_shape(), true, nullptr, flat_brush(0));
  const uint32_t solid = scene.add(bvh, lower, placed(*bvh, lower), true, nullptr, flat_brush(255));
  scene.commit();
  EXPECT_EQ(&scene.bvh(clear), &scene.bvh(solid));
  Hit hit;
  ASSERT_TRUE(scene.intersect(kDown, kInfinity, &hit));
  EXPECT_EQ(hit.geometry, solid) << "the upper instance's brush lets the ray through";
  EXPECT_FALSE(scene.occluded(kDown, 1.2f));
  EXPECT_TRUE(scene.occluded(kDown, 1.7f));
}

TEST(InstanceBrush, TheMasksOwnTextureAsABrushDecidesAsNoBrush) {
  const auto bvh = quad_bvh(false);
  auto half = std::make_shared<AlphaMask>(*bvh->mask());
  half->texels = {128};
  const auto shared = std::make_shared<const ShapeBvh>(bvh->shared_shape(), half);
  EmbreeScene bare, brushed;
  bare.add(shared, Transform{}, shared->shared_shape());
  brushed.add(shared, Transform{}, shared->shared_shape(), true, nullptr,
              std::make_shared<const AlphaTexture>(*half));
  bare.commit();
  brushed.commit();
  int hits = 0;
  for (uint32_t i = 0; i < 4000; ++i) {
    const auto u = [&](uint32_t d) { return u32_to_unit_float(hash_combine(i, d, 0x7u)); };
    const Point3 from(u(0) * 2.f - 0.5f, u(1) * 2.f - 0.5f, 1.f);
    const Ray ray{from, Point3(0.1f + 0.8f * u(2), 0.1f + 0.8f * u(3), 0.f) - from};
    Hit a, b;
    const bool found = bare.intersect(ray, kInfinity, &a);
    ASSERT_EQ(found, brushed.intersect(ray, kInfinity, &b));
    ASSERT_EQ(bare.occluded(ray, 2.f), brushed.occluded(ray, 2.f));
    hits += found;
  }
  EXPECT_GT(hits, 1000);
  EXPECT_LT(hits, 3000);
}

TEST(InstanceBrush, PaintOrderReadsEachInstancesBrush) {
  // Two coats of one shared paint BVH on a floor, both in world space: the one painted
  // last is seen where its brush covers, the first where it does not.
  const auto bvh = quad_bvh(true);
  for (const bool last_covers : {true, false}) {
    SCOPED_TRACE(last_covers ? "the last coat covers" : "the last coat is clear");
    EmbreeScene scene;
    scene.add(make_quad(Point3(-1.f, -1.f, -0.002f), {3.f, 0.f, 0.f}, {0.f, 3.f, 0.f}, Transform{}));
    const uint32_t first = scene.add(bvh, Transform{}, bvh->shared_shape(), true, nullptr, flat_brush(255));
    const uint32_t last =
        scene.add(bvh, Transform{}, bvh->shared_shape(), true, nullptr, flat_brush(last_covers ? 255 : 0));
    scene.commit();
    for (const RayKind kind : {RayKind::camera, RayKind::indirect}) {
      Hit hit;
      ASSERT_TRUE(scene.intersect(kDown, kInfinity, &hit, kind));
      EXPECT_EQ(hit.geometry, last_covers ? last : first);
    }
  }
}

}  // namespace
}  // namespace inkray
