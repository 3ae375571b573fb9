// The traceable geometry of a compiled scene: triangle meshes, alpha-tested
// meshes (painterly strokes) and analytic spheres, each in a BVH of its own,
// placed by instances in one top-level BVH.
#pragma once

#include "core/geometry/alpha_mask.h"
#include "core/geometry/ray.h"
#include "core/geometry/sphere.h"
#include "core/geometry/triangle_mesh.h"

#include <array>
#include <memory>
#include <variant>
#include <vector>

struct RTCSceneTy;
struct RTCGeometryTy;

namespace inkray {

struct Hit {
  float t = 0.f;
  uint32_t geometry = 0;  // index of the shape, in the order shapes were added (= object index)
  uint32_t prim = 0;
  Vec2 barycentric{0.f};
};

using Shape = std::variant<TriangleMesh, Sphere>;

// Colours that stand for a mesh's own vertex colours, one per group of triangles (a
// painterly stroke): a repaint of 100,000 strokes makes 100,000 colours, not a copy of
// their mesh (docs/architecture.md, "Edits of large documents"). A hit weighs its
// group's colour as it weighs the three vertex colours it stands for, so a mesh
// whose vertices carry these colours shades the same, bit for bit.
struct MeshPaint {
  std::shared_ptr<const std::vector<uint32_t>> group_of_triangle;
  std::vector<Color> colors;  // by group
};

// What a closest-hit ray gathers: what the camera sees, directly or through
// mirrors and glass (every shape), or light after a diffuse or glossy bounce
// (paint hidden from it is skipped: the surface under it stands in).
enum class RayKind { camera, indirect };

// One shape in its own Embree scene (a bottom-level BVH), in the space it was
// built in. Immutable once made: compiled scenes share it, each placing it with
// an instance, so moving an object rebuilds none of it (docs/architecture.md,
// "Geometry: one BVH per shape").
class ShapeBvh {
 public:
  // An alpha-tested mesh: a hit counts with probability mask->coverage(uv)
  // (or its per-triangle AlphaTriangle's), decided by a hash of the ray and the
  // triangle, so coverage anti-aliases over samples and shadow rays see partial
  // coverage; shadow rays skip paint (AlphaMask::paint). Ordinary shapes pay
  // nothing. The texture read is the instance's brush where it brings one
  // (EmbreeScene::add), so meshes under different brushes share one BVH.
  explicit ShapeBvh(std::shared_ptr<const Shape> shape, std::shared_ptr<const AlphaMask> mask = nullptr);
  ~ShapeBvh();
  ShapeBvh(const ShapeBvh&) = delete;
  ShapeBvh& operator=(const ShapeBvh&) = delete;

  const Shape& shape() const { return *shape_; }
  const std::shared_ptr<const Shape>& shared_shape() const { return shape_; }
  const AlphaMask* mask() const { return mask_.get(); }
  RTCSceneTy* embree_scene() const { return scene_; }
  // What Embree allocated for this BVH while building it (its memory monitor;
  // approximate when other BVHs are built at the same time).
  size_t bvh_bytes() const { return bvh_bytes_ + quad_indices_.capacity() * sizeof(uint32_t); }
  // Whether Embree holds the mesh as quads (AlphaMask::quads): its hits then
  // name a quad, which EmbreeScene turns back into a triangle of the mesh.
  bool traced_as_quads() const { return !quad_indices_.empty(); }

