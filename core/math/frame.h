// Orthonormal frame around a normal, for moving directions into and out of
// the local shading space where the normal is +z.
#pragma once

#include "core/math/types.h"

namespace inkray {

struct Frame {
  Vec3 x, y, z;

  // Duff et al. 2017, "Building an Orthonormal Basis, Revisited": branchless and
  // continuous except at one point, so no tuned epsilon is needed.
  static Frame from_z(const Vec3& n) {
    const float sign = std::copysign(1.f, n.z);
    const float a = -1.f / (sign + n.z);
    const float b = n.x * n.y * a;
    return {Vec3(1.f + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3(b, sign + n.y * n.y * a, -n.y), n};
  }
  Vec3 to_local(const Vec3& v) const { return {glm::dot(v, x), glm::dot(v, y), glm::dot(v, z)}; }
  Vec3 to_world(const Vec3& v) const { return x * v.x + y * v.y + z * v.z; }
};

}  // namespace inkray
