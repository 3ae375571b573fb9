// The traceable geometry of a compiled scene: triangle meshes, alpha-tested
// meshes (painterly strokes) and analytic spheres in one Embree BVH. Immutable
// after commit(); intersect() and occluded() are safe to call from any number
// of threads.
#pragma once

#include "core/geometry/alpha_mask.h"
#include "core/geometry/ray.h"
#include "core/geometry/sphere.h"
#include "core/geometry/triangle_mesh.h"

#include <memory>
#include <variant>
#include <vector>

namespace inkray {

struct Hit {
  float t = 0.f;
  uint32_t geometry = 0;  // index of the shape, in the order shapes were added (= object index)
  uint32_t prim = 0;
  Vec2 barycentric{0.f};
};

using Shape = std::variant<TriangleMesh, Sphere>;

class EmbreeScene {
 public:
  EmbreeScene();
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Returns the shape's index; shapes must not be added after commit().
  uint32_t add(Shape shape);
  // An alpha-tested mesh: a hit counts with probability mask->coverage(uv), decided
  // by a hash of the ray and the triangle, so coverage anti-aliases over samples
  // and shadow rays see partial coverage. Ordinary shapes pay nothing for it.
  uint32_t add(TriangleMesh mesh, std::shared_ptr<const AlphaMask> mask);
  void commit();

  bool intersect(const Ray& ray, float t_max, Hit* hit) const;
  bool occluded(const Ray& ray, float t_max) const;
  SurfaceInteraction interaction(const Ray& ray, const Hit& hit) const;

  const Shape& shape(uint32_t index) const { return shapes_[index]; }
  size_t shape_count() const { return shapes_.size(); }
  // The shape's alpha mask, or null for an opaque shape.
  const AlphaMask* alpha_mask(uint32_t index) const { return masks_[index].get(); }
  // Bounds of everything, for directional and environment lights.
  void bounds(Point3* lo, Point3* hi) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  // Embree shares the meshes' buffers and the spheres' addresses: geometries
  // are created in commit(), after which shapes_ never reallocates.
  std::vector<Shape> shapes_;
  std::vector<std::shared_ptr<const AlphaMask>> masks_;  // one per shape, null when opaque
};

}  // namespace inkray