 private:
  std::shared_ptr<const Shape> shape_;
  std::shared_ptr<const AlphaMask> mask_;
  std::vector<uint32_t> quad_indices_;
  RTCSceneTy* scene_ = nullptr;
  size_t bvh_bytes_ = 0;
};

// Bytes Embree holds now, over every BVH of the process (its memory monitor).
size_t embree_memory_bytes();

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
  // `indirect` false hides paint (AlphaMask::paint) from RayKind::indirect rays;
  // other shapes are seen by every ray.
  // `paint`, for a mesh, stands for its vertex colours in what hits read; `brush`, for
  // an alpha-tested one, for its mask's texture in the alpha test.
  uint32_t add(std::shared_ptr<const ShapeBvh> bvh, const Transform& to_world,
               std::shared_ptr<const Shape> world, bool indirect = true,
               std::shared_ptr<const MeshPaint> paint = nullptr,
               std::shared_ptr<const AlphaTexture> brush = nullptr);
  // A shared bottom level that moves while the shutter is open (docs/architecture.md,
  // "Motion blur"): placed by `open` at time 0 and by `close` at time 1, an Embree
  // instance of two time steps in between (scale and shear and the translation
  // interpolated linearly, the rotation by slerp, so a turning object keeps its size).
  // A hit is computed from `local`, the shape in the BVH's own space (the BVH's shape,
  // or the same mesh with other vertex colours), placed where the instance stands at
  // the ray's time; `world`, the shape at the frame, is what lights, strokes and
  // shape() read.
  uint32_t add_moving(std::shared_ptr<const ShapeBvh> bvh, const Transform& open, const Transform& close,
                      std::shared_ptr<const Shape> local, std::shared_ptr<const Shape> world,
                      bool indirect = true, std::shared_ptr<const MeshPaint> paint = nullptr,
                      std::shared_ptr<const AlphaTexture> brush = nullptr);
  // An uncommitted scene placing what the committed `other` places, for an edit that
  // moves a few of its shapes (replace) before commit(&other).
  static EmbreeScene with_instances_of(const EmbreeScene& other);
  // Places shape `index` (added, not moving) anew; before commit().
  void replace(uint32_t index, std::shared_ptr<const ShapeBvh> bvh, const Transform& to_world,
               std::shared_ptr<const Shape> world);
  // Builds the top level. With `previous` (a committed scene, say the last compile's),
  // an instance that places the same BVH by the same transform as previous's instance of
  // the same index takes previous's Embree instance (Embree attaches a geometry to any
  // number of scenes): moving one object of thousands makes one new instance, and a new
  // brush none (the alpha test finds each instance's brush through the query). The
  // shapes placed anew are traced from a small second top level, and previous's main
  // one is shared while the same few keep moving (docs/architecture.md, "Edits of
  // large documents"): a drag rebuilds a top level of one instance, not of thousands.
  void commit(const EmbreeScene* previous = nullptr);
  // How many shapes the second top level holds at the most; a commit that would
  // put more there builds one top level of everything.
  static constexpr size_t kMostLiveShapes = 64;
  // The shapes traced from the second top level (sorted; empty for most scenes).
  const std::vector<uint32_t>& live_shapes() const { return impl_->live; }
  // Whether this scene's main top level is `other`'s, shared rather than built again.
  bool shares_top_level(const EmbreeScene& other) const { return impl_->scene == other.impl_->scene; }
  // Whether `other` places the same BVHs, by the same transforms, with the same
  // world shapes: then its committed top level can stand for this one.
  bool same_instances(const EmbreeScene& other) const;

  // The closest hit; where it is on paint, the paint painted last there.
  bool intersect(const Ray& ray, float t_max, Hit* hit, RayKind kind = RayKind::camera) const;
  // The closest hit on what casts shadows, paint left out (it lies on a surface, which
  // hides what it hides): what stands between the camera and a hidden line.
  bool intersect_solid(const Ray& ray, float t_max, Hit* hit) const;
  bool occluded(const Ray& ray, float t_max) const;
  SurfaceInteraction interaction(const Ray& ray, const Hit& hit) const;

