// Hidden lines on scenes whose answer is known: the edges of a box behind a quad and
// behind another box, a box's own back edges, a sphere's contour behind a quad, and
// nothing where nothing is hidden.
#include "core/document/json_io.h"
#include "core/npr/lines/hidden_lines.h"
#include "support/render_helpers.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace inkray {
namespace {

using testing::draw_outlines;

constexpr int kWidth = 320, kHeight = 240;

// The camera at `eye` looking at the origin, the line types `on` drawn.
SceneDesc scene_from(const Point3& eye, testing::LineTypesOn on) {
  SceneDesc d = testing::small_scene(kWidth, kHeight);
  d.camera.look_from = eye;
  d.camera.look_at = Point3(0.f);
  d.camera.vfov = 30.f;
  d.materials.push_back({"grey", DiffuseDesc{Color(0.5f)}, {}});
  draw_outlines(d.outlines, 2.f, float(kHeight), on);
  return d;
}

void add(SceneDesc& d, const std::string& name, ShapeVariant shape) {
  d.objects.push_back(testing::make_object(name, std::move(shape), "grey"));
}

std::shared_ptr<const RenderScene> compiled(const SceneDesc& d) {
  const CompileResult c = compile_scene(d);
  EXPECT_TRUE(c.scene) << (c.errors.empty() ? "" : c.errors.front());
  return c.scene;
}

Vec2 film_of(const RenderScene& scene, const Point3& p) {
  Vec2 f(0.f);
  EXPECT_TRUE(scene.camera.project(p, &f));
  return f;
}

float distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.f, 1.f);
  return glm::length(p - (a + t * ab));
}

using Edge3 = std::array<Point3, 2>;

// The twelve edges of the box [lo, hi].
std::vector<Edge3> box_edges(const Point3& lo, const Point3& hi) {
  std::vector<Edge3> edges;
  const auto corner = [&](int i) {
    return Point3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
  };
  for (int i = 0; i < 8; ++i)
    for (int axis = 0; axis < 3; ++axis)
      if (!(i & (1 << axis))) edges.push_back({corner(i), corner(i | (1 << axis))});
  return edges;
}

// How far p lies on the image from the nearest of `edges`.
float distance_to_edges(const RenderScene& scene, Vec2 p, const std::vector<Edge3>& edges) {
  float best = 1e30f;
  for (const Edge3& e : edges)
    best = std::min(best, distance_to_segment(p, film_of(scene, e[0]), film_of(scene, e[1])));
  return best;
}

// The image rectangle of a quad facing the camera.
struct Rect {
  Vec2 lo{0.f}, hi{0.f};
  bool contains(Vec2 p, float margin) const {
    return p.x >= lo.x - margin && p.y >= lo.y - margin && p.x <= hi.x + margin && p.y <= hi.y + margin;
  }
};
Rect rect_of(const RenderScene& scene, const QuadDesc& q) {
  Rect r{Vec2(1e30f), Vec2(-1e30f)};
  for (const Point3& p :
       {q.corner, q.corner + q.edge_u, q.corner + q.edge_v, q.corner + q.edge_u + q.edge_v}) {
    r.lo = glm::min(r.lo, film_of(scene, p));
    r.hi = glm::max(r.hi, film_of(scene, p));
  }
  return r;
}

float total_length(const std::vector<Chain>& chains) {
  float len = 0.f;
  for (const Chain& c : chains) len += chain_length(c);
  return len;
}

// A box seen from above and to the side, its silhouette a hexagon; a tall quad in front
// of it, facing the camera, hides a band of it.
const Point3 kEye(3.f, 4.f, 9.f);
const Point3 kBoxLo(-1.f), kBoxHi(1.f);

QuadDesc occluder_facing(const Point3& eye, float half_width, float distance_from_eye) {
  const Vec3 w = glm::normalize(-eye), u = glm::normalize(glm::cross(w, Vec3(0.f, 1.f, 0.f)));
  const Vec3 v = glm::cross(u, w);
  const Point3 centre = eye + distance_from_eye * w;
  return {centre - half_width * u - 4.f * v, 2.f * half_width * u, 8.f * v};
}

