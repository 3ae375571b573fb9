#include "core/math/transform.h"

#include "core/math/float_error.h"

#include <glm/gtc/matrix_transform.hpp>

namespace inkray {

Transform Transform::from_matrix(const Mat4& mat) { return {mat, glm::inverse(mat)}; }
Transform Transform::translate(const Vec3& t) {
  return {glm::translate(Mat4(1.f), t), glm::translate(Mat4(1.f), -t)};
}
Transform Transform::scale(const Vec3& s) {
  return {glm::scale(Mat4(1.f), s), glm::scale(Mat4(1.f), 1.f / s)};
}
Transform Transform::rotate(float degrees, const Vec3& axis) {
  const Mat4 r = glm::rotate(Mat4(1.f), glm::radians(degrees), glm::normalize(axis));
  return {r, glm::transpose(r)};
}

Transform operator*(const Transform& b, const Transform& a) { return {b.m * a.m, a.inv * b.inv}; }

Point3 Transform::point_with_error(const Point3& p, const Vec3& p_error, Vec3* out_error) const {
  const Point3 result = point(p);
  Vec3 err(0.f);
  for (int row = 0; row < 3; ++row) {
    float abs_sum = std::abs(m[3][row]);
    float err_sum = 0.f;
    for (int col = 0; col < 3; ++col) {
      abs_sum += std::abs(m[col][row] * p[col]);
      err_sum += std::abs(m[col][row]) * p_error[col];
    }
    err[row] = (gamma_bound(3) + 1.f) * err_sum + gamma_bound(3) * abs_sum;
  }
  *out_error = err;
  return result;
}

}  // namespace inkray
