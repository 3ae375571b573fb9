#include "core/geometry/embree_scene.h"

#include "core/geometry/embree_device.h"
#include "core/geometry/instance_placement.h"
#include "core/math/float_error.h"
#include "core/math/hash.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <stdexcept>

namespace inkray {
namespace {

void sphere_bounds(const RTCBoundsFunctionArguments* args) {
  const auto* sphere = static_cast<const Sphere*>(args->geometryUserPtr);
  Point3 lo, hi;
  sphere->bounds(&lo, &hi);
  *args->bounds_o = {lo.x, lo.y, lo.z, 0.f, hi.x, hi.y, hi.z, 0.f};
}

// We only call the single-ray API, so callbacks see N == 1.
void sphere_intersect(const RTCIntersectFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const auto* sphere = static_cast<const Sphere*>(args->geometryUserPtr);
  auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
  const Ray ray{{rh->ray.org_x, rh->ray.org_y, rh->ray.org_z}, {rh->ray.dir_x, rh->ray.dir_y, rh->ray.dir_z}};
  const auto t = sphere->intersect(ray, rh->ray.tnear, rh->ray.tfar);
  if (!t) return;
  rh->ray.tfar = *t;
  rh->hit.u = rh->hit.v = 0.f;
  rh->hit.Ng_x = rh->hit.Ng_y = rh->hit.Ng_z = 0.f;
  rh->hit.geomID = args->geomID;
  rh->hit.primID = args->primID;
  rh->hit.instID[0] = args->context->instID[0];
}

void sphere_occluded(const RTCOccludedFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const auto* sphere = static_cast<const Sphere*>(args->geometryUserPtr);
  auto* r = reinterpret_cast<RTCRay*>(args->ray);
  const Ray ray{{r->org_x, r->org_y, r->org_z}, {r->dir_x, r->dir_y, r->dir_z}};
  if (sphere->intersect(ray, r->tnear, r->tfar)) r->tfar = -kInfinity;
}

// Whether a candidate hit on an alpha-tested mesh counts, the mesh's mask read in
// `texture` (its instance's brush). The uniform number comes from a hash of the ray's
// bits and the triangle: the same ray always decides the same way (Embree may report a
// triangle twice under spatial splits), while the many rays of a pixel sample the coverage.
bool alpha_accepts(const TriangleMesh& mesh, const AlphaMask& mask, const AlphaTexture& texture,
                   const RTCFilterFunctionNArguments* args, uint32_t prim, float b1, float b2) {
  RTCRayN* ray = args->ray;
  RTCHitN* hit = args->hit;
  const unsigned n = args->N;
  const Vec3 d(RTCRayN_dir_x(ray, n, 0), RTCRayN_dir_y(ray, n, 0), RTCRayN_dir_z(ray, n, 0));
  if (mask.layer_thickness > 0.f) {
    // A ray leaving the surface the layer lies on (or the layer itself) starts
    // within the layer's thickness of the triangle's plane: it passes through.
    // Compared squared: most hits of a paint layer end here, before any lookup.
    const Vec3 ng(RTCHitN_Ng_x(hit, n, 0), RTCHitN_Ng_y(hit, n, 0), RTCHitN_Ng_z(hit, n, 0));
    const float height = RTCRayN_tfar(ray, n, 0) * glm::dot(d, ng);
    if (height * height < mask.layer_thickness * mask.layer_thickness * glm::dot(ng, ng)) return false;
  }
  float alpha = 0.f;
  if (!mask.triangles.empty()) {
    alpha = texture.coverage_of(mask.triangles[prim], b1, b2);
  } else {
    const uint32_t* idx = &mesh.indices[3 * size_t(prim)];
    const Vec2 uv = (1.f - b1 - b2) * mesh.uvs[idx[0]] + b1 * mesh.uvs[idx[1]] + b2 * mesh.uvs[idx[2]];
    alpha = texture.coverage_in(int(mask.variant_of(prim, texture.variants)), uv);
  }
  if (alpha >= 1.f) return true;
  if (alpha <= 0.f) return false;
  // The ray's bits folded by odd multipliers, then one full mix: rays of a
  // pixel differ in a few low bits of their direction, which this spreads.
  const uint32_t bits = std::bit_cast<uint32_t>(RTCRayN_org_x(ray, n, 0)) * 0x9e3779b1u ^
                        std::bit_cast<uint32_t>(RTCRayN_org_y(ray, n, 0)) * 0x85ebca77u ^
                        std::bit_cast<uint32_t>(RTCRayN_org_z(ray, n, 0)) * 0xc2b2ae3du ^
                        std::bit_cast<uint32_t>(d.x) * 0x27d4eb2fu ^
                        std::bit_cast<uint32_t>(d.y) * 0x165667b1u ^
                        std::bit_cast<uint32_t>(d.z) * 0xd3a2646du ^ prim * 0xfd7046c5u;
  return u32_to_unit_float(hash_u32(bits ^ (bits >> 15))) < alpha;
}

// The last-painted paint hit found so far by a query resolving paint order.
struct PaintHit {
  uint32_t instance = 0, prim = 0;
  float t = 0.f, u = 0.f, v = 0.f;
  bool found = true;  // false: no paint yet, any accepted paint is better
};

// Every query's context: Embree's, what each instance's alpha test reads, and for a
// query resolving paint order the best paint hit so far (null otherwise).
struct QueryContext {
  RTCIntersectContext rtc;
  PaintHit* paint = nullptr;
  // The instance whose BVH a paint-order query asks directly (Embree names no
  // instance then), or kNoInstance when it asks the top level.
  uint32_t instance = kNoInstance;
  static constexpr uint32_t kNoInstance = ~0u;
  // Embree's instance id to the instance's index: an instance traced in pieces
  // (motion_pieces) has ids from `first_piece` on for its further pieces.
  const uint32_t* piece_owner = nullptr;
  uint32_t first_piece = kNoInstance;
  // By instance index (EmbreeScene::alpha_texture).
  const AlphaTexture* const* alpha_textures = nullptr;

