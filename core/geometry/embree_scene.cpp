#include "core/geometry/embree_scene.h"

#include "core/geometry/embree_device.h"
#include "core/math/float_error.h"
#include "core/math/hash.h"

#include <embree3/rtcore.h>

#include <array>
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

// Whether a candidate hit on an alpha-tested mesh counts. The uniform number
// comes from a hash of the ray's bits and the triangle: the same ray always
// decides the same way (Embree may report a triangle twice under spatial
// splits), while the many rays of a pixel sample the coverage.
bool alpha_accepts(const TriangleMesh& mesh, const AlphaMask& mask, const RTCFilterFunctionNArguments* args) {
  RTCRayN* ray = args->ray;
  RTCHitN* hit = args->hit;
  const unsigned n = args->N;
  const uint32_t prim = RTCHitN_primID(hit, n, 0);
  const float b1 = RTCHitN_u(hit, n, 0), b2 = RTCHitN_v(hit, n, 0), b0 = 1.f - b1 - b2;
  const Point3 o(RTCRayN_org_x(ray, n, 0), RTCRayN_org_y(ray, n, 0), RTCRayN_org_z(ray, n, 0));
  const Vec3 d(RTCRayN_dir_x(ray, n, 0), RTCRayN_dir_y(ray, n, 0), RTCRayN_dir_z(ray, n, 0));
  if (mask.layer_thickness > 0.f) {
    // A ray leaving the surface the layer lies on (or the layer itself) starts
    // within the layer's thickness of the triangle's plane: it passes through.
    const Vec3 ng(RTCHitN_Ng_x(hit, n, 0), RTCHitN_Ng_y(hit, n, 0), RTCHitN_Ng_z(hit, n, 0));
    const float ng_len = glm::length(ng);
    const float height = RTCRayN_tfar(ray, n, 0) * std::abs(glm::dot(d, ng));
    if (height < mask.layer_thickness * ng_len) return false;
  }
  const uint32_t* idx = &mesh.indices[3 * size_t(prim)];
  const Vec2 uv = b0 * mesh.uvs[idx[0]] + b1 * mesh.uvs[idx[1]] + b2 * mesh.uvs[idx[2]];
  const float alpha = mask.coverage(uv, prim);
  if (alpha >= 1.f) return true;
  if (alpha <= 0.f) return false;
  uint32_t h = hash_combine(std::bit_cast<uint32_t>(o.x), std::bit_cast<uint32_t>(o.y),
                            std::bit_cast<uint32_t>(o.z), prim);
  h = hash_combine(h, std::bit_cast<uint32_t>(d.x), std::bit_cast<uint32_t>(d.y), std::bit_cast<uint32_t>(d.z));
  return u32_to_unit_float(h) < alpha;
}

// We only call the single-ray API, so filters see N == 1. The user data is the
// ShapeBvh, whose shape is the mesh (in the space the filter's ray is in).
void alpha_filter(const RTCFilterFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const auto* bvh = static_cast<const ShapeBvh*>(args->geometryUserPtr);
  if (!alpha_accepts(std::get<TriangleMesh>(bvh->shape()), *bvh->mask(), args)) args->valid[0] = 0;
}

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
  r.mask = 0xffffffffu;
  r.flags = 0;
  return r;
}

SurfaceInteraction triangle_interaction(const TriangleMesh& mesh, const Hit& hit, const Ray& ray) {
  const uint32_t i0 = mesh.indices[3 * hit.prim], i1 = mesh.indices[3 * hit.prim + 1],
                 i2 = mesh.indices[3 * hit.prim + 2];
  const Point3 &p0 = mesh.positions[i0], &p1 = mesh.positions[i1], &p2 = mesh.positions[i2];
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
  si.p_error = Vec3(gamma_bound(7) * max_component(glm::abs(b0 * p0) + glm::abs(b1 * p1) + glm::abs(b2 * p2)));
  const Vec3 n = glm::cross(p1 - p0, p2 - p0);
  const float len = glm::length(n);
  const MeshShading shading =
      interpolate_shading(mesh, hit.prim, b1, b2, len > 0.f ? n / len : -glm::normalize(ray.d));
  si.ng = shading.ng;
  si.ns = shading.ns;
  si.uv = shading.uv;
  si.color = shading.color;
  si.prim = hit.prim;
  return si;
}

}  // namespace

