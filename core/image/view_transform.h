// What a viewer does to scene-linear radiance before encoding it: exposure, then a
// view transform to display-linear values. Its inverse lets a colour chosen on the
// display (a line colour) be stored in a linear image that encodes back to it.
#pragma once

#include "core/math/types.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace inkray {

enum class ViewTransform { standard, filmic, raw };
inline constexpr std::array<std::string_view, 3> kViewTransformNames = {"standard", "filmic", "raw"};

struct DisplayEncoding {
  float exposure = 0.f;  // stops
  ViewTransform transform = ViewTransform::standard;
  bool operator==(const DisplayEncoding&) const = default;
};

// Narkowicz's fit of the ACES filmic curve: highlights roll off instead of clipping.
// Increasing from 0 at 0 to 1 at filmic_white(), and 1 beyond.
inline float filmic_curve(float x) {
  x *= 0.6f;
  return std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.f, 1.f);
}
// The x where filmic_curve reaches 1: the inverse's value at 1.
float filmic_white();
// The inverse of filmic_curve on [0, 1]: 0 at 0, filmic_white() at 1 (inputs clamped).
float filmic_curve_inverse(float y);

// One display's mapping, with 2^exposure computed once for per-pixel loops.
//   standard: exposure, clamped to [0, 1]
//   filmic:   exposure, then filmic_curve, in [0, 1]
//   raw:      exposure alone, unclamped (its 8-bit encoding clamps)
// from_display inverts it on [0, 1] (raw: everywhere), so a display value there
// comes back from to_display(from_display(d)) as d, up to rounding.
class DisplayMapping {
 public:
  explicit DisplayMapping(const DisplayEncoding& e)
      : scale_(std::exp2(e.exposure)), transform_(e.transform) {}

  ViewTransform transform() const { return transform_; }

  float to_display(float radiance) const {
    const float x = scale_ * radiance;
    switch (transform_) {
      case ViewTransform::standard:
        return std::clamp(x, 0.f, 1.f);
      case ViewTransform::filmic:
        return filmic_curve(x);
      case ViewTransform::raw:
        break;
    }
    return x;
  }
  float from_display(float display) const {
    switch (transform_) {
      case ViewTransform::standard:
        return std::clamp(display, 0.f, 1.f) / scale_;
      case ViewTransform::filmic:
        return filmic_curve_inverse(display) / scale_;
      case ViewTransform::raw:
        break;
    }
    return display / scale_;
  }
  Color to_display(const Color& c) const { return {to_display(c.r), to_display(c.g), to_display(c.b)}; }
  Color from_display(const Color& c) const {
    return {from_display(c.r), from_display(c.g), from_display(c.b)};
  }

 private:
  float scale_;
  ViewTransform transform_;
};

}  // namespace inkray