  QueryContext(const std::vector<uint32_t>& owners, const std::vector<const AlphaTexture*>& textures)
      : piece_owner(owners.data()), first_piece(uint32_t(textures.size())), alpha_textures(textures.data()) {}
  uint32_t instance_of(uint32_t id) const { return id < first_piece ? id : piece_owner[id - first_piece]; }
  // The instance whose BVH a filter is called from: the one asked directly, or the one
  // Embree is inside.
  uint32_t filtered_instance(const RTCIntersectContext* rtc_context) const {
    return instance != kNoInstance ? instance : instance_of(rtc_context->instID[0]);
  }
};

// The closest hit over the main top level and, when some shapes were placed anew
// since it was built, the second one (EmbreeScene::commit): the second sees the ray
// shortened to the first's hit, so it reports only a nearer one.
template <class Impl>
void intersect_top_levels(const Impl& impl, QueryContext& context, RTCRayHit& rh) {
  rtcIntersect1(impl.scene, &context.rtc, &rh);
  if (impl.live_scene) rtcIntersect1(impl.live_scene, &context.rtc, &rh);
}

// The triangle and its barycentrics at (u, v) of quad q (AlphaMask::quads):
// Embree splits the quad (v0, v1, v2, v3) into (v0, v1, v3) and (v2, v3, v1)
// and reports the second's hits as (1 - u', 1 - v').
void quad_to_triangle(uint32_t q, float u, float v, uint32_t* prim, float* b1, float* b2) {
  if (u + v <= 1.f) {
    *prim = 2 * q;
    *b1 = u;
    *b2 = v;
  } else {  // (b, b1, a1) = (v1, v2, v3): weights 1 - v, u + v - 1, 1 - u
    *prim = 2 * q + 1;
    *b1 = u + v - 1.f;
    *b2 = 1.f - u;
  }
}

// We only call the single-ray API, so filters see N == 1. The user data is the
// ShapeBvh, whose shape is the mesh (in the space the filter's ray is in); the
// texture comes from the query, by the instance (Embree's instance id, which every
// query through a top level has, or the instance a direct query names).
void alpha_filter(const RTCFilterFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const auto* bvh = static_cast<const ShapeBvh*>(args->geometryUserPtr);
  uint32_t prim = RTCHitN_primID(args->hit, args->N, 0);
  float b1 = RTCHitN_u(args->hit, args->N, 0), b2 = RTCHitN_v(args->hit, args->N, 0);
  if (bvh->traced_as_quads()) quad_to_triangle(prim, b1, b2, &prim, &b1, &b2);
  const TriangleMesh& mesh = std::get<TriangleMesh>(bvh->shape());
  const auto* query = reinterpret_cast<const QueryContext*>(args->context);
  const uint32_t instance = query->filtered_instance(args->context);
  const AlphaTexture& texture = *query->alpha_textures[instance];
  if (PaintHit* paint = query->paint) {
    // Resolving paint order: only paint painted after the best so far matters,
    // and every hit is refused so the query looks on.
    args->valid[0] = 0;
    if (paint->found && (instance < paint->instance || (instance == paint->instance && prim <= paint->prim)))
      return;
    if (alpha_accepts(mesh, *bvh->mask(), texture, args, prim, b1, b2))
      *paint = {instance, prim, RTCRayN_tfar(args->ray, args->N, 0), b1, b2, true};
    return;
  }
  if (!alpha_accepts(mesh, *bvh->mask(), texture, args, prim, b1, b2)) args->valid[0] = 0;
}

// Instance masks: every shape but paint is kSolid, paint is kPaint, and also
// kPaintIndirect unless hidden from indirect rays. Shadow rays see only kSolid
// (paint casts no shadow); camera rays kSolid | kPaint, indirect rays kSolid |
// kPaintIndirect; the query resolving paint order sees the ray's paint bit only.
constexpr unsigned kSolid = 1u << 0;
constexpr unsigned kPaint = 1u << 1;
constexpr unsigned kPaintIndirect = 1u << 2;

// Bytes Embree holds on the shared device (BVHs and their build scratch), from
// its memory monitor.
std::atomic<int64_t> g_embree_bytes{0};

// Debian's Embree is built with assertions: a ray whose origin is not finite or
// lies beyond about 1.8e18 aborts the process. compile_scene keeps geometry and
// cameras far inside that; this last check (one compare per axis) turns a ray that
// got there anyway into a miss instead of a crash.
bool traceable(const Ray& ray, float t_max) {
  constexpr float kLimit = 1e18f;  // comparisons false for NaN, so NaN is refused too
  return std::fabs(ray.o.x) < kLimit && std::fabs(ray.o.y) < kLimit && std::fabs(ray.o.z) < kLimit &&
         std::isfinite(ray.d.x + ray.d.y + ray.d.z) && t_max >= 0.f;
}

RTCRay to_rtc(const Ray& ray, float t_max) {
  RTCRay r{};
  r.org_x = ray.o.x;
  r.org_y = ray.o.y;
  r.org_z = ray.o.z;
  r.dir_x = ray.d.x;
  r.dir_y = ray.d.y;
  r.dir_z = ray.d.z;
  r.tnear = 0.f;
  r.tfar = t_max;
  r.time = ray.time;  // only moving instances read it
  r.mask = 0xffffffffu;
  r.flags = 0;
  return r;
}

// The closest hit over the top levels on the instances `mask` lets through, named by
// the scene's shapes (a hit on a quad as its triangle's); *ng is the hit's geometric
// normal in its instance's space. False for a miss, or a ray Embree cannot take.
template <class Impl>
bool closest_hit(const Impl& impl, const Ray& ray, float t_max, unsigned mask, Hit* hit, Vec3* ng) {
  QueryContext context(impl.piece_owner, impl.alpha_textures);
  rtcInitIntersectContext(&context.rtc);
  if (!traceable(ray, t_max)) return false;
  RTCRayHit rh{};
  rh.ray = to_rtc(ray, t_max);
  rh.ray.mask = mask;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  intersect_top_levels(impl, context, rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit->t = rh.ray.tfar;
  hit->geometry = context.instance_of(rh.hit.instID[0]);
  hit->prim = rh.hit.primID;
  hit->barycentric = {rh.hit.u, rh.hit.v};
  if (impl.instances[hit->geometry].bvh->traced_as_quads())
    quad_to_triangle(rh.hit.primID, rh.hit.u, rh.hit.v, &hit->prim, &hit->barycentric.x, &hit->barycentric.y);
  *ng = Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
  return true;
}

// interpolate_shading of a mesh moved by `move`, as `transformed` (triangle_mesh.h)
// would move it: normals by the inverse transpose, each normalised, then interpolated.
MeshShading moved_shading(const TriangleMesh& mesh, uint32_t tri, float b1, float b2, const Normal3& ng,
                          const Transform& move) {
  MeshShading s = interpolate_shading(mesh, tri, b1, b2, ng);  // uv and colour
  s.ng = s.ns = ng;
  if (mesh.normals.empty()) return s;
  const uint32_t* idx = &mesh.indices[3 * size_t(tri)];
  const auto moved = [&](uint32_t i) { return glm::normalize(move.normal(mesh.normals[i])); };
  const Vec3 ns = (1.f - b1 - b2) * moved(idx[0]) + b1 * moved(idx[1]) + b2 * moved(idx[2]);
  const float ns_len = glm::length(ns);
  if (ns_len > 0.f) {
    s.ns = ns / ns_len;
    if (glm::dot(s.ng, s.ns) < 0.f) s.ng = -s.ng;
  }
  return s;
}

// The hit on a triangle of `mesh`, which lies in world space, or (kMoved) in the
// space of a moving instance that `move` places where it stands at the ray's time
// (the barycentrics are the same in both spaces). Two instances, so the still one
// is exactly what it was before shapes could move.
template <bool kMoved>
SurfaceInteraction triangle_interaction(const TriangleMesh& mesh, const Hit& hit, const Ray& ray,
                                        const Transform* move = nullptr) {
  const uint32_t i0 = mesh.indices[3 * hit.prim], i1 = mesh.indices[3 * hit.prim + 1],
                 i2 = mesh.indices[3 * hit.prim + 2];
  Point3 p0 = mesh.positions[i0], p1 = mesh.positions[i1], p2 = mesh.positions[i2];
  if constexpr (kMoved) p0 = move->point(p0), p1 = move->point(p1), p2 = move->point(p2);
  const float b1 = hit.barycentric.x, b2 = hit.barycentric.y, b0 = 1.f - b1 - b2;
  SurfaceInteraction si;
  si.t = hit.t;
  // Recompute p from barycentrics rather than o + t d: its error is bounded by
  // the vertices' magnitudes, not by the ray's length (pbrt-v4 6.8.5).
  si.p = b0 * p0 + b1 * p1 + b2 * p2;
  // pbrt-v4 bounds the error per axis by gamma(7) sum |b_i p_i|, relying on its
  // own intersector to reject t <= its error. Embree accepts t = 0, so a point
  // exact on an axis-aligned plane (zero error along its normal) would re-hit
  // it: use the largest axis bound on every axis.
  si.p_error =
      Vec3(gamma_bound(7) * max_component(glm::abs(b0 * p0) + glm::abs(b1 * p1) + glm::abs(b2 * p2)));
  const Vec3 n = glm::cross(p1 - p0, p2 - p0);
  const float len = glm::length(n);
  const Normal3 facet = len > 0.f ? n / len : -glm::normalize(ray.d);
  MeshShading shading;
  if constexpr (kMoved)
    shading = moved_shading(mesh, hit.prim, b1, b2, facet, *move);
  else
    shading = interpolate_shading(mesh, hit.prim, b1, b2, facet);
  si.ng = shading.ng;
  si.ns = shading.ns;
  si.uv = shading.uv;
  si.color = shading.color;
  si.prim = hit.prim;
  return si;
}

}  // namespace

size_t embree_memory_bytes() {
  return size_t(std::max<int64_t>(0, g_embree_bytes.load(std::memory_order_relaxed)));
}

RTCDevice shared_embree_device() {
  static RTCDevice device = [] {
    RTCDevice d = rtcNewDevice(nullptr);
    if (!d) throw std::runtime_error("Embree: could not create a device");
    rtcSetDeviceErrorFunction(
        d,
        [](void*, RTCError code, const char* msg) {
          std::fprintf(stderr, "Embree error %d: %s\n", int(code), msg);
        },
        nullptr);
    rtcSetDeviceMemoryMonitorFunction(
        d,
        [](void*, ssize_t bytes, bool) {
          g_embree_bytes.fetch_add(int64_t(bytes), std::memory_order_relaxed);
          return true;
        },
        nullptr);
    return d;
  }();
  return device;
}

namespace {

RTCScene new_embree_scene(RTCBuildQuality quality, RTCSceneFlags flags = RTC_SCENE_FLAG_ROBUST) {
  RTCScene scene = rtcNewScene(shared_embree_device());
  rtcSetSceneFlags(scene, flags);
  rtcSetSceneBuildQuality(scene, quality);
  return scene;
}

// Embree's instance transform: the 3x4 column-major part of the affine matrix.
std::array<float, 12> embree_transform(const Transform& t) {
  std::array<float, 12> xfm{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) xfm[size_t(3 * c + r)] = t.m[c][r];
  return xfm;
}

// A transform from Embree's 3x4 column-major form.
Transform from_embree(const std::array<float, 12>& xfm) {
  Mat4 m(1.f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) m[c][r] = xfm[size_t(3 * c + r)];
  return Transform::from_matrix(m);
}

// How much a transform stretches lengths at most (along an axis, and never less than
// 1): what a paint layer grown in its space is thick at least, after it.
float stretch(const Transform& t) {
  return std::max({glm::length(t.vector(Vec3(1.f, 0.f, 0.f))), glm::length(t.vector(Vec3(0.f, 1.f, 0.f))),
                   glm::length(t.vector(Vec3(0.f, 0.f, 1.f))), 1.f});
}

}  // namespace

namespace {

// The quads (a, b, b1, a1) of a mesh whose triangles pair up as (a, b, a1) and
// (b, b1, a1) (AlphaMask::quads); none when they do not.
std::vector<uint32_t> quads_of(const TriangleMesh& mesh) {
  const std::vector<uint32_t>& t = mesh.indices;
  if (t.size() % 6 != 0) return {};
  std::vector<uint32_t> quads(t.size() / 6 * 4);
  for (size_t q = 0; q < t.size() / 6; ++q) {
    const uint32_t* p = &t[6 * q];
    if (p[3] != p[1] || p[5] != p[2]) return {};
    quads[4 * q] = p[0];
    quads[4 * q + 1] = p[1];
    quads[4 * q + 2] = p[4];
    quads[4 * q + 3] = p[2];
  }
  return quads;
}

}  // namespace

ShapeBvh::ShapeBvh(std::shared_ptr<const Shape> shape, std::shared_ptr<const AlphaMask> mask)
    : shape_(std::move(shape)), mask_(std::move(mask)) {
  const auto* mesh = std::get_if<TriangleMesh>(shape_.get());
  if (mask_ && (!mesh || (mesh->uvs.size() < mesh->vertex_count() &&
                          mask_->triangles.size() < mesh->triangle_count())))
    throw std::invalid_argument(
        "ShapeBvh: an alpha-tested shape must be a mesh with a uv per vertex or per-triangle alpha data");
  RTCDevice device = shared_embree_device();
  // Alpha-tested layers skip the robust (watertight) traversal: a ray slipping
  // between two triangles of a stroke sees what lies under it, which an alpha
  // test does anyway, and the robust mode costs a fifth of their traversal.
  // Paint is built at medium quality: a tenth of the high quality's build time
  // (no spatial splits) for the same traversal work, measured on strokes.
  const bool paint = mask_ && mask_->paint;
  scene_ = new_embree_scene(paint ? RTC_BUILD_QUALITY_MEDIUM : RTC_BUILD_QUALITY_HIGH,
                            mask_ ? RTC_SCENE_FLAG_NONE : RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geom = nullptr;
  if (mesh && mask_ && mask_->quads) quad_indices_ = quads_of(*mesh);
  if (mesh && !quad_indices_.empty()) {
    geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_QUAD);
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh->positions.data(), 0,
                               sizeof(Point3), mesh->vertex_count());
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, quad_indices_.data(), 0,
                               4 * sizeof(uint32_t), quad_indices_.size() / 4);
  } else if (mesh) {
    geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh->positions.data(), 0,
                               sizeof(Point3), mesh->vertex_count());
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh->indices.data(), 0,
                               3 * sizeof(uint32_t), mesh->triangle_count());
  }
  if (mesh) {
    if (mask_) {
      rtcSetGeometryUserData(geom, this);
      rtcSetGeometryIntersectFilterFunction(geom, alpha_filter);
      rtcSetGeometryOccludedFilterFunction(geom, alpha_filter);
    }
  } else {
    geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, 1);
    rtcSetGeometryUserData(geom, const_cast<Sphere*>(&std::get<Sphere>(*shape_)));
    rtcSetGeometryBoundsFunction(geom, sphere_bounds, nullptr);
    rtcSetGeometryIntersectFunction(geom, sphere_intersect);
    rtcSetGeometryOccludedFunction(geom, sphere_occluded);
  }
  rtcCommitGeometry(geom);
  rtcAttachGeometryByID(scene_, geom, 0);
  rtcReleaseGeometry(geom);
  const int64_t before = g_embree_bytes.load(std::memory_order_relaxed);
  rtcCommitScene(scene_);
  bvh_bytes_ = size_t(std::max<int64_t>(0, g_embree_bytes.load(std::memory_order_relaxed) - before));
}

