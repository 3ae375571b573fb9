#include "core/film/resolve.h"

#include "core/npr/painterly_filter.h"

namespace inkray {
namespace {

// The filter radius is given for a 1080-line image, so the look holds at any resolution.
RgbImage apply_painterly(RgbImage image, const RenderSettings& settings, ThreadPool* pool) {
  if (settings.painterly == PainterlyFilter::none) return image;
  PainterlyFilterParams params;
  params.radius = settings.painterly_radius * float(image.height) / 1080.f;
  params.sharpness = settings.painterly_sharpness;
  return settings.painterly == PainterlyFilter::kuwahara ? kuwahara_filter(image, params, pool)
                                                         : anisotropic_kuwahara_filter(image, params, pool);
}

// Line colours go over the filtered image, so the filter never smears them.
void composite_lines(const Film& film, const OutlineDesc& outlines, RgbImage& image) {
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) {
      const LineSample m = film.line_mean(x, y);
      if (m.weight <= 0.f) continue;
      // Objects that override the line colour own that share of the pixel's lines.
      const float override_share = std::clamp(m.override_weight / m.weight, 0.f, 1.f);
      const Color override_color = m.override_weight > 0.f ? m.override_color / m.override_weight : Color(0.f);
      Color& c = image.at(x, y);
      for (int t = 0; t < kLineTypeCount; ++t) {
        const LineStyleDesc& style = line_style(outlines, LineType(t));
        const float alpha = style.opacity * line_opacity(m.coverage[size_t(t)]);
        if (alpha <= 0.f) continue;
        const Color line = glm::mix(style.color, override_color, override_share);
        c = glm::mix(c, line, alpha);
      }
    }
  }
}

}  // namespace

RgbImage resolve_final(const Film& film, const RenderSettings& settings, const OutlineDesc& outlines,
                       ThreadPool* pool) {
  RgbImage image = apply_painterly(film.resolve(), settings, pool);
  if (film.has_lines()) composite_lines(film, outlines, image);
  return image;
}

}  // namespace inkray
