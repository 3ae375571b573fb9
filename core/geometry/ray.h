// Rays and the surface record of a hit.
#pragma once

#include "core/math/types.h"

namespace inkray {

// `time` is the instant of the shutter the ray samples, in [0, 1) from its opening
// to its closing (0 without motion blur). Every ray spawned from a hit inherits it,
// so one camera sample sees the scene at one instant (docs/architecture.md,
// "Motion blur").
struct Ray {
  Point3 o{0.f};
  Vec3 d{0.f, 0.f, 1.f};
  float time = 0.f;
};

// What the integrator needs from a hit, in world space.
struct SurfaceInteraction {
  Point3 p{0.f};
  Vec3 p_error{0.f};          // bound on |p - true hit point| per axis
  Normal3 ng{0.f, 0.f, 1.f};  // geometric normal, oriented by winding / outward for spheres
  Normal3 ns{0.f, 0.f, 1.f};  // shading normal, in ng's hemisphere
  Vec2 uv{0.f};
  Color color{1.f};  // interpolated vertex colour (painterly strokes); multiplies base colours
  float t = 0.f;
  float time = 0.f;     // the shutter instant of the ray that found it (Ray::time)
  uint32_t object = 0;  // index into RenderScene::objects
  uint32_t prim = 0;    // triangle index within the object's mesh
};

}  // namespace inkray

#include "core/math/float_error.h"

namespace inkray {

// A ray leaving a surface point: starts outside the point's error box on the side of d.
// It samples the shutter's opening (time 0): a ray leaving a hit takes the overload
// below, which keeps the hit's instant.
inline Ray spawn_ray(const Point3& p, const Vec3& p_error, const Normal3& n, const Vec3& d) {
  return {offset_ray_origin(p, p_error, n, d), d};
}
// A ray leaving a hit, at the hit's instant; n picks the side it leaves from.
inline Ray spawn_ray(const SurfaceInteraction& si, const Normal3& n, const Vec3& d) {
  return {offset_ray_origin(si.p, si.p_error, n, d), d, si.time};
}

// A shadow ray between two surface points. Its direction is unnormalised, so
// t runs from 0 at `from` to 1 at `to`; trace it up to kShadowTMax. Its time is
// the caller's to set (lights stand where the frame has them).
inline constexpr float kShadowTMax = 1.f - 1e-4f;
inline Ray spawn_ray_to(const Point3& from, const Vec3& from_error, const Normal3& from_n, const Point3& to,
                        const Vec3& to_error, const Normal3& to_n) {
  const Point3 o = offset_ray_origin(from, from_error, from_n, to - from);
  const Point3 target = offset_ray_origin(to, to_error, to_n, o - to);
  return {o, target - o};
}

}  // namespace inkray
