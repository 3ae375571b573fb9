// Alpha mask lookups: called from Embree's filter callbacks for every candidate
// hit on an alpha-tested mesh, so they stay branch-light and allocation-free.
#include "core/geometry/alpha_mask.h"

#include "core/math/hash.h"

#include <algorithm>
#include <cmath>

namespace inkray {

uint32_t AlphaMask::variant_of(uint32_t prim) const {
  if (!triangles.empty())
    return prim < triangles.size() ? (uint32_t(triangles[prim].pick) * uint32_t(variants)) >> 8 : 0;
  if (variants <= 1 || triangles_per_item == 0) return 0;
  return hash_u32(prim / triangles_per_item) % uint32_t(variants);
}

float AlphaMask::coverage_in(int variant, Vec2 uv) const {
  if (width <= 0 || height <= 0) return 1.f;
  // Texel centres sit at (i + 0.5) / width; beyond the outer centres the edge texel holds.
  // fmax/fmin rather than clamp: a NaN uv lands on texel 0 instead of reaching floor().
  const float x = std::fmin(std::fmax(uv.x * float(width) - 0.5f, 0.f), float(width - 1));
  const float y = std::fmin(std::fmax(uv.y * float(height) - 0.5f, 0.f), float(height - 1));
  const int x0 = int(x), y0 = int(y);  // x, y >= 0: truncation is floor
  const int dx = x0 + 1 < width ? 1 : 0;
  const size_t dy = y0 + 1 < height ? size_t(width) : 0;
  const float tx = x - float(x0), ty = y - float(y0);
  const uint8_t* row =
      texels.data() + (size_t(variant) * size_t(height) + size_t(y0)) * size_t(width) + size_t(x0);
  const float t00 = row[0], t10 = row[dx], t01 = row[dy], t11 = row[dy + size_t(dx)];
  const float top = t00 + tx * (t10 - t00);
  const float bottom = t01 + tx * (t11 - t01);
  return (top + ty * (bottom - top)) * (1.f / 255.f);
}

float AlphaMask::coverage(Vec2 uv, uint32_t prim) const { return coverage_in(int(variant_of(prim)), uv); }

float AlphaMask::coverage_of(const AlphaTriangle& t, float b1, float b2) const {
  const float b0 = 1.f - b1 - b2;
  const float fade = (b0 * float(t.fade[0]) + b1 * float(t.fade[1]) + b2 * float(t.fade[2])) * (1.f / 255.f);
  if (fade <= 0.f) return 0.f;
  const Vec2 uv((b0 * float(t.u[0]) + b1 * float(t.u[1]) + b2 * float(t.u[2])) * (1.f / 65535.f),
                (b0 * float(t.v[0]) + b1 * float(t.v[1]) + b2 * float(t.v[2])) * (1.f / 65535.f));
  const int variant = int((uint32_t(t.pick) * uint32_t(variants)) >> 8);
  return std::min(fade, 1.f) * coverage_in(variant, uv);
}

}  // namespace inkray
