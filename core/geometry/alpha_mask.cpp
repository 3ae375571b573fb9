// Alpha mask lookups: called from Embree's filter callbacks for every candidate
// hit on an alpha-tested mesh, so they stay branch-light and allocation-free.
#include "core/geometry/alpha_mask.h"

#include "core/math/hash.h"

#include <algorithm>
#include <cmath>

namespace inkray {

uint32_t AlphaMask::variant_of(uint32_t prim, int texture_variants) const {
  if (!triangles.empty())
    return prim < triangles.size() ? (uint32_t(triangles[prim].pick) * uint32_t(texture_variants)) >> 8 : 0;
  if (texture_variants <= 1 || triangles_per_item == 0) return 0;
  return hash_u32(prim / triangles_per_item) % uint32_t(texture_variants);
}

float AlphaMask::coverage(Vec2 uv, uint32_t prim) const { return coverage_in(int(variant_of(prim)), uv); }

}  // namespace inkray
