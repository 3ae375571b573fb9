// Alpha mask lookups: called from Embree's filter callbacks for every candidate
// hit on an alpha-tested mesh, so they stay branch-light and allocation-free.
#include "core/geometry/alpha_mask.h"

#include "core/math/hash.h"

#include <algorithm>
#include <cmath>

namespace inkray {

uint32_t AlphaMask::variant_of(uint32_t prim) const {
  if (variants <= 1 || triangles_per_item == 0) return 0;
  return hash_u32(prim / triangles_per_item) % uint32_t(variants);
}

float AlphaMask::coverage(Vec2 uv, uint32_t prim) const {
  if (width <= 0 || height <= 0) return 1.f;
  // Texel centres sit at (i + 0.5) / width; beyond the outer centres the edge texel holds.
  // fmax/fmin rather than clamp: a NaN uv lands on texel 0 instead of reaching floor().
  const float x = std::fmin(std::fmax(uv.x * float(width) - 0.5f, 0.f), float(width - 1));
  const float y = std::fmin(std::fmax(uv.y * float(height) - 0.5f, 0.f), float(height - 1));
  const float fx = std::floor(x), fy = std::floor(y);
  const int x0 = int(fx), x1 = std::min(x0 + 1, width - 1);
  const int y0 = int(fy), y1 = std::min(y0 + 1, height - 1);
  const float tx = x - fx, ty = y - fy;
  const int layer = int(variant_of(prim));
  const float top = float(at(layer, x0, y0)) + tx * (float(at(layer, x1, y0)) - float(at(layer, x0, y0)));
  const float bottom = float(at(layer, x0, y1)) + tx * (float(at(layer, x1, y1)) - float(at(layer, x0, y1)));
  return (top + ty * (bottom - top)) * (1.f / 255.f);
}

}  // namespace inkray