ShapeBvh::~ShapeBvh() { rtcReleaseScene(scene_); }

EmbreeScene::Impl::~Impl() {
  for (const auto& pieces : motion)
    for (const MotionGeometry& piece : pieces) rtcReleaseGeometry(piece.geom);
  for (RTCGeometry geom : still)
    if (geom) rtcReleaseGeometry(geom);
  if (scene) rtcReleaseScene(scene);
  if (live_scene) rtcReleaseScene(live_scene);
}

EmbreeScene::EmbreeScene() : impl_(std::make_shared<Impl>()) {}

uint32_t EmbreeScene::add(Shape shape) {
  auto world = std::make_shared<const Shape>(std::move(shape));
  return add(std::make_shared<const ShapeBvh>(world), Transform{}, world);
}

uint32_t EmbreeScene::add(TriangleMesh mesh, std::shared_ptr<const AlphaMask> mask) {
  auto world = std::make_shared<const Shape>(std::move(mesh));
  return add(std::make_shared<const ShapeBvh>(world, std::move(mask)), Transform{}, world);
}

uint32_t EmbreeScene::add(std::shared_ptr<const ShapeBvh> bvh, const Transform& to_world,
                          std::shared_ptr<const Shape> world, bool indirect,
                          std::shared_ptr<const MeshPaint> paint, std::shared_ptr<const AlphaTexture> brush) {
  if (impl_->committed) throw std::logic_error("EmbreeScene::add after commit");
  impl_->instances.push_back({std::move(bvh), to_world, std::move(world), indirect});
  impl_->instances.back().paint = std::move(paint);
  impl_->instances.back().brush = std::move(brush);
  return uint32_t(impl_->instances.size() - 1);
}

