// EmbreeScene::intersect_solid: the closest hit on what casts shadows. Where there is
// no paint it is intersect's hit; paint in front of a surface is passed through.
#include "core/geometry/embree_scene.h"

#include <gtest/gtest.h>

#include <memory>

namespace inkray {
namespace {

// A unit quad in z = 0, a layer of paint fully covering it (traced as quads).
std::shared_ptr<const ShapeBvh> paint_bvh() {
  auto mask = std::make_shared<AlphaMask>();
  mask->width = mask->height = 1;
  mask->texels = {255};
  mask->paint = true;
  mask->triangles.resize(2);
  mask->quads = true;
  mask->layer_thickness = 0.01f;
  return std::make_shared<const ShapeBvh>(
      std::make_shared<const Shape>(make_quad(Point3(0.f), {1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, Transform{})),
      std::move(mask));
}

TEST(IntersectSolid, WithoutPaintItIsTheClosestHit) {
  EmbreeScene scene;
  scene.add(make_box(Point3(-1.f), Point3(0.f, 1.f, 1.f), Transform{}));
  scene.add(Sphere{Point3(1.f, 0.f, 0.f), 0.8f, Transform{}});
  scene.commit();
  int hits = 0;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) {
      const Ray ray{{-2.f + 0.25f * float(i), -1.5f + 0.2f * float(j), 5.f}, {0.05f, 0.02f, -1.f}};
      Hit a, b;
      const bool hit = scene.intersect(ray, kInfinity, &a);
      ASSERT_EQ(scene.intersect_solid(ray, kInfinity, &b), hit);
      if (!hit) continue;
      ++hits;
      EXPECT_EQ(b.t, a.t);
      EXPECT_EQ(b.geometry, a.geometry);
      EXPECT_EQ(b.prim, a.prim);
      EXPECT_EQ(b.barycentric, a.barycentric);
    }
  EXPECT_GT(hits, 50);
}

TEST(IntersectSolid, PaintInFrontIsPassedThrough) {
  const auto paint = paint_bvh();
  EmbreeScene scene;
  // The wall the paint lies on, just behind it within its layer.
  const uint32_t wall =
      scene.add(make_quad(Point3(-1.f, -1.f, -0.005f), {3.f, 0.f, 0.f}, {0.f, 3.f, 0.f}, Transform{}));
  const uint32_t layer = scene.add(paint, Transform{}, paint->shared_shape());
  scene.commit();
  const Ray down{{0.5f, 0.5f, 1.f}, {0.f, 0.f, -1.f}};
  Hit seen, solid;
  ASSERT_TRUE(scene.intersect(down, kInfinity, &seen));
  EXPECT_EQ(seen.geometry, layer) << "the camera sees the paint";
  ASSERT_TRUE(scene.intersect_solid(down, kInfinity, &solid));
  EXPECT_EQ(solid.geometry, wall);
  EXPECT_FLOAT_EQ(solid.t, 1.005f);
  EXPECT_FALSE(scene.intersect_solid(down, 1.004f, &solid));
}

}  // namespace
}  // namespace inkray
