#include "core/film/aov_display.h"

#include "core/math/hash.h"

#include <algorithm>

namespace inkray {

RgbImage aov_for_display(Aov aov, const RgbImage& raw) {
  RgbImage out = raw;
  switch (aov) {
    case Aov::albedo:
      break;
    case Aov::normal:
      for (Color& c : out.pixels)
        if (c != Color(0.f)) c = 0.5f * c + Color(0.5f);
      break;
    case Aov::depth: {
      float lo = kInfinity, hi = 0.f;
      for (const Color& c : raw.pixels)
        if (c.x > 0.f) lo = std::min(lo, c.x), hi = std::max(hi, c.x);
      // Near is bright, far is dark, misses are black.
      for (Color& c : out.pixels)
        c = c.x > 0.f ? Color(1.f - 0.9f * (hi > lo ? (c.x - lo) / (hi - lo) : 0.f)) : Color(0.f);
      break;
    }
    case Aov::object_id:
    case Aov::material_id:
      for (Color& c : out.pixels) {
        if (c.x < 0.f) {
          c = Color(0.f);
          continue;
        }
        const uint32_t h = hash_u32(uint32_t(c.x) + 1u);
        c = Color(0.2f) +
            0.8f * Color(float(h & 255u), float((h >> 8) & 255u), float((h >> 16) & 255u)) / 255.f;
      }
      break;
    case Aov::toon_band:  // -1 off toon surfaces, else up to 7 (film.h): grey steps, black elsewhere
      for (Color& c : out.pixels) c = Color(glm::clamp((c.x + 1.f) / 8.f, 0.f, 1.f));
      break;
    default:
      break;  // outline opacities are already in [0, 1]
  }
  return out;
}

}  // namespace inkray
