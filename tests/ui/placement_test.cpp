// New objects land in front of the camera, inside the view, sized to it and beside
// what is already there; an imported mesh is fitted to the view from its bounds.
#include "ui/model/placement.h"
#include "core/camera/camera.h"
#include "core/compiler/compile_objects.h"
#include "support/file_helpers.h"
#include "support/render_helpers.h"
#include "ui/model/document.h"
#include "ui/model/scene_edits.h"

#include <gtest/gtest.h>

#include <fstream>

namespace inkray {
namespace {

// The object's world box lies in front of the camera and inside the image.
void expect_in_view(const SceneDesc& s, const ObjectDesc& o) {
  const Camera camera(s.camera, s.render.width, s.render.height);
  Point3 lo, hi;
  object_box(o, &lo, &hi);
  for (int i = 0; i < 8; ++i) {
    const Point3 corner(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    Vec2 px;
    ASSERT_TRUE(camera.project(corner, &px)) << o.name << " corner " << i << " is behind the camera";
    EXPECT_GE(px.x, 0.f) << o.name;
    EXPECT_LE(px.x, float(s.render.width)) << o.name;
    EXPECT_GE(px.y, 0.f) << o.name;
    EXPECT_LE(px.y, float(s.render.height)) << o.name;
  }
}

// Whether two objects are apart: balls measured as balls, anything else by its box.
bool apart(const ObjectDesc& a, const ObjectDesc& b) {
  const auto ball = [](const ObjectDesc& o, Point3* c, float* r) {
    const auto* s = std::get_if<SphereDesc>(&o.shape);
    if (!s) return false;
    *c = transform_from_desc(o.transform).point(s->center);
    *r = s->radius * max_component(o.transform.scale);
    return true;
  };
  Point3 ca(0.f), cb(0.f), alo, ahi, blo, bhi;
  float ra = 0.f, rb = 0.f;
  const bool a_ball = ball(a, &ca, &ra), b_ball = ball(b, &cb, &rb);
  object_box(a, &alo, &ahi);
  object_box(b, &blo, &bhi);
  const auto box_distance = [](const Point3& p, const Point3& lo, const Point3& hi) {
    return glm::length(glm::max(glm::max(lo - p, p - hi), Vec3(0.f)));
  };
  if (a_ball && b_ball) return glm::length(ca - cb) > ra + rb;
  if (a_ball) return box_distance(ca, blo, bhi) > ra;
  if (b_ball) return box_distance(cb, alo, ahi) > rb;
  return !(glm::all(glm::lessThan(alo, bhi)) && glm::all(glm::lessThan(blo, ahi)));
}

TEST(Placement, AnEmptySceneGetsItAtTheTargetSizedToTheView) {
  SceneDesc s;
  s.camera.look_from = Point3(0.f, 0.f, 8.f);
  s.camera.look_at = Point3(0.f, 0.f, 0.f);
  const Selection sel = add_shape(s, NewShape::sphere);
  const ObjectDesc& o = s.objects[size_t(sel.index)];
  EXPECT_EQ(o.transform.translate, s.camera.look_at);
  const auto& sphere = std::get<SphereDesc>(o.shape);
  EXPECT_NEAR(2.f * sphere.radius, kNewShapeFraction * visible_height(s.camera, 8.f), 1e-5f);
  expect_in_view(s, o);
}

TEST(Placement, NewShapesGoBesideExistingOnes) {
  SceneDesc s = Document::default_scene();  // a ball sits at the camera's target
  for (NewShape shape : {NewShape::sphere, NewShape::box, NewShape::quad, NewShape::sphere}) {
    const Selection sel = add_shape(s, shape);
    const ObjectDesc& o = s.objects[size_t(sel.index)];
    expect_in_view(s, o);
    for (int i = 0; i < sel.index; ++i) {
      EXPECT_TRUE(apart(o, s.objects[size_t(i)])) << o.name << " is inside " << s.objects[size_t(i)].name;
    }
  }
}

TEST(Placement, ACrowdedViewStillPlacesInView) {
  SceneDesc s = Document::default_scene();
  ObjectDesc room;  // around the camera: every spot overlaps it
  room.name = "room";
  room.shape = BoxDesc{Point3(-50.f), Point3(50.f)};
  s.objects.push_back(room);
  const Selection sel = add_shape(s, NewShape::sphere);
  expect_in_view(s, s.objects[size_t(sel.index)]);
}

TEST(Placement, BallsAreMeasuredAsBallsNotBoxes) {
  // Three balls in a row fill the view's middle; the new one finds the gap above them
  // that their boxes would hide.
  SceneDesc s = testing::sized_scene(800, 450);
  s.camera = {{.look_from = Point3(0.f, 2.6f, 9.f), .look_at = Point3(0.f, 0.9f, 0.f), .vfov = 32.f}};
  for (float x : {-2.4f, 0.f, 2.4f}) {
    ObjectDesc ball;
    ball.name = "ball" + std::to_string(int(x * 10));
    ball.shape = SphereDesc{Point3(x, 0.9f, x == 0.f ? -0.6f : 0.f), 0.9f};
    s.objects.push_back(ball);
  }
  const Placement p = place_in_view(s);
  for (const ObjectDesc& o : s.objects) {
    const auto& ball = std::get<SphereDesc>(o.shape);
    EXPECT_GT(glm::length(p.center - ball.center), ball.radius + 0.5f * p.size) << o.name;
  }
  EXPECT_LT(std::abs(p.center.x), 2.4f);  // above the row, not beyond its ends
}

TEST(Placement, ScalesWithTheScenesUnits) {
  // A scene in millimetres: the same view, a thousand times larger.
  SceneDesc s;
  s.camera.look_from = Point3(0.f, 1500.f, 6000.f);
  s.camera.look_at = Point3(0.f, 700.f, 0.f);
  const Selection sel = add_shape(s, NewShape::box);
  const auto& box = std::get<BoxDesc>(s.objects[size_t(sel.index)].shape);
  const float distance = glm::length(s.camera.look_at - s.camera.look_from);
  // Its diagonal spans the fraction of the view.
  EXPECT_NEAR(glm::length(box.max - box.min), kNewShapeFraction * visible_height(s.camera, distance), 1e-1f);
  expect_in_view(s, s.objects[size_t(sel.index)]);
}

TEST(Placement, ALightGoesAboveTheTargetInView) {
  SceneDesc s = Document::default_scene();
  const Selection sel = add_point_light(s);
  const auto& light = std::get<PointLightDesc>(s.lights[size_t(sel.index)].data);
  EXPECT_GT(light.position.y, s.camera.look_at.y);
  Vec2 px;
  const Camera camera(s.camera, s.render.width, s.render.height);
  ASSERT_TRUE(camera.project(light.position, &px));
  EXPECT_GT(px.y, 0.f);
  EXPECT_GT(light.intensity, 0.f);
}

TEST(Placement, AnImportedMeshIsFittedToTheView) {
  testing::ScratchFolder folder;
  {
    // A slab 200 x 50 x 20 units far off the origin, as CAD exports often are.
    std::ofstream obj(folder / "slab.obj");
    obj << "v 100 0 -10\nv 300 0 -10\nv 300 50 -10\nv 100 50 -10\n"
           "v 100 0 10\nv 300 0 10\nv 300 50 10\nv 100 50 10\n"
           "f 1 2 3 4\nf 5 6 7 8\nf 1 2 6 5\nf 4 3 7 8\n";
  }
  SceneDesc s = Document::default_scene();
  s.base_dir = folder.path();
  const Selection fitted = add_mesh(s, (folder / "slab.obj").string());
  const ObjectDesc& o = s.objects[size_t(fitted.index)];
  EXPECT_EQ(std::get<MeshDesc>(o.shape).path, "slab.obj");
  const Transform t = transform_from_desc(o.transform);
  const Point3 lo = t.point(Point3(100.f, 0.f, -10.f)), hi = t.point(Point3(300.f, 50.f, 10.f));
  // Its longest side spans the expected fraction of the view's height at the target.
  const float distance = glm::length(s.camera.look_at - s.camera.look_from);
  EXPECT_NEAR(hi.x - lo.x, kNewMeshFraction * visible_height(s.camera, distance), 1e-3f);
  const Camera camera(s.camera, s.render.width, s.render.height);
  for (const Point3& p : {lo, hi}) {
    Vec2 px;
    ASSERT_TRUE(camera.project(p, &px));
    EXPECT_GT(px.x, 0.f);
    EXPECT_LT(px.x, float(s.render.width));
    EXPECT_GT(px.y, 0.f);
    EXPECT_LT(px.y, float(s.render.height));
  }

  const Selection native = add_mesh(s, (folder / "slab.obj").string(), /*keep_native_size=*/true);
  EXPECT_EQ(s.objects[size_t(native.index)].transform, TransformDesc{});
  // An unreadable file is still added, unscaled at the view's centre; the compile says why.
  const Selection missing = add_mesh(s, (folder / "missing.obj").string());
  EXPECT_EQ(s.objects[size_t(missing.index)].transform.scale, Vec3(1.f));
}

}  // namespace
}  // namespace inkray
