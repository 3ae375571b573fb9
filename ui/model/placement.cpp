#include "ui/model/placement.h"

#include "core/compiler/compile_objects.h"
#include "ui/model/scene_edits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace inkray {
namespace {

// How far a sphere at `center` stays clear of the object (negative: it overlaps). Spheres
// are measured as spheres, since their box would wall off the space around them; other
// shapes by their world box.
float clearance(const ObjectDesc& o, const Point3& center, float radius) {
  if (const auto* sphere = std::get_if<SphereDesc>(&o.shape)) {
    const Transform t = transform_from_desc(o.transform);
    const float scale = max_component(glm::abs(o.transform.scale));
    return glm::length(center - t.point(sphere->center)) - sphere->radius * scale - radius;
  }
  Point3 lo, hi;
  object_box(o, &lo, &hi);
  return glm::length(glm::max(glm::max(lo - center, center - hi), Vec3(0.f))) - radius;
}

float clearance(const SceneDesc& scene, const Point3& center, float radius) {
  float clear = std::numeric_limits<float>::infinity();
  for (const ObjectDesc& o : scene.objects) clear = std::min(clear, clearance(o, center, radius));
  return clear;
}

}  // namespace

float visible_height(const CameraDesc& camera, float distance) {
  return 2.f * distance * std::tan(glm::radians(std::clamp(camera.vfov, 0.01f, 179.f)) * 0.5f);
}

Placement place_in_view(const SceneDesc& scene, float fraction) {
  const CameraDesc& c = scene.camera;
  Vec3 forward = c.look_at - c.look_from;
  const float distance = std::max(glm::length(forward), 1e-3f);
  forward /= distance;
  Vec3 right = glm::cross(forward, glm::length(c.up) > 0.f ? glm::normalize(c.up) : Vec3(0.f, 1.f, 0.f));
  right = glm::length(right) > 1e-6f ? glm::normalize(right) : Vec3(1.f, 0.f, 0.f);
  const Vec3 up = glm::cross(right, forward);

  const float height = visible_height(c, distance);
  const float aspect = float(std::max(scene.render.width, 1)) / float(std::max(scene.render.height, 1));
  Placement placement{c.look_at, std::max(fraction * height, 1e-4f)};
  const float radius = 0.5f * placement.size;
  // Spots a radius and a bit apart, nearest the target first, each wholly in view.
  const float step = 0.6f * placement.size;
  const int reach_x = int((0.5f * height * aspect - radius) / step);
  const int reach_y = int((0.5f * height - radius) / step);
  std::vector<std::pair<int, int>> spots;
  for (int j = -reach_y; j <= reach_y; ++j)
    for (int i = -reach_x; i <= reach_x; ++i) spots.emplace_back(i, j);
  // Ties prefer above to below (the ground is usually below) and right to left.
  std::stable_sort(spots.begin(), spots.end(), [](const auto& a, const auto& b) {
    const int da = a.first * a.first + a.second * a.second, db = b.first * b.first + b.second * b.second;
    if (da != db) return da < db;
    return a.second != b.second ? a.second > b.second : a.first > b.first;
  });
  // The first spot with a gap around it; in a crowded view the one that overlaps least.
  const float gap = 0.1f * radius;
  float best = -std::numeric_limits<float>::infinity();
  Point3 best_center = placement.center;
  for (const auto& [i, j] : spots) {
    const Point3 center = placement.center + right * (float(i) * step) + up * (float(j) * step);
    const float clear = clearance(scene, center, radius);
    if (clear >= gap) {
      placement.center = center;
      return placement;
    }
    if (clear > best) best = clear, best_center = center;
  }
  placement.center = best_center;
  return placement;
}

TransformDesc fit_bounds(const Point3& lo, const Point3& hi, const Placement& placement) {
  TransformDesc t;
  const float extent = max_component(hi - lo);
  const float s = extent > 0.f && std::isfinite(extent) ? placement.size / extent : 1.f;
  t.scale = Vec3(s);
  t.translate = placement.center - s * 0.5f * (lo + hi);
  return t;
}

}  // namespace inkray
