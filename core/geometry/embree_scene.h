// The traceable geometry of a compiled scene: triangle meshes, alpha-tested
// meshes (painterly strokes) and analytic spheres, each in a BVH of its own,
// placed by instances in one top-level BVH.
#pragma once

#include "core/geometry/alpha_mask.h"
#include "core/geometry/ray.h"
#include "core/geometry/sphere.h"
#include "core/geometry/triangle_mesh.h"

#include <memory>
#include <variant>
#include <vector>

struct RTCSceneTy;

namespace inkray {

struct Hit {
  float t = 0.f;
  uint32_t geometry = 0;  // index of the shape, in the order shapes were added (= object index)
  uint32_t prim = 0;
  Vec2 barycentric{0.f};
};

using Shape = std::variant<TriangleMesh, Sphere>;

// One shape in its own Embree scene (a bottom-level BVH), in the space it was
// built in. Immutable once made: compiled scenes share it, each placing it with
// an instance, so moving an object rebuilds none of it (docs/architecture.md,
// "Geometry: one BVH per shape").
class ShapeBvh {
 public:
  // An alpha-tested mesh: a hit counts with probability mask->coverage(uv),
  // decided by a hash of the ray and the triangle, so coverage anti-aliases over
  // samples and shadow rays see partial coverage. Ordinary shapes pay nothing.
  explicit ShapeBvh(std::shared_ptr<const Shape> shape, std::shared_ptr<const AlphaMask> mask = nullptr);
  ~ShapeBvh();
  ShapeBvh(const ShapeBvh&) = delete;
  ShapeBvh& operator=(const ShapeBvh&) = delete;

  const Shape& shape() const { return *shape_; }
  const std::shared_ptr<const Shape>& shared_shape() const { return shape_; }
  const AlphaMask* mask() const { return mask_.get(); }
  RTCSceneTy* embree_scene() const { return scene_; }

 private:
  std::shared_ptr<const Shape> shape_;
  std::shared_ptr<const AlphaMask> mask_;
  RTCSceneTy* scene_ = nullptr;
};

// The traceable geometry of a compiled scene: a top-level Embree scene of
// instances, one per shape, each placing a ShapeBvh. Immutable after commit();
// intersect() and occluded() are safe to call from any number of threads.
// Copies share the committed scene (a compiled scene whose materials changed
// keeps its geometry), so copy only after commit().
class EmbreeScene {
 public:
  EmbreeScene();

  // A shape already in world space, in a BVH of its own placed where it is.
  // Returns the shape's index; shapes must not be added after commit().
  uint32_t add(Shape shape);
  uint32_t add(TriangleMesh mesh, std::shared_ptr<const AlphaMask> mask);
  // A shared bottom level placed by `to_world`. `world` is the same shape in world
  // space, which hits, lights and strokes read: for a mesh, its vertices transformed
  // by to_world (the barycentrics of a hit are the same in both); the BVH's own
  // shape when to_world is the identity.
  uint32_t add(std::shared_ptr<const ShapeBvh> bvh, const Transform& to_world, std::shared_ptr<const Shape> world);
  void commit();
  // Whether `other` places the same BVHs, by the same transforms, with the same
  // world shapes: then its committed top level can stand for this one.
  bool same_instances(const EmbreeScene& other) const;

  bool intersect(const Ray& ray, float t_max, Hit* hit) const;
  bool occluded(const Ray& ray, float t_max) const;
  SurfaceInteraction interaction(const Ray& ray, const Hit& hit) const;

  const Shape& shape(uint32_t index) const { return *impl_->instances[index].world; }
  size_t shape_count() const { return impl_->instances.size(); }
  // The shape's alpha mask, or null for an opaque shape.
  const AlphaMask* alpha_mask(uint32_t index) const { return impl_->instances[index].bvh->mask(); }
  // Bounds of everything, for directional and environment lights.
  void bounds(Point3* lo, Point3* hi) const;

 private:
  struct Instance {
    std::shared_ptr<const ShapeBvh> bvh;
    Transform to_world;
    std::shared_ptr<const Shape> world;
  };
  struct Impl {
    std::vector<Instance> instances;
    RTCSceneTy* scene = nullptr;
    bool committed = false;
    ~Impl();
  };
  std::shared_ptr<Impl> impl_;
};

}  // namespace inkray
