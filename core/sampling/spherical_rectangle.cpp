#include "core/sampling/spherical_rectangle.h"

#include <algorithm>
#include <cmath>

namespace inkray {
namespace {

using D3 = glm::dvec3;

constexpr double kTwoPi = 6.283185307179586;

}  // namespace

std::optional<SphericalRectangle> spherical_rectangle(const Point3& from, const Point3& corner, const Vec3& x,
                                                      const Vec3& y, float width, float height) {
  SphericalRectangle r;
  r.origin = from;
  r.x = x;
  r.y = y;
  r.z = glm::cross(x, y);
  const D3 d = D3(corner) - D3(from);
  r.z0 = glm::dot(d, D3(r.z));
  if (r.z0 > 0.0) r.z = -r.z, r.z0 = -r.z0;  // the rectangle on the -z side
  if (!(r.z0 < 0.0)) return std::nullopt;
  r.x0 = glm::dot(d, D3(x));
  r.y0 = glm::dot(d, D3(y));
  r.x1 = r.x0 + double(width);
  r.y1 = r.y0 + double(height);
  // The corners' directions and the normals of the four great circles through them.
  const D3 v00(r.x0, r.y0, r.z0), v01(r.x0, r.y1, r.z0), v10(r.x1, r.y0, r.z0), v11(r.x1, r.y1, r.z0);
  const D3 n0 = glm::normalize(glm::cross(v00, v10)), n1 = glm::normalize(glm::cross(v10, v11));
  const D3 n2 = glm::normalize(glm::cross(v11, v01)), n3 = glm::normalize(glm::cross(v01, v00));
  const auto angle = [](const D3& a, const D3& b) {
    return std::acos(std::clamp(-glm::dot(a, b), -1.0, 1.0));
  };
  const double g0 = angle(n0, n1), g1 = angle(n1, n2), g2 = angle(n2, n3), g3 = angle(n3, n0);
  r.b0 = n0.z;
  r.b1 = n2.z;
  r.k = kTwoPi - g2 - g3;
  r.solid_angle = g0 + g1 - r.k;
  if (!(r.solid_angle > 0.0) || !std::isfinite(r.solid_angle)) return std::nullopt;
  return r;
}

Point3 sample_spherical_rectangle(const SphericalRectangle& r, Vec2 u) {
  // The x of the point: the sub-rectangle [x0, xu] holds a fraction u.x of the solid angle.
  const double au = double(u.x) * r.solid_angle + r.k;
  const double fu = (std::cos(au) * r.b0 - r.b1) / std::sin(au);
  const double cu = std::clamp(std::copysign(1.0, fu) / std::sqrt(fu * fu + r.b0 * r.b0), -1.0, 1.0);
  const double xu = std::clamp(-(cu * r.z0) / std::sqrt(std::max(1.0 - cu * cu, 1e-300)), r.x0, r.x1);
  // Its y: uniform in the projected height along that column.
  const double dist2 = xu * xu + r.z0 * r.z0, dist = std::sqrt(dist2);
  const double h0 = r.y0 / std::sqrt(dist2 + r.y0 * r.y0);
  const double h1 = r.y1 / std::sqrt(dist2 + r.y1 * r.y1);
  const double hv = h0 + double(u.y) * (h1 - h0), hv2 = hv * hv;
  const double yv = hv2 < 1.0 - 1e-12 ? std::clamp(hv * dist / std::sqrt(1.0 - hv2), r.y0, r.y1) : r.y1;
  return Point3(D3(r.origin) + xu * D3(r.x) + yv * D3(r.y) + r.z0 * D3(r.z));
}

}  // namespace inkray
