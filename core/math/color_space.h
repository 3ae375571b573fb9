// HSV <-> RGB for colour edits that artists think of in hue, saturation and
// value (stroke colour jitter, ramps). Hue is in degrees [0, 360); s, v in [0, 1].
// Works on linear RGB as stored; HSV is a parametrisation here, not a colour space.
#pragma once

#include "core/math/types.h"

#include <cmath>

namespace inkray {

// (h, s, v) packed in a Color: x = hue in degrees, y = saturation, z = value.
// Grey has no hue; it gets h = 0 so the result is deterministic.
inline Color rgb_to_hsv(Color rgb) {
  const float v = max_component(rgb);
  const float lo = glm::min(rgb.r, glm::min(rgb.g, rgb.b));
  const float chroma = v - lo;
  if (!(chroma > 0.f) || !(v > 0.f)) return {0.f, 0.f, glm::max(v, 0.f)};
  float h = 0.f;
  if (v == rgb.r)
    h = (rgb.g - rgb.b) / chroma;
  else if (v == rgb.g)
    h = 2.f + (rgb.b - rgb.r) / chroma;
  else
    h = 4.f + (rgb.r - rgb.g) / chroma;
  h *= 60.f;
  if (h < 0.f) h += 360.f;
  if (h >= 360.f) h -= 360.f;  // -0 rounding can land exactly on 360
  return {h, chroma / v, v};
}

// Hue outside [0, 360) wraps (so -30 is 330); s and v are clamped to [0, 1].
inline Color hsv_to_rgb(Color hsv) {
  float h = std::fmod(hsv.x, 360.f);
  if (h < 0.f) h += 360.f;
  if (!std::isfinite(h)) h = 0.f;
  const float s = glm::clamp(hsv.y, 0.f, 1.f), v = glm::clamp(hsv.z, 0.f, 1.f);
  const float c = v * s;
  const float hp = h / 60.f;
  const float x = c * (1.f - std::abs(std::fmod(hp, 2.f) - 1.f));
  Color rgb(0.f);
  switch (int(hp) % 6) {
    case 0:
      rgb = {c, x, 0.f};
      break;
    case 1:
      rgb = {x, c, 0.f};
      break;
    case 2:
      rgb = {0.f, c, x};
      break;
    case 3:
      rgb = {0.f, x, c};
      break;
    case 4:
      rgb = {x, 0.f, c};
      break;
    default:
      rgb = {c, 0.f, x};
      break;
  }
  return rgb + Color(v - c);
}

// Shifts hue (wrapping) and saturation and value (clamped to [0, 1]). A grey
// colour keeps hue 0 and gains the hue shift only once it gains saturation.
inline Color jitter_hsv(Color rgb, float dh_degrees, float ds, float dv) {
  Color hsv = rgb_to_hsv(rgb);
  hsv.x += dh_degrees;
  hsv.y = glm::clamp(hsv.y + ds, 0.f, 1.f);
  hsv.z = glm::clamp(hsv.z + dv, 0.f, 1.f);
  return hsv_to_rgb(hsv);
}

}  // namespace inkray
