// Affine transforms: a matrix with its inverse, applied to points, vectors and
// normals, with the rounding error of the point transform bounded (pbrt-v4 6.8).
#pragma once

#include "core/math/types.h"

namespace inkray {

struct Transform {
  Mat4 m{1.f};
  Mat4 inv{1.f};

  static Transform from_matrix(const Mat4& mat);
  static Transform translate(const Vec3& t);
  static Transform scale(const Vec3& s);
  // Right-handed rotation about an arbitrary axis, angle in degrees.
  static Transform rotate(float degrees, const Vec3& axis);

  Point3 point(const Point3& p) const { return Point3(m * glm::vec4(p, 1.f)); }
  Vec3 vector(const Vec3& v) const { return Vec3(m * glm::vec4(v, 0.f)); }
  // Normals transform by the inverse transpose; result is not normalised.
  Normal3 normal(const Normal3& n) const { return Vec3(glm::transpose(inv) * glm::vec4(n, 0.f)); }
  // Transforms p and bounds the absolute error of the result.
  Point3 point_with_error(const Point3& p, const Vec3& p_error, Vec3* out_error) const;
  bool is_identity() const { return m == Mat4(1.f); }
};

// a then b: (b * a)(p) = b(a(p)).
Transform operator*(const Transform& b, const Transform& a);

}  // namespace inkray
