// EmbreeScene::commit(&previous) traces the shapes an edit placed anew from a small
// second top level and shares previous's main one while the same few keep moving
// (docs/architecture.md, "Edits of large documents"). Whatever the split, every ray
// finds exactly what a top level built from scratch gives it.
#include "core/geometry/embree_scene.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <vector>

namespace inkray {
namespace {

// A field of spheres and boxes on a 10 x 10 grid, every shape an instance of one of
// two shared BVHs.
struct Field {
  std::shared_ptr<const ShapeBvh> sphere =
      std::make_shared<const ShapeBvh>(std::make_shared<const Shape>(Sphere{Point3(0.f), 0.4f, Transform{}}));
  std::shared_ptr<const ShapeBvh> box = std::make_shared<const ShapeBvh>(
      std::make_shared<const Shape>(make_box(Point3(-0.35f), Point3(0.35f), Transform{})));
  std::vector<Transform> placements;

  Field() {
    for (int i = 0; i < 100; ++i)
      placements.push_back(Transform::translate(Vec3(float(i % 10) - 4.5f, 0.f, float(i / 10) - 4.5f)));
  }
  const std::shared_ptr<const ShapeBvh>& bvh(size_t i) const { return i % 2 ? box : sphere; }
  std::shared_ptr<const Shape> world(size_t i) const {
    const Transform& t = placements[i];
    if (i % 2) return std::make_shared<const Shape>(transformed(std::get<TriangleMesh>(box->shape()), t));
    return std::make_shared<const Shape>(Sphere{Point3(0.f), 0.4f, t});
  }
  // Every shape placed anew, committed with no previous scene.
  EmbreeScene from_scratch() const {
    EmbreeScene scene;
    for (size_t i = 0; i < placements.size(); ++i) scene.add(bvh(i), placements[i], world(i));
    scene.commit();
    return scene;
  }
  // `previous` with shape `i` moved to where placements[i] now says, committed against it.
  EmbreeScene moved(const EmbreeScene& previous, size_t i) const {
    EmbreeScene scene = EmbreeScene::with_instances_of(previous);
    scene.replace(uint32_t(i), bvh(i), placements[i], world(i));
    scene.commit(&previous);
    return scene;
  }
};

// Rays from above and from the side over the field, and shadow rays between shapes.
void expect_same_hits(const EmbreeScene& a, const EmbreeScene& b) {
  int hits = 0;
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 48; ++x) {
      const Vec2 s(float(x) / 47.f * 11.f - 5.5f, float(y) / 47.f * 11.f - 5.5f);
      for (const Ray& ray : {Ray{Point3(s.x, 6.f, s.y), Vec3(0.05f, -1.f, 0.02f)},
                             Ray{Point3(-8.f, 0.1f + 0.01f * s.y, s.x), Vec3(1.f, 0.f, 0.03f * s.y)}}) {
        Hit ha, hb;
        const bool found_a = a.intersect(ray, 100.f, &ha), found_b = b.intersect(ray, 100.f, &hb);
        ASSERT_EQ(found_a, found_b) << "ray " << x << ", " << y;
        EXPECT_EQ(a.occluded(ray, 100.f), b.occluded(ray, 100.f)) << "ray " << x << ", " << y;
        if (!found_a) continue;
        ++hits;
        EXPECT_EQ(std::memcmp(&ha.t, &hb.t, sizeof ha.t), 0) << "ray " << x << ", " << y;
        EXPECT_EQ(ha.geometry, hb.geometry) << "ray " << x << ", " << y;
        EXPECT_EQ(ha.prim, hb.prim) << "ray " << x << ", " << y;
        EXPECT_EQ(ha.barycentric, hb.barycentric) << "ray " << x << ", " << y;
      }
    }
  }
  EXPECT_GT(hits, 1000);  // the rays see the field
  Point3 lo_a, hi_a, lo_b, hi_b;
  a.bounds(&lo_a, &hi_a);
  b.bounds(&lo_b, &hi_b);
  EXPECT_EQ(lo_a, lo_b);
  EXPECT_EQ(hi_a, hi_b);
}

TEST(LiveTopLevel, AMovedShapeIsTracedApartAndHitsAsFromScratch) {
  Field field;
  const EmbreeScene before = field.from_scratch();
  EXPECT_TRUE(before.live_shapes().empty());
  field.placements[7] = Transform::translate(Vec3(0.7f, 0.3f, -2.f));  // into its neighbours' gaps
  const EmbreeScene after = field.moved(before, 7);
  EXPECT_EQ(after.live_shapes(), std::vector<uint32_t>{7});
  EXPECT_FALSE(after.shares_top_level(before));  // the main one no longer holds shape 7 where it was
  expect_same_hits(after, field.from_scratch());
}

TEST(LiveTopLevel, MovingTheSameShapeAgainSharesTheMainTopLevel) {
  Field field;
  EmbreeScene scene = field.from_scratch();
  std::vector<EmbreeScene> kept;  // each edit's scene, as renders of it may still run
  for (int step = 1; step <= 6; ++step) {
    field.placements[42] = Transform::translate(Vec3(0.25f * float(step), 0.1f * float(step), 0.5f));
    EmbreeScene next = field.moved(scene, 42);
    EXPECT_EQ(next.live_shapes(), std::vector<uint32_t>{42});
    EXPECT_EQ(next.shares_top_level(scene), step > 1) << "step " << step;
    kept.push_back(scene);
    scene = next;
  }
  expect_same_hits(scene, field.from_scratch());
  // A commit that changes nothing (a material edit) keeps both top levels as they are.
  EmbreeScene same = EmbreeScene::with_instances_of(scene);
  same.commit(&scene);
  EXPECT_EQ(same.live_shapes(), std::vector<uint32_t>{42});
  EXPECT_TRUE(same.shares_top_level(scene));
  expect_same_hits(same, field.from_scratch());
}

TEST(LiveTopLevel, ManyMovedShapesFoldBackIntoOneTopLevel) {
  Field field;
  EmbreeScene scene = field.from_scratch();
  for (size_t i = 0; i < EmbreeScene::kMostLiveShapes + 1; ++i) {
    field.placements[i] = field.placements[i] * Transform::translate(Vec3(0.f, 0.2f, 0.f));
    scene = field.moved(scene, i);
    const size_t live = i < EmbreeScene::kMostLiveShapes ? i + 1 : 0;
    ASSERT_EQ(scene.live_shapes().size(), live) << "after moving " << i + 1 << " shapes";
  }
  expect_same_hits(scene, field.from_scratch());
}

TEST(LiveTopLevel, AnEditOfEveryShapeBuildsOneTopLevel) {
  Field field;
  const EmbreeScene before = field.from_scratch();
  EmbreeScene scene = EmbreeScene::with_instances_of(before);
  for (size_t i = 0; i < field.placements.size(); ++i) {
    field.placements[i] = field.placements[i] * Transform::translate(Vec3(0.f, 0.f, 0.1f));
    scene.replace(uint32_t(i), field.bvh(i), field.placements[i], field.world(i));
  }
  scene.commit(&before);
  EXPECT_TRUE(scene.live_shapes().empty());
  expect_same_hits(scene, field.from_scratch());
}

}  // namespace
}  // namespace inkray
