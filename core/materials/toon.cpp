// Toon shading curves. Everything here is a pure function of the light level and
// angles, so bands are exactly reproducible and unit-testable without a scene.
#include "core/materials/toon.h"

#include <algorithm>
#include <cmath>

namespace inkray {

float toon_soft_step(float x, float edge, float width) {
  if (!(width > 0.f)) return x >= edge ? 1.f : 0.f;
  const float t = glm::clamp((x - (edge - 0.5f * width)) / width, 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

float toon_band_level(const ToonMaterial& m, float light_level) {
  const int bands = std::max(m.bands, 2);
  const float t = glm::clamp(m.threshold, 0.f, 1.f);
  const float step = (1.f - t) / float(bands - 1);
  float sum = 0.f;
  for (int k = 0; k < bands - 1; ++k) sum += toon_soft_step(light_level, t + float(k) * step, m.softness);
  return sum / float(bands - 1);
}

Color toon_ramp_eval(const std::vector<Color>& stops, float x) {
  if (stops.empty()) return Color(1.f);
  if (stops.size() == 1) return stops[0];
  const float f = glm::clamp(x, 0.f, 1.f) * float(stops.size() - 1);
  const size_t i = std::min(size_t(f), stops.size() - 2);
  return glm::mix(stops[i], stops[i + 1], f - float(i));
}

Color toon_ramp_image_eval(const RgbImage& image, float u, float v) {
  if (image.width <= 0 || image.height <= 0) return Color(1.f);
  // Texel centres span [0, 1]: u = 0 is the left column's centre, v = 0 the bottom row's.
  const float x = glm::clamp(u, 0.f, 1.f) * float(image.width - 1);
  const float y = (1.f - glm::clamp(v, 0.f, 1.f)) * float(image.height - 1);
  const int x0 = std::min(int(x), image.width - 1), y0 = std::min(int(y), image.height - 1);
  const int x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
  const float fx = x - float(x0), fy = y - float(y0);
  return glm::mix(glm::mix(image.at(x0, y0), image.at(x1, y0), fx),
                  glm::mix(image.at(x0, y1), image.at(x1, y1), fx), fy);
}

Color toon_base_color(const ToonMaterial& m, const Color& base, const ToonLightInput& in) {
  const float level = glm::clamp(in.level, 0.f, 1.f);
  // A coloured light tints what it lights; the darkest band keeps the artist's
  // shadow colour, so the tint fades in with the light and leaves no seam.
  if (m.ramp_image)
    return base * toon_ramp_image_eval(*m.ramp_image, level, in.ramp_v) *
           glm::mix(Color(1.f), in.tint, level);
  if (m.ramp && !m.ramp->empty())
    return base * toon_ramp_eval(*m.ramp, level) * glm::mix(Color(1.f), in.tint, level);
  return base * glm::mix(m.shadow_color, in.tint, toon_band_level(m, level));
}

float toon_specular_coverage(const ToonMaterial& m, float cos_nh, float relative_strength) {
  if (!m.specular || !(cos_nh > 0.f) || !(relative_strength > 0.f)) return 0.f;
  const float lobe = std::pow(std::min(cos_nh, 1.f), m.shininess) * std::min(relative_strength, 1.f);
  return toon_soft_step(lobe, 1.f - m.specular_size, m.softness);
}

float toon_rim_coverage(const ToonMaterial& m, float facing) {
  if (!m.rim) return 0.f;
  const float f = 1.f - glm::clamp(facing, 0.f, 1.f);
  const float outer = m.rim_threshold + m.rim_width;
  const float inside = toon_soft_step(f, m.rim_threshold, m.softness);
  // An outer edge at or past the silhouette (f = 1) would only clip the rim's last sliver.
  return outer >= 1.f ? inside : inside * (1.f - toon_soft_step(f, outer, m.softness));
}

}  // namespace inkray
