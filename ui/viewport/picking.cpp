#include "ui/viewport/picking.h"

#include <limits>

namespace inkray {

PickResult pick(const RenderScene& scene, const Camera& camera, Vec2 image_pos) {
  PickResult result;
  // The lens centre: the ray a pinhole would see, whatever the aperture.
  const Ray ray = camera.generate_ray(image_pos, Vec2(0.5f));
  Hit hit;
  if (!scene.world->geometry.intersect(ray, std::numeric_limits<float>::infinity(), &hit)) return result;
  if (hit.geometry >= scene.world->objects.size()) return result;
  result.object = int(scene.world->objects[hit.geometry].source);
  result.point = ray.o + ray.d * hit.t;
  result.depth = glm::dot(result.point - camera.origin(), camera.forward());
  return result;
}

}  // namespace inkray