EmbreeScene EmbreeScene::with_instances_of(const EmbreeScene& other) {
  EmbreeScene scene;
  scene.impl_->instances = other.impl_->instances;
  return scene;
}

void EmbreeScene::replace(uint32_t index, std::shared_ptr<const ShapeBvh> bvh, const Transform& to_world,
                          std::shared_ptr<const Shape> world) {
  if (impl_->committed) throw std::logic_error("EmbreeScene::replace after commit");
  Instance& instance = impl_->instances.at(index);
  if (instance.moving) throw std::logic_error("EmbreeScene::replace of a moving shape");
  instance.bvh = std::move(bvh);
  instance.to_world = to_world;
  instance.world = std::move(world);
  instance.paint = nullptr;
  instance.brush = nullptr;
}

uint32_t EmbreeScene::add_moving(std::shared_ptr<const ShapeBvh> bvh, const Transform& open,
                                 const Transform& close, std::shared_ptr<const Shape> local,
                                 std::shared_ptr<const Shape> world, bool indirect,
                                 std::shared_ptr<const MeshPaint> paint,
                                 std::shared_ptr<const AlphaTexture> brush) {
  if (impl_->committed) throw std::logic_error("EmbreeScene::add_moving after commit");
  Instance instance{std::move(bvh), open, std::move(world), indirect};
  instance.moving = true;
  instance.to_close = close;
  instance.local = local ? std::move(local) : instance.bvh->shared_shape();
  instance.paint = std::move(paint);
  instance.brush = std::move(brush);
  impl_->instances.push_back(std::move(instance));
  return uint32_t(impl_->instances.size() - 1);
}