RTCDevice shared_embree_device() {
  static RTCDevice device = [] {
    RTCDevice d = rtcNewDevice(nullptr);
    if (!d) throw std::runtime_error("Embree: could not create a device");
    rtcSetDeviceErrorFunction(
        d, [](void*, RTCError code, const char* msg) { std::fprintf(stderr, "Embree error %d: %s\n", int(code), msg); },
        nullptr);
    return d;
  }();
  return device;
}

namespace {

RTCScene new_embree_scene(RTCBuildQuality quality) {
  RTCScene scene = rtcNewScene(shared_embree_device());
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
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

}  // namespace

ShapeBvh::ShapeBvh(std::shared_ptr<const Shape> shape, std::shared_ptr<const AlphaMask> mask)
    : shape_(std::move(shape)), mask_(std::move(mask)) {
  const auto* mesh = std::get_if<TriangleMesh>(shape_.get());
  if (mask_ && (!mesh || mesh->uvs.size() < mesh->vertex_count()))
    throw std::invalid_argument("ShapeBvh: an alpha-tested shape must be a mesh with a uv per vertex");
  RTCDevice device = shared_embree_device();
  scene_ = new_embree_scene(RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geom = nullptr;
  if (mesh) {
    geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh->positions.data(), 0,
                               sizeof(Point3), mesh->vertex_count());
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh->indices.data(), 0,
                               3 * sizeof(uint32_t), mesh->triangle_count());
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
  rtcCommitScene(scene_);
}

ShapeBvh::~ShapeBvh() { rtcReleaseScene(scene_); }

EmbreeScene::Impl::~Impl() {
  if (scene) rtcReleaseScene(scene);
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
                          std::shared_ptr<const Shape> world) {
  if (impl_->committed) throw std::logic_error("EmbreeScene::add after commit");
  impl_->instances.push_back({std::move(bvh), to_world, std::move(world)});
  return uint32_t(impl_->instances.size() - 1);
}

void EmbreeScene::commit() {
  if (impl_->committed) throw std::logic_error("EmbreeScene::commit twice");
  RTCDevice device = shared_embree_device();
  // Few instances, rebuilt on every move of an object: a fast build matters more
  // than the last few percent of traversal speed, which the bottom levels decide.
  impl_->scene = new_embree_scene(RTC_BUILD_QUALITY_MEDIUM);
  for (uint32_t id = 0; id < impl_->instances.size(); ++id) {
    const Instance& instance = impl_->instances[id];
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geom, instance.bvh->embree_scene());
    rtcSetGeometryTimeStepCount(geom, 1);
    const std::array<float, 12> xfm = embree_transform(instance.to_world);
    rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm.data());
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(impl_->scene, geom, id);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(impl_->scene);
  impl_->committed = true;
}

bool EmbreeScene::same_instances(const EmbreeScene& other) const {
  const auto& a = impl_->instances;
  const auto& b = other.impl_->instances;
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].bvh != b[i].bvh || a[i].world != b[i].world || a[i].to_world.m != b[i].to_world.m) return false;
  return true;
}

bool EmbreeScene::intersect(const Ray& ray, float t_max, Hit* hit) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  if (!traceable(ray, t_max)) return false;
  RTCRayHit rh{};
  rh.ray = to_rtc(ray, t_max);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit->t = rh.ray.tfar;
  hit->geometry = rh.hit.instID[0];
  hit->prim = rh.hit.primID;
  hit->barycentric = {rh.hit.u, rh.hit.v};
  return true;
}

bool EmbreeScene::occluded(const Ray& ray, float t_max) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  if (!traceable(ray, t_max)) return false;
  RTCRay r = to_rtc(ray, t_max);
  rtcOccluded1(impl_->scene, &context, &r);
  return r.tfar < 0.f;
}

SurfaceInteraction EmbreeScene::interaction(const Ray& ray, const Hit& hit) const {
  const Shape& shape = *impl_->instances[hit.geometry].world;
  SurfaceInteraction si = std::holds_alternative<TriangleMesh>(shape)
                              ? triangle_interaction(std::get<TriangleMesh>(shape), hit, ray)
                              : std::get<Sphere>(shape).interaction(ray, hit.t);
  si.object = hit.geometry;
  return si;
}

void EmbreeScene::bounds(Point3* lo, Point3* hi) const {
  RTCBounds b;
  rtcGetSceneBounds(impl_->scene, &b);
  *lo = {b.lower_x, b.lower_y, b.lower_z};
  *hi = {b.upper_x, b.upper_y, b.upper_z};
}

}  // namespace inkray
