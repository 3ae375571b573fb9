// Sampling a rectangle uniformly in the solid angle it subtends from a point
// (Urena, Fajardo and King 2013, "An Area-Preserving Parametrization for Spherical
// Rectangles"). Every direction towards the rectangle is equally likely, so the
// 1/distance² and cosine of area sampling leave the estimate: near a large light
// the direct light's variance falls most. Computed in double: the spherical excess of
// a small or distant rectangle is a difference of nearly equal angles (in float, 0.2%
// off at 4e-3 sr).
#pragma once

#include "core/math/types.h"

#include <optional>

namespace inkray {

struct SphericalRectangle {
  // The local frame: x and y along the rectangle's edges, z towards the reference
  // point's side (the rectangle at z = z0 < 0), origin at the reference point.
  Point3 origin{0.f};
  Vec3 x{1.f, 0.f, 0.f}, y{0.f, 1.f, 0.f}, z{0.f, 0.f, 1.f};
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0, z0 = 0;
  double b0 = 0, b1 = 0, k = 0;
  double solid_angle = 0;
};

// The rectangle corner + s * x + t * y, s in [0, width], t in [0, height] (x, y unit
// and perpendicular), seen from `from`; nullopt when `from` lies in its plane.
std::optional<SphericalRectangle> spherical_rectangle(const Point3& from, const Point3& corner, const Vec3& x,
                                                      const Vec3& y, float width, float height);

// The point of the rectangle that direction sample u reaches; its pdf in solid
// angle is 1 / solid_angle.
Point3 sample_spherical_rectangle(const SphericalRectangle& r, Vec2 u);

}  // namespace inkray