EmbreeScene::TopLevels EmbreeScene::split_top_levels(const EmbreeScene* previous) const {
  // Only still shapes, the same number of them: what an edit that moves a few objects makes.
  if (!previous || previous->impl_->instances.size() != impl_->instances.size() ||
      previous->impl_->any_moving)
    return {};
  const auto& now = impl_->instances;
  const auto& before = previous->impl_->instances;
  if (std::any_of(now.begin(), now.end(), [](const Instance& i) { return i.moving; })) return {};
  // The shapes placed anew, with those previous already traced apart.
  std::vector<uint32_t> live = previous->impl_->live;
  bool share_main = true;
  // A new brush or paint is not a new placement: hits find both by the instance.
  for (uint32_t id = 0; id < now.size(); ++id) {
    const bool same = now[id].bvh == before[id].bvh && now[id].indirect == before[id].indirect &&
                      now[id].to_world.m == before[id].to_world.m;
    if (same || std::binary_search(previous->impl_->live.begin(), previous->impl_->live.end(), id)) continue;
    // Previous's main top level places this shape where it was: it cannot serve.
    share_main = false;
    live.insert(std::upper_bound(live.begin(), live.end(), id), id);
    if (live.size() > kMostLiveShapes) return {};
  }
  return {std::move(live), share_main};
}