TEST(HiddenLines, ABoxBehindAQuadIsHiddenExactlyWhereTheQuadCoversIt) {
  SceneDesc d = scene_from(kEye, {.silhouette = true, .object = false, .crease = false});
  add(d, "box", BoxDesc{kBoxLo, kBoxHi});
  const QuadDesc quad = occluder_facing(kEye, 0.3f, 5.f);
  add(d, "quad", quad);
  const auto scene = compiled(d);
  ASSERT_TRUE(scene);
  const std::vector<Chain> chains = hidden_chains(*scene);
  ASSERT_FALSE(chains.empty());
  const std::vector<Edge3> edges = box_edges(kBoxLo, kBoxHi);
  const Rect rect = rect_of(*scene, quad);
  for (const Chain& c : chains) {
    EXPECT_EQ(c.type, LineType::silhouette);
    EXPECT_EQ(c.covers, 1);
    EXPECT_EQ(c.object, 0);
    EXPECT_EQ(c.path, LinePath::direct);
    for (const ChainPoint& q : c.points) {
      EXPECT_LT(distance_to_edges(*scene, q.p, edges), 1.f) << q.p.x << ", " << q.p.y;
      EXPECT_TRUE(rect.contains(q.p, 0.5f)) << q.p.x << ", " << q.p.y;
      EXPECT_EQ(q.opacity, 1.f);
      EXPECT_GT(q.depth, 5.f);
    }
  }
  // The band crosses the hexagon's top and bottom: two stretches about the band's width
  // each (its sides slant, so a little more).
  const float band = rect.hi.x - rect.lo.x;
  EXPECT_EQ(chains.size(), 2u);
  EXPECT_GT(total_length(chains), 2.f * band - 2.f);
  EXPECT_LT(total_length(chains), 2.f * band * 1.6f);
}

TEST(HiddenLines, ABoxBehindABoxIsCoveredByItsFrontAndBack) {
  SceneDesc d = scene_from(kEye, {.silhouette = true, .object = false, .crease = false});
  add(d, "box", BoxDesc{kBoxLo, kBoxHi});
  // A small box between the camera and the middle of the big one's front bottom edge
  // (a silhouette edge: the face below it looks away).
  const Point3 centre = glm::mix(kEye, Point3(0.f, -1.f, 1.f), 0.6f);
  add(d, "front", BoxDesc{centre - Vec3(0.15f), centre + Vec3(0.15f)});
  const auto scene = compiled(d);
  ASSERT_TRUE(scene);
  const std::vector<Chain> chains = hidden_chains(*scene);
  ASSERT_FALSE(chains.empty());
  const std::vector<Edge3> edges = box_edges(kBoxLo, kBoxHi);
  for (const Chain& c : chains) {
    EXPECT_EQ(c.object, 0) << "nothing hides the small box";
    EXPECT_EQ(c.covers, 2) << "the rays cross the small box's front and back";
    for (const ChainPoint& q : c.points) EXPECT_LT(distance_to_edges(*scene, q.p, edges), 1.f);
  }
}

TEST(HiddenLines, ABoxAloneHidesItsBackEdgesAndShowsItsSilhouette) {
  SceneDesc d = scene_from(kEye, {.silhouette = true, .object = false, .crease = true});
  add(d, "box", BoxDesc{kBoxLo, kBoxHi});
  const auto scene = compiled(d);
  ASSERT_TRUE(scene);
  const std::vector<Chain> chains = hidden_chains(*scene);
  // The eye sees the faces +x, +y, +z: the hidden corner is lo, and the back edges
  // the three that meet there.
  const std::vector<Edge3> back = {{kBoxLo, Point3(kBoxHi.x, kBoxLo.y, kBoxLo.z)},
                                   {kBoxLo, Point3(kBoxLo.x, kBoxHi.y, kBoxLo.z)},
                                   {kBoxLo, Point3(kBoxLo.x, kBoxLo.y, kBoxHi.z)}};
  float back_length = 0.f;
  for (const Edge3& e : back) back_length += glm::length(film_of(*scene, e[1]) - film_of(*scene, e[0]));
  ASSERT_FALSE(chains.empty());
  for (const Chain& c : chains) {
    EXPECT_EQ(c.type, LineType::crease) << "the silhouette is in sight";
    EXPECT_EQ(c.covers, 1);
    for (const ChainPoint& q : c.points) EXPECT_LT(distance_to_edges(*scene, q.p, back), 1.f);
  }
  // The back edges run hidden right up to the silhouette's corners.
  EXPECT_NEAR(total_length(chains), back_length, 1.5f);
}

// A unit ball at the origin seen from z = 10, behind `quad`: its hidden chains, and the
// radius of its contour on the image (the tangent points lie asin(r / D) off the axis).
struct BallBehind {
  std::vector<Chain> chains;
  float radius_px = 0.f;
};
BallBehind ball_behind(const QuadDesc& quad) {
  SceneDesc d = scene_from(Point3(0.f, 0.f, 10.f), {.silhouette = true, .object = false, .crease = false});
  add(d, "ball", SphereDesc{Point3(0.f), 1.f});
  add(d, "quad", quad);
  const auto scene = compiled(d);
  if (!scene) return {};
  return {hidden_chains(*scene), scene->camera.world_to_pixels(std::tan(std::asin(0.1f)), 1.f)};
}

