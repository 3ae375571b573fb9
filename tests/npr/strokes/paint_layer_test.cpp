// Paint (AlphaMask::paint) in the traced scene: overlapping strokes are seen
// in painting order whatever their heights, shadow rays pass through paint,
// hits on a mesh traced as quads name the right triangle, rays leaving a paint
// hit start clear of the layer, and paint hidden from indirect rays is skipped
// by them only.
#include "core/geometry/embree_scene.h"

#include <gtest/gtest.h>

namespace inkray {
namespace {

constexpr float kLayer = 0.003f;

// An opaque paint layer of `triangles` triangles traced as quads.
std::shared_ptr<AlphaMask> opaque_paint(size_t triangles) {
  auto mask = std::make_shared<AlphaMask>();
  mask->width = mask->height = 1;
  mask->texels = {255};
  mask->triangles.resize(triangles);
  mask->paint = true;
  mask->quads = true;
  mask->layer_thickness = kLayer;
  return mask;
}

// Two opaque paint quads over a floor at z = 0: quad 0 (painted first) at
// z = 0.002 over x in [0, 1], quad 1 (painted last) lower, at z = 0.001, over
// x in [0.5, 1.5]; each quad is the triangles (a, b, a1), (b, b1, a1).
struct PaintedFloor {
  EmbreeScene scene;
  uint32_t floor = 0, paint = 0;
  // `indirect` false hides the paint from RayKind::indirect rays.
  explicit PaintedFloor(bool indirect = true) {
    std::vector<Point3> p;
    std::vector<uint32_t> idx;
    for (const auto& [x0, z] : {std::pair{0.f, 0.002f}, std::pair{0.5f, 0.001f}}) {
      const uint32_t a = uint32_t(p.size());
      p.insert(p.end(), {{x0, 0.f, z}, {x0 + 1.f, 0.f, z}, {x0, 1.f, z}, {x0 + 1.f, 1.f, z}});
      idx.insert(idx.end(), {a, a + 1, a + 2, a + 1, a + 3, a + 2});
    }
    TriangleMesh mesh = make_mesh(p, {}, {}, idx, Transform{});
    auto mask = opaque_paint(4);
    floor = scene.add(make_quad(Point3(-1.f, -1.f, 0.f), {4.f, 0.f, 0.f}, {0.f, 3.f, 0.f}, Transform{}));
    auto world = std::make_shared<const Shape>(std::move(mesh));
    paint = scene.add(std::make_shared<const ShapeBvh>(world, std::move(mask)), Transform{}, world, indirect);
    scene.commit();
  }
  const TriangleMesh& mesh() const { return std::get<TriangleMesh>(scene.shape(paint)); }
};

Point3 on_triangle(const TriangleMesh& m, const Hit& hit) {
  const uint32_t* i = &m.indices[3 * hit.prim];
  const float b1 = hit.barycentric.x, b2 = hit.barycentric.y;
  return (1.f - b1 - b2) * m.positions[i[0]] + b1 * m.positions[i[1]] + b2 * m.positions[i[2]];
}

TEST(StrokePaintLayer, TheLastPaintedIsSeenWhateverItsHeight) {
  const PaintedFloor f;
  for (float x : {0.55f, 0.7f, 0.95f}) {
    for (float y : {0.1f, 0.5f, 0.9f}) {
      const Ray ray{{x, y, 1.f}, {0.f, 0.f, -1.f}};
      Hit hit;
      ASSERT_TRUE(f.scene.intersect(ray, kInfinity, &hit));
      EXPECT_EQ(hit.geometry, f.paint);
      EXPECT_GE(hit.prim, 2u) << "quad 0 lies higher, but quad 1 was painted over it";
      // The hit's triangle and barycentrics name the point the ray reached.
      const Point3 p = on_triangle(f.mesh(), hit);
      EXPECT_NEAR(glm::distance(p, ray.o + hit.t * ray.d), 0.f, 1e-5f);
      EXPECT_NEAR(p.z, 0.001f, 1e-6f);
    }
  }
  Hit hit;
  ASSERT_TRUE(f.scene.intersect(Ray{{0.2f, 0.3f, 1.f}, {0.f, 0.f, -1.f}}, kInfinity, &hit));
  EXPECT_LT(hit.prim, 2u);
  ASSERT_TRUE(f.scene.intersect(Ray{{-0.5f, 0.3f, 1.f}, {0.f, 0.f, -1.f}}, kInfinity, &hit));
  EXPECT_EQ(hit.geometry, f.floor);
}

TEST(StrokePaintLayer, QuadHitsNameBothHalves) {
  const PaintedFloor f;
  int halves[2] = {0, 0};
  for (int i = 0; i < 64; ++i) {
    const Ray ray{{0.05f + 0.4f * float(i % 8) / 8.f, 0.05f + float(i / 8) / 8.f, 1.f}, {0.f, 0.f, -1.f}};
    Hit hit;
    ASSERT_TRUE(f.scene.intersect(ray, kInfinity, &hit));
    ASSERT_LT(hit.prim, 2u);
    ++halves[hit.prim];
    EXPECT_NEAR(glm::distance(on_triangle(f.mesh(), hit), ray.o + hit.t * ray.d), 0.f, 1e-5f);
  }
  EXPECT_GT(halves[0], 0);
  EXPECT_GT(halves[1], 0);
}

TEST(StrokePaintLayer, ShadowRaysPassThroughPaint) {
  const PaintedFloor f;
  // From above to just over the floor, through both quads: paint casts no shadow.
  EXPECT_FALSE(f.scene.occluded(Ray{{0.7f, 0.5f, 1.f}, {0.f, 0.f, -1.f}}, 0.9995f));
  // The floor still does.
  EXPECT_TRUE(f.scene.occluded(Ray{{0.7f, 0.5f, 1.f}, {0.f, 0.f, -1.f}}, 1.5f));
}

TEST(StrokePaintLayer, RaysLeavingPaintStartAboveTheLayer) {
  const PaintedFloor f;
  const Ray ray{{0.7f, 0.5f, 1.f}, {0.f, 0.f, -1.f}};
  Hit hit;
  ASSERT_TRUE(f.scene.intersect(ray, kInfinity, &hit));
  const SurfaceInteraction si = f.scene.interaction(ray, hit);
  EXPECT_GE(si.p.z, 0.001f + kLayer * 0.999f);
  EXPECT_GT(si.ng.z, 0.f);
  // Straight up and along the layer, nothing is in the way.
  Hit next;
  EXPECT_FALSE(f.scene.intersect(Ray{si.p, {0.f, 0.f, 1.f}}, kInfinity, &next));
  EXPECT_FALSE(f.scene.intersect(Ray{si.p, glm::normalize(Vec3(1.f, 0.f, 0.05f))}, kInfinity, &next));
}

TEST(StrokePaintLayer, IndirectRaysSkipPaintHiddenFromThemOnly) {
  for (const bool indirect : {true, false}) {
    SCOPED_TRACE(indirect ? "seen by indirect rays" : "hidden from indirect rays");
    const PaintedFloor f(indirect);
    const Ray ray{{0.7f, 0.5f, 1.f}, {0.f, 0.f, -1.f}};
    Hit hit;
    ASSERT_TRUE(f.scene.intersect(ray, kInfinity, &hit, RayKind::camera));
    EXPECT_EQ(hit.geometry, f.paint);
    EXPECT_GE(hit.prim, 2u);
    ASSERT_TRUE(f.scene.intersect(ray, kInfinity, &hit, RayKind::indirect));
    if (indirect) {
      EXPECT_EQ(hit.geometry, f.paint);
      EXPECT_GE(hit.prim, 2u) << "paint order holds for indirect rays too";
    } else {
      EXPECT_EQ(hit.geometry, f.floor) << "the surface under the paint stands in for it";
    }
    // Shadow rays never see paint.
    EXPECT_FALSE(f.scene.occluded(ray, 0.9995f));
  }
}

// Quad 0 and quad 1 of PaintedFloor as two emitters' paint on a floor: the one
// added later is on top where they overlap, whether camera rays find the floor
// first and ask the paint's BVHs directly (every paint instance placed by the
// identity) or ask the top level (one placed by a translation).
TEST(StrokePaintLayer, PaintAddedLaterIsOnTopAcrossInstances) {
  for (const bool moved : {false, true}) {
    SCOPED_TRACE(moved ? "second paint placed by a translation" : "paint in world space");
    EmbreeScene scene;
    scene.add(make_quad(Point3(-1.f, -1.f, 0.f), {4.f, 0.f, 0.f}, {0.f, 3.f, 0.f}, Transform{}));
    std::vector<uint32_t> paint;
    for (const auto& [x0, z] : {std::pair{0.f, 0.002f}, std::pair{0.5f, 0.001f}}) {
      const float shift = moved && x0 > 0.f ? 0.25f : 0.f;  // the BVH's mesh sits that far to -x
      const std::vector<Point3> p = {
          {x0 - shift, 0.f, z}, {x0 + 1.f - shift, 0.f, z}, {x0 - shift, 1.f, z}, {x0 + 1.f - shift, 1.f, z}};
      auto mask = opaque_paint(2);
      const Transform to_world = Transform::translate({shift, 0.f, 0.f});
      auto local = std::make_shared<const Shape>(make_mesh(p, {}, {}, {0, 1, 2, 1, 3, 2}, Transform{}));
      auto world = std::make_shared<const Shape>(make_mesh(p, {}, {}, {0, 1, 2, 1, 3, 2}, to_world));
      paint.push_back(scene.add(std::make_shared<const ShapeBvh>(local, std::move(mask)), to_world, world));
    }
    scene.commit();
    for (float x : {0.55f, 0.8f, 0.95f}) {
      Hit hit;
      const Ray ray{{x, 0.5f, 1.f}, {0.f, 0.f, -1.f}};
      ASSERT_TRUE(scene.intersect(ray, kInfinity, &hit));
      EXPECT_EQ(hit.geometry, paint[1]) << "the second paint lies lower but was added later";
      EXPECT_NEAR(ray.o.z + hit.t * ray.d.z, 0.001f, 1e-6f);
    }
    Hit hit;
    ASSERT_TRUE(scene.intersect(Ray{{0.2f, 0.5f, 1.f}, {0.f, 0.f, -1.f}}, kInfinity, &hit));
    EXPECT_EQ(hit.geometry, paint[0]);
  }
}

// Camera rays see paint on the surface they hit, in paint order: paint where a
// ray meets no surface (a sheet past a silhouette) is not seen.
TEST(StrokePaintLayer, CameraRaysSeePaintOnlyOnASurface) {
  EmbreeScene scene;
  scene.add(make_quad(Point3(0.f, 0.f, 0.f), {1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, Transform{}));
  const std::vector<Point3> p = {
      {-1.f, 0.f, 0.001f}, {2.f, 0.f, 0.001f}, {-1.f, 1.f, 0.001f}, {2.f, 1.f, 0.001f}};
  auto mask = opaque_paint(2);
  auto world = std::make_shared<const Shape>(make_mesh(p, {}, {}, {0, 1, 2, 1, 3, 2}, Transform{}));
  const uint32_t paint =
      scene.add(std::make_shared<const ShapeBvh>(world, std::move(mask)), Transform{}, world);
  scene.commit();
  Hit hit;
  ASSERT_TRUE(scene.intersect(Ray{{0.5f, 0.5f, 1.f}, {0.f, 0.f, -1.f}}, kInfinity, &hit));
  EXPECT_EQ(hit.geometry, paint);
  EXPECT_NEAR(1.f - hit.t, 0.001f, 1e-6f);
  // Seen at a grazing angle too: the stretch grows with 1 / cos.
  const Vec3 grazing = glm::normalize(Vec3(0.f, 0.95f, -0.05f));
  ASSERT_TRUE(
      scene.intersect(Ray{Point3(0.5f, 0.5f, 0.f) - grazing * (0.2f / grazing.y), grazing}, kInfinity, &hit));
  EXPECT_EQ(hit.geometry, paint);
  EXPECT_FALSE(scene.intersect(Ray{{1.5f, 0.5f, 1.f}, {0.f, 0.f, -1.f}}, kInfinity, &hit))
      << "beside the surface the paint is a sheet in the air";
}

}  // namespace
}  // namespace inkray