void EmbreeScene::commit(const EmbreeScene* previous) {
  if (impl_->committed) throw std::logic_error("EmbreeScene::commit twice");
  if (previous && !previous->impl_->committed) previous = nullptr;
  RTCDevice device = shared_embree_device();
  TopLevels split = split_top_levels(previous);
  impl_->live = std::move(split.live);
  // Few instances, rebuilt on every move of an object: a fast build matters more
  // than the last few percent of traversal speed, which the bottom levels decide.
  if (split.share_main) {
    impl_->scene = previous->impl_->scene;
    rtcRetainScene(impl_->scene);
  } else {
    impl_->scene = new_embree_scene(RTC_BUILD_QUALITY_MEDIUM);
  }
  if (!impl_->live.empty()) impl_->live_scene = new_embree_scene(RTC_BUILD_QUALITY_MEDIUM);
  // The top level that traces shape `id`, or null when the shared main one holds it already.
  const auto top_level_of = [&](uint32_t id) -> RTCScene {
    if (std::binary_search(impl_->live.begin(), impl_->live.end(), id)) return impl_->live_scene;
    return split.share_main ? nullptr : impl_->scene;
  };
  impl_->motion.assign(impl_->instances.size(), {});
  impl_->still.assign(impl_->instances.size(), nullptr);
  impl_->alpha_textures.resize(impl_->instances.size());
  for (uint32_t id = 0; id < impl_->instances.size(); ++id) impl_->alpha_textures[id] = alpha_texture(id);
  // previous's Embree instance of shape `id`, when it places what this one does.
  const auto reusable = [&](uint32_t id) -> RTCGeometry {
    if (!previous || id >= previous->impl_->still.size()) return nullptr;
    const Instance& a = impl_->instances[id];
    const Instance& b = previous->impl_->instances[id];
    return a.bvh == b.bvh && a.indirect == b.indirect && !b.moving && a.to_world.m == b.to_world.m
               ? previous->impl_->still[id]
               : nullptr;
  };
  const auto attached = [&](RTCGeometry geom, uint32_t id) {
    // The first geometry of an instance goes by the instance's index; the further pieces
    // of one that is traced in pieces go by indices after the last instance.
    uint32_t geom_id = id;
    if (!impl_->motion[id].empty() && impl_->motion[id].front().geom != geom) {
      geom_id = uint32_t(impl_->instances.size() + impl_->piece_owner.size());
      impl_->piece_owner.push_back(id);
    }
    const AlphaMask* mask = impl_->instances[id].bvh->mask();
    const bool paint = mask && mask->paint;
    rtcSetGeometryMask(geom, !paint                          ? kSolid
                             : impl_->instances[id].indirect ? kPaint | kPaintIndirect
                                                             : kPaint);
    rtcCommitGeometry(geom);
    if (RTCScene top = top_level_of(id)) rtcAttachGeometryByID(top, geom, geom_id);
  };
  for (uint32_t id = 0; id < impl_->instances.size(); ++id) {
    const Instance& instance = impl_->instances[id];
    if (!instance.moving) {
      // What does not move has one time step: rays ignore their time there, and a
      // scene without moving shapes is traced exactly as without motion blur. A
      // singular placement is not traced at all (docs/architecture.md, "Singular transforms").
      if (RTCGeometry shared = reusable(id)) {
        // Committed already, with this instance's ray mask (paint or solid).
        rtcRetainGeometry(shared);
        if (RTCScene top = top_level_of(id)) rtcAttachGeometryByID(top, shared, id);
        impl_->still[id] = shared;
      } else if (placeable(instance.to_world)) {
        RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(geom, instance.bvh->embree_scene());
        rtcSetGeometryTimeStepCount(geom, 1);
        const std::array<float, 12> xfm = embree_transform(instance.to_world);
        rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm.data());
        attached(geom, id);
        impl_->still[id] = geom;  // our reference
      }
    } else {
      impl_->any_moving = true;
      // Each piece of the shutter over which the placement stays invertible is an
      // Embree instance of two time steps present only over that piece.
      for (const MotionPiece& piece : motion_pieces(instance.to_world, instance.to_close)) {
        RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(geom, instance.bvh->embree_scene());
        rtcSetGeometryTimeStepCount(geom, 2);
        rtcSetGeometryTransformQuaternion(geom, 0, &piece.at_start);
        rtcSetGeometryTransformQuaternion(geom, 1, &piece.at_end);
        if (piece.start != 0.f || piece.end != 1.f) rtcSetGeometryTimeRange(geom, piece.start, piece.end);
        impl_->motion[id].push_back({piece.start, piece.end, geom});  // keeps the reference
        attached(geom, id);
      }
    }
    const AlphaMask* mask = instance.bvh->mask();
    const bool paint = mask && mask->paint;
    if (paint) {
      impl_->camera_paint.push_back(id);
      impl_->camera_layer = std::max(impl_->camera_layer, mask->layer_thickness);
      if (instance.indirect) impl_->indirect_paint.push_back(id);
    }
  }
  impl_->direct_paint = std::all_of(impl_->camera_paint.begin(), impl_->camera_paint.end(), [&](uint32_t id) {
    return !impl_->instances[id].moving && impl_->instances[id].to_world.is_identity();
  });
  for (const uint32_t id : impl_->camera_paint) {
    RTCBounds b;
    rtcGetSceneBounds(impl_->instances[id].bvh->embree_scene(), &b);
    const float grow = impl_->instances[id].bvh->mask()->layer_thickness;
    impl_->camera_paint_bounds.push_back(
        {Point3(b.lower_x, b.lower_y, b.lower_z) - grow, Point3(b.upper_x, b.upper_y, b.upper_z) + grow});
  }
  if (!split.share_main) rtcCommitScene(impl_->scene);
  if (impl_->live_scene) rtcCommitScene(impl_->live_scene);
  impl_->committed = true;
}

bool EmbreeScene::same_instances(const EmbreeScene& other) const {
  const auto& a = impl_->instances;
  const auto& b = other.impl_->instances;
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].bvh != b[i].bvh || a[i].world != b[i].world || a[i].to_world.m != b[i].to_world.m ||
        a[i].indirect != b[i].indirect || a[i].moving != b[i].moving || a[i].paint != b[i].paint ||
        a[i].brush != b[i].brush ||
        (a[i].moving && (a[i].to_close.m != b[i].to_close.m || a[i].local != b[i].local)))
      return false;
  return true;
}