const Vec2 kCentre(kWidth / 2.f, kHeight / 2.f);

TEST(HiddenLines, ASphereBehindAQuadHidesTheArcBehindIt) {
  // The lower left quarter of the image, from the middle, behind a quad at z = 3.
  const BallBehind ball = ball_behind({Point3(-5.f, -5.f, 3.f), Vec3(5.f, 0.f, 0.f), Vec3(0.f, 5.f, 0.f)});
  ASSERT_EQ(ball.chains.size(), 1u);
  const Chain& c = ball.chains.front();
  EXPECT_EQ(c.type, LineType::silhouette);
  EXPECT_EQ(c.covers, 1);
  EXPECT_EQ(c.object, 0);
  EXPECT_FALSE(c.closed);
  for (const ChainPoint& q : c.points) {
    EXPECT_NEAR(glm::length(q.p - kCentre), ball.radius_px, 0.5f);
    EXPECT_LE(q.p.x, kCentre.x + 0.5f) << "only the arc behind the quad";
    EXPECT_GE(q.p.y, kCentre.y - 0.5f) << "only the arc behind the quad";
  }
  EXPECT_NEAR(chain_length(c), 0.5f * std::numbers::pi_v<float> * ball.radius_px, 1.f);
  // Open: it starts at its end with the smaller x, the arc's left end.
  EXPECT_NEAR(c.points.front().p.x, kCentre.x - ball.radius_px, 0.5f);
  EXPECT_NEAR(c.points.back().p.y, kCentre.y + ball.radius_px, 0.5f);
}

TEST(HiddenLines, ASphereWhollyBehindAQuadIsOneClockwiseLoop) {
  const BallBehind ball = ball_behind({Point3(-5.f, -5.f, 3.f), Vec3(10.f, 0.f, 0.f), Vec3(0.f, 10.f, 0.f)});
  ASSERT_EQ(ball.chains.size(), 1u);
  const Chain& c = ball.chains.front();
  EXPECT_TRUE(c.closed);
  EXPECT_NEAR(chain_length(c), 2.f * std::numbers::pi_v<float> * ball.radius_px, 1.5f);
  // Starts at the top, runs clockwise on screen: to the right first, turning right.
  EXPECT_NEAR(c.points.front().p.y, kCentre.y - ball.radius_px, 0.5f);
  EXPECT_GT(c.points[1].p.x, c.points[0].p.x);
  for (const ChainPoint& q : c.points) EXPECT_NEAR(q.curvature, 1.f / ball.radius_px, 0.2f / ball.radius_px);
}

TEST(HiddenLines, ChainsAreClippedToTheImage) {
  const Point3 eye(0.f, 0.f, 10.f);
  SceneDesc d = scene_from(eye, {.silhouette = false, .object = false, .crease = true});
  // A bar far wider than the view, behind a quad wider still: its front edges run
  // hidden from one side of the image to the other; its ends lie far outside it.
  add(d, "bar", BoxDesc{Point3(-100.f, -0.5f, -0.5f), Point3(100.f, 0.5f, 0.5f)});
  add(d, "wall", QuadDesc{Point3(-300.f, -2.f, 3.f), Vec3(600.f, 0.f, 0.f), Vec3(0.f, 4.f, 0.f)});
  const auto scene = compiled(d);
  ASSERT_TRUE(scene);
  const std::vector<Chain> chains = hidden_chains(*scene);
  ASSERT_FALSE(chains.empty());
  int across = 0;
  for (const Chain& c : chains) {
    for (const ChainPoint& q : c.points) {
      EXPECT_GE(q.p.x, 0.f);
      EXPECT_LE(q.p.x, float(kWidth));
      EXPECT_GE(q.p.y, 0.f);
      EXPECT_LE(q.p.y, float(kHeight));
    }
    across += c.points.front().p.x == 0.f && c.points.back().p.x == float(kWidth);
  }
  EXPECT_EQ(across, 2) << "the bar's top and bottom front edges, each one chain";
}