  const Shape& shape(uint32_t index) const { return *impl_->instances[index].world; }
  size_t shape_count() const { return impl_->instances.size(); }
  // The shape's alpha mask (its BVH's), or null for an opaque shape; and the texture its
  // alpha test reads: the instance's brush, or that mask's own.
  const AlphaMask* alpha_mask(uint32_t index) const { return impl_->instances[index].bvh->mask(); }
  const AlphaTexture* alpha_texture(uint32_t index) const {
    const Instance& instance = impl_->instances[index];
    return instance.brush ? instance.brush.get() : instance.bvh->mask();
  }
  const ShapeBvh& bvh(uint32_t index) const { return *impl_->instances[index].bvh; }
  // Whether the shape moves while the shutter is open (add_moving), and whether any does.
  bool moving(uint32_t index) const { return impl_->instances[index].moving; }
  bool any_moving() const { return impl_->any_moving; }
  // Where the shape's BVH is placed at shutter instant `time` in [0, 1]: for a moving
  // shape Embree's own interpolation (the one rays are traced through); after commit().
  Transform placement(uint32_t index, float time) const;
  // Bounds of everything (over the whole shutter), for directional and environment lights.
  void bounds(Point3* lo, Point3* hi) const;

 private:
  struct Instance {
    std::shared_ptr<const ShapeBvh> bvh;
    Transform to_world;  // at the shutter's opening when it moves
    std::shared_ptr<const Shape> world;
    bool indirect = true;  // RayKind::indirect rays see it
    // Moving (add_moving): placed by to_close at the shutter's closing; hits read `local`.
    bool moving = false;
    Transform to_close{};
    std::shared_ptr<const Shape> local{};
    std::shared_ptr<const MeshPaint> paint{};     // stands for the mesh's vertex colours
    std::shared_ptr<const AlphaTexture> brush{};  // stands for its mask's texture
  };
  struct Impl {
    std::vector<Instance> instances;
    // The Embree instances of each moving shape, one per piece of the shutter it is
    // traced over (none for the others), kept to ask where it stands at a time.
    struct MotionGeometry {
      float start = 0.f, end = 1.f;
      RTCGeometryTy* geom = nullptr;
    };
    std::vector<std::vector<MotionGeometry>> motion;
    // The Embree instance of each shape that does not move (null for moving and
    // unplaceable ones), held so a later top level can attach it too.
    std::vector<RTCGeometryTy*> still;
    // The instance each further piece belongs to: Embree ids from instances.size() on.
    std::vector<uint32_t> piece_owner;
    // What each instance's alpha test reads (alpha_texture; null for opaque shapes), by
    // instance index: queries carry it to the filter, which knows only the instance id.
    std::vector<const AlphaTexture*> alpha_textures;
    bool any_moving = false;
    // Paint seen by camera rays, and by indirect rays, in instance order, when
    // every paint instance is placed by the identity (strokes are built in world
    // space): the paint-order query then asks their BVHs directly.
    std::vector<uint32_t> camera_paint, indirect_paint;
    bool direct_paint = false;
    float camera_layer = 0.f;                                // the thickest layer of camera paint
    std::vector<std::array<Point3, 2>> camera_paint_bounds;  // world bounds of each, grown by its layer
    RTCSceneTy* scene = nullptr;
    // The shapes recent edits placed anew, out of `scene` and in a top level of their
    // own (null when there are none), so `scene` can be the previous commit's.
    std::vector<uint32_t> live;
    RTCSceneTy* live_scene = nullptr;
    bool committed = false;
    ~Impl();
  };
  // Replaces a hit on paint by the last-painted paint the ray passes through
  // there (AlphaMask::paint).
  // `layer_thickness`: the hit paint's, in world units; `ng` its normal in world space.
  void resolve_paint(const Ray& ray, float layer_thickness, const Vec3& ng, RayKind kind, Hit* hit) const;
  // The hit on a moving shape, where it stands at the ray's time; *layer_scale is
  // how much its placement then stretches a paint layer.
  SurfaceInteraction moving_interaction(const Ray& ray, const Hit& hit, float* layer_scale) const;
  // A camera ray's hit on a surface: the last-painted camera paint on it, if
  // any, replaces it.
  void paint_on_surface(const Ray& ray, const Vec3& ng, Hit* hit) const;
  // Which shapes commit(previous) traces from the second top level, and whether
  // previous's main top level then serves as this one's.
  struct TopLevels {
    std::vector<uint32_t> live;
    bool share_main = false;
  };
  TopLevels split_top_levels(const EmbreeScene* previous) const;

  std::shared_ptr<Impl> impl_;
};

}  // namespace inkray