Transform EmbreeScene::placement(uint32_t index, float time) const {
  const Instance& instance = impl_->instances[index];
  if (!instance.moving) return instance.to_world;
  // The piece traced at that instant, or the nearest: a hit is never where none is.
  const auto& pieces = impl_->motion[index];
  if (pieces.empty()) return instance.to_world;
  time = glm::clamp(time, 0.f, 1.f);
  const Impl::MotionGeometry* piece = &pieces.front();
  for (const Impl::MotionGeometry& p : pieces)
    if (time >= p.start) piece = &p;
  std::array<float, 12> xfm{};
  rtcGetGeometryTransform(piece->geom, glm::clamp(time, piece->start, piece->end),
                          RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm.data());
  return from_embree(xfm);
}

bool EmbreeScene::intersect(const Ray& ray, float t_max, Hit* hit, RayKind kind) const {
  // Camera rays find the surface first and then the paint on it, which lies
  // within the layer in front of the hit: the paint BVH, a shell around the
  // object, is walked over that stretch only, not by every ray passing near it.
  const bool surface_first = kind == RayKind::camera && impl_->direct_paint && !impl_->camera_paint.empty();
  const unsigned seen = surface_first ? kSolid : kSolid | (kind == RayKind::camera ? kPaint : kPaintIndirect);
  Vec3 ng;
  if (!closest_hit(*impl_, ray, t_max, seen, hit, &ng)) return false;
  const ShapeBvh& bvh = *impl_->instances[hit->geometry].bvh;
  if (surface_first) {
    paint_on_surface(ray, ng, hit);
    return true;
  }
  const AlphaMask* mask = bvh.mask();
  if (mask && mask->paint) {
    if (!impl_->instances[hit->geometry].moving) {
      resolve_paint(ray, mask->layer_thickness, ng, kind, hit);
    } else {
      // Embree reports the normal in the instance's space: carried to where the
      // paint stands at the ray's time, its layer stretched with it.
      const Transform at = placement(hit->geometry, ray.time);
      resolve_paint(ray, mask->layer_thickness * stretch(at), at.normal(ng), kind, hit);
    }
  }
  return true;
}

bool EmbreeScene::intersect_solid(const Ray& ray, float t_max, Hit* hit) const {
  Vec3 ng;
  return closest_hit(*impl_, ray, t_max, kSolid, hit, &ng);
}

void EmbreeScene::paint_on_surface(const Ray& ray, const Vec3& ng, Hit* hit) const {
  // As in resolve_paint: the layer's thickness over the cosine, capped at
  // grazing angles. The ray comes from in front of the paint, so the stretch
  // ends at the surface. Embree reports a mesh's normal in its instance's space
  // and none for a sphere (a user geometry).
  // Most surface hits lie outside every painted object's bounds: nothing to ask.
  const Point3 p = ray.o + hit->t * ray.d;
  const auto inside = [&](const std::array<Point3, 2>& b) {
    return p.x >= b[0].x && p.y >= b[0].y && p.z >= b[0].z && p.x <= b[1].x && p.y <= b[1].y && p.z <= b[1].z;
  };
  if (std::none_of(impl_->camera_paint_bounds.begin(), impl_->camera_paint_bounds.end(), inside)) return;
  const Instance& instance = impl_->instances[hit->geometry];
  Vec3 n = ng;
  if (instance.moving) {
    const Transform at = placement(hit->geometry, ray.time);
    if (const auto* sphere = std::get_if<Sphere>(instance.local.get()))
      n = Sphere{sphere->center, sphere->radius, at * sphere->to_world}.normal_at(p);
    else
      n = at.normal(ng);
  } else if (const auto* sphere = std::get_if<Sphere>(instance.world.get())) {
    n = sphere->normal_at(p);
  } else if (!instance.to_world.is_identity()) {
    n = instance.to_world.normal(ng);
  }
  const float d_len = glm::length(ray.d), ng_len = glm::length(n);
  if (!(d_len > 0.f) || !(ng_len > 0.f)) return;
  const float cos_theta = std::abs(glm::dot(ray.d, n)) / (d_len * ng_len);
  const float reach = impl_->camera_layer / (std::max(cos_theta, 0.05f) * d_len);
  QueryContext context(impl_->piece_owner, impl_->alpha_textures);
  rtcInitIntersectContext(&context.rtc);
  PaintHit top;
  top.found = false;
  context.paint = &top;
  RTCRayHit rh{};
  rh.ray = to_rtc(ray, hit->t * (1.f + 1e-5f));
  rh.ray.tnear = std::max(hit->t - reach, 0.f);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  // Only the paint whose bounds hold the hit can lie over it.
  for (size_t i = 0; i < impl_->camera_paint.size(); ++i) {
    if (!inside(impl_->camera_paint_bounds[i])) continue;
    context.instance = impl_->camera_paint[i];
    rtcIntersect1(impl_->instances[context.instance].bvh->embree_scene(), &context.rtc, &rh);
  }
  if (top.found) *hit = {top.t, top.instance, top.prim, {top.u, top.v}};
}