TEST(HiddenLines, AnObjectWithoutLinesStillHidesOthers) {
  SceneDesc d = scene_from(kEye, {.silhouette = true, .object = false, .crease = false});
  add(d, "box", BoxDesc{kBoxLo, kBoxHi});
  const QuadDesc quad = occluder_facing(kEye, 0.3f, 5.f);
  add(d, "quad", quad);
  d.objects[1].lines.exclude = true;
  const auto scene = compiled(d);
  ASSERT_TRUE(scene);
  EXPECT_EQ(hidden_chains(*scene).size(), 2u);
  d.objects[0].lines.exclude = true;
  const auto excluded = compiled(d);
  ASSERT_TRUE(excluded);
  EXPECT_TRUE(hidden_chains(*excluded).empty());
}

TEST(HiddenLines, PaintNeitherDrawsNorHidesLines) {
  SceneDesc d = scene_from(kEye, {.silhouette = true, .object = false, .crease = true});
  add(d, "box", BoxDesc{kBoxLo, kBoxHi});
  const auto bare = compiled(d);
  ASSERT_TRUE(bare);
  StrokeEmitterDesc strokes;
  strokes.name = "paint";
  strokes.object = "box";
  strokes.count = 300;
  strokes.width_min = 0.1f, strokes.width_max = 0.2f;
  strokes.length_min = 0.3f, strokes.length_max = 0.5f;
  d.strokes.push_back(strokes);
  const auto painted = compiled(d);
  ASSERT_TRUE(painted);
  ASSERT_GT(painted->world->objects.size(), bare->world->objects.size());
  const std::vector<Chain> a = hidden_chains(*bare), b = hidden_chains(*painted);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(b[i].covers, a[i].covers);
    EXPECT_EQ(b[i].points.size(), a[i].points.size());
  }
}

TEST(HiddenLines, NothingHiddenGivesNoChains) {
  SceneDesc d = scene_from(kEye, {.silhouette = true, .object = false, .crease = false});
  add(d, "box", BoxDesc{kBoxLo, kBoxHi});
  add(d, "ball", SphereDesc{Point3(3.f, 0.f, 0.f), 1.f});
  add(d, "quad", QuadDesc{Point3(-2.f, -1.f, -2.f), Vec3(4.f, 0.f, 0.f), Vec3(0.f, 0.f, 4.f)});
  const auto scene = compiled(d);
  ASSERT_TRUE(scene);
  EXPECT_TRUE(hidden_chains(*scene).empty());
  // No line types asked for, none found, whatever is hidden.
  SceneDesc off = scene_from(kEye, {.silhouette = false, .object = false, .crease = false});
  add(off, "box", BoxDesc{kBoxLo, kBoxHi});
  add(off, "quad", occluder_facing(kEye, 0.3f, 5.f));
  const auto none = compiled(off);
  ASSERT_TRUE(none);
  EXPECT_TRUE(hidden_chains(*none).empty());
}

TEST(HiddenLines, TheSameSceneGivesTheSameChains) {
  SceneLoadResult loaded = load_scene(std::filesystem::path(INKRAY_SOURCE_DIR) / "scenes/cad_creases.json");
  ASSERT_TRUE(loaded.scene);
  SceneDesc d = *loaded.scene;
  d.render.width = 480;
  d.render.height = 270;
  const auto scene = compiled(d);
  ASSERT_TRUE(scene);
  const std::vector<Chain> a = hidden_chains(*scene), b = hidden_chains(*scene);
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].type, b[i].type);
    EXPECT_EQ(a[i].object, b[i].object);
    EXPECT_EQ(a[i].covers, b[i].covers);
    EXPECT_EQ(a[i].closed, b[i].closed);
    ASSERT_EQ(a[i].points.size(), b[i].points.size());
    for (size_t k = 0; k < a[i].points.size(); ++k) {
      EXPECT_EQ(a[i].points[k].p, b[i].points[k].p);
      EXPECT_EQ(a[i].points[k].depth, b[i].points[k].depth);
    }
    for (const ChainPoint& q : a[i].points) {
      EXPECT_GE(q.p.x, 0.f);
      EXPECT_GE(q.p.y, 0.f);
      EXPECT_LE(q.p.x, 480.f);
      EXPECT_LE(q.p.y, 270.f);
    }
  }
  // In LineType order.
  for (size_t i = 1; i < a.size(); ++i) EXPECT_LE(int(a[i - 1].type), int(a[i].type));
}

TEST(HiddenLines, ACancelledRequestGivesNothing) {
  SceneDesc d = scene_from(kEye, {.silhouette = true, .object = false, .crease = true});
  add(d, "box", BoxDesc{kBoxLo, kBoxHi});
  const auto scene = compiled(d);
  ASSERT_TRUE(scene);
  const std::atomic<bool> stop{true};
  EXPECT_TRUE(hidden_chains(*scene, Cancel(&stop)).empty());
}

}  // namespace
}  // namespace inkray