void EmbreeScene::resolve_paint(const Ray& ray, float layer_thickness, const Vec3& ng, RayKind kind,
                                Hit* hit) const {
  // Other paint under the hit lies within the layer's thickness of it, which
  // the ray crosses over this distance (capped at grazing angles, where the
  // layer would reach across the object). Paint nearer than the hit was refused
  // already: the stretch starts at it.
  const float d_len = glm::length(ray.d), ng_len = glm::length(ng);
  if (!(d_len > 0.f) || !(ng_len > 0.f)) return;
  const float cos_theta = std::abs(glm::dot(ray.d, ng)) / (d_len * ng_len);
  const float reach = layer_thickness / (std::max(cos_theta, 0.05f) * d_len);
  // The same ray, so every alpha test decides as it did, over that stretch only.
  QueryContext context(impl_->piece_owner, impl_->alpha_textures);
  rtcInitIntersectContext(&context.rtc);
  PaintHit top{hit->geometry, hit->prim, hit->t, hit->barycentric.x, hit->barycentric.y};
  context.paint = &top;
  RTCRayHit rh{};
  rh.ray = to_rtc(ray, hit->t + reach);
  rh.ray.tnear = hit->t * (1.f - 1e-5f);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  if (impl_->direct_paint) {
    // Each paint BVH on its own: no top level and no instance to enter, which
    // cost this short query as much as the paint it crosses.
    for (const uint32_t id : kind == RayKind::camera ? impl_->camera_paint : impl_->indirect_paint) {
      context.instance = id;
      rtcIntersect1(impl_->instances[id].bvh->embree_scene(), &context.rtc, &rh);
    }
  } else {
    rh.ray.mask = kind == RayKind::camera ? kPaint : kPaintIndirect;
    intersect_top_levels(*impl_, context, rh);
  }
  *hit = {top.t, top.instance, top.prim, {top.u, top.v}};
}

bool EmbreeScene::occluded(const Ray& ray, float t_max) const {
  QueryContext context(impl_->piece_owner, impl_->alpha_textures);
  rtcInitIntersectContext(&context.rtc);
  if (!traceable(ray, t_max)) return false;
  RTCRay r = to_rtc(ray, t_max);
  r.mask = kSolid;
  rtcOccluded1(impl_->scene, &context.rtc, &r);
  if (r.tfar >= 0.f && impl_->live_scene) rtcOccluded1(impl_->live_scene, &context.rtc, &r);
  return r.tfar < 0.f;
}

SurfaceInteraction EmbreeScene::moving_interaction(const Ray& ray, const Hit& hit, float* layer_scale) const {
  // A moving shape is hit where it stands at the ray's time, not where the frame
  // has it (`world`): its own shape placed by Embree's interpolated transform, the
  // one the ray was traced through (docs/architecture.md, "Motion blur").
  const Transform at = placement(hit.geometry, ray.time);
  *layer_scale = stretch(at);
  const Shape& shape = *impl_->instances[hit.geometry].local;
  if (const auto* mesh = std::get_if<TriangleMesh>(&shape))
    return triangle_interaction<true>(*mesh, hit, ray, &at);
  const Sphere& sphere = std::get<Sphere>(shape);
  return Sphere{sphere.center, sphere.radius, at * sphere.to_world}.interaction(ray, hit.t);
}

SurfaceInteraction EmbreeScene::interaction(const Ray& ray, const Hit& hit) const {
  const Instance& instance = impl_->instances[hit.geometry];
  const Shape& shape = *instance.world;
  float layer_scale = 1.f;
  SurfaceInteraction si = instance.moving ? moving_interaction(ray, hit, &layer_scale)
                          : std::holds_alternative<TriangleMesh>(shape)
                              ? triangle_interaction<false>(std::get<TriangleMesh>(shape), hit, ray)
                              : std::get<Sphere>(shape).interaction(ray, hit.t);
  si.object = hit.geometry;
  si.time = ray.time;
  if (instance.paint && hit.prim < instance.paint->group_of_triangle->size()) {
    // Weighed as interpolate_shading weighs three vertex colours equal to it.
    const Color c = instance.paint->colors[(*instance.paint->group_of_triangle)[hit.prim]];
    const float b1 = hit.barycentric.x, b2 = hit.barycentric.y, b0 = 1.f - b1 - b2;
    si.color = b0 * c + b1 * c + b2 * c;
  }
  const AlphaMask* mask = instance.bvh->mask();
  if (mask && mask->paint && mask->layer_thickness > 0.f) {
    // Paint is seen in painting order, not by height, so its shading point may
    // sit on top of the layer, on the side the ray came from: rays leaving it
    // then start clear of the paint around it instead of testing and refusing
    // every stroke there (the layer test in alpha_accepts).
    const float side = glm::dot(ray.d, si.ng) < 0.f ? 1.f : -1.f;
    si.p += side * (mask->layer_thickness * layer_scale) * si.ng;
    si.p_error += Vec3(gamma_bound(2) * max_component(glm::abs(si.p)));
  }
  return si;
}

void EmbreeScene::bounds(Point3* lo, Point3* hi) const {
  RTCBounds b;
  rtcGetSceneBounds(impl_->scene, &b);
  *lo = {b.lower_x, b.lower_y, b.lower_z};
  *hi = {b.upper_x, b.upper_y, b.upper_z};
  if (impl_->live_scene) {
    rtcGetSceneBounds(impl_->live_scene, &b);
    *lo = glm::min(*lo, Point3(b.lower_x, b.lower_y, b.lower_z));
    *hi = glm::max(*hi, Point3(b.upper_x, b.upper_y, b.upper_z));
  }
  if (!impl_->any_moving) return;
  // Bounds at the shutter's opening and closing, between which Embree's linear
  // bounds hold everything at every instant.
  alignas(16) RTCLinearBounds moving;
  rtcGetSceneLinearBounds(impl_->scene, &moving);
  for (const RTCBounds& at : {moving.bounds0, moving.bounds1}) {
    *lo = glm::min(*lo, Point3(at.lower_x, at.lower_y, at.lower_z));
    *hi = glm::max(*hi, Point3(at.upper_x, at.upper_y, at.upper_z));
  }
}

}  // namespace inkray
