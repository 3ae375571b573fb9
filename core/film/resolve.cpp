// The final image, and what its painterly filter will cost.
#include "core/film/resolve.h"

#include "core/film/film_chains.h"
#include "core/npr/lines/stroke_raster.h"
#include "core/npr/painterly_filter.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace inkray {
namespace {

// The filter radius is given for a 1080-line image, so the look holds at any
// resolution: `full_height` is the image's, or the full image's for a crop.
RgbImage apply_painterly(RgbImage image, const ResolveSettings& settings, ThreadBudget* pool,
                         const Cancel& cancel, int full_height) {
  if (settings.painterly == PainterlyFilter::none) return image;
  PainterlyFilterParams params;
  params.radius = settings.painterly_radius * float(full_height) / 1080.f;
  params.sharpness = settings.painterly_sharpness;
  return settings.painterly == PainterlyFilter::kuwahara
             ? kuwahara_filter(image, params, pool, cancel)
             : anisotropic_kuwahara_filter(image, params, pool, cancel);
}

}  // namespace

RgbImage resolve_base(const Film& film, const ResolveSettings& settings, ThreadBudget* pool,
                      const Cancel& cancel) {
  return apply_painterly(film.resolve(), settings, pool, cancel, film.height());
}

RgbImage resolve_base(RgbImage radiance, const ResolveSettings& settings, int full_height, ThreadBudget* pool,
                      const Cancel& cancel) {
  return apply_painterly(std::move(radiance), settings, pool, cancel, full_height);
}

bool same_base(const ResolveSettings& a, const ResolveSettings& b) {
  if (a.painterly != b.painterly) return false;
  return a.painterly == PainterlyFilter::none ||
         (a.painterly_radius == b.painterly_radius && a.painterly_sharpness == b.painterly_sharpness);
}

FilmLines gather_lines(const Film& film, const ResolveSettings& settings) {
  FilmLines lines;
  lines.width = film.width(), lines.height = film.height();
  if (!film.has_lines()) return lines;
  if (!settings.sets.empty()) {
    lines.chains = film_chains(film, settings.material_paths);
    lines.chained = true;
    lines.chained_paths = settings.material_paths;
  }
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) {
      const LineSample m = film.line_mean(x, y);
      if (!(m.weight > 0.f)) continue;
      lines.pixels.push_back(uint32_t(y) * uint32_t(film.width()) + uint32_t(x));
      lines.means.push_back(m);
    }
  }
  return lines;
}

std::vector<Chain> chains_to_draw(const std::vector<Chain>& film_chains, const ResolveSettings& settings,
                                  int width) {
  std::vector<Chain> chains = film_chains;
  if (!settings.hidden || settings.hidden_width <= 0) return chains;
  // A preview film is a fraction of the full image: its hidden lines are that much smaller.
  const float scale = float(width) / float(settings.hidden_width);
  for (Chain c : *settings.hidden) {
    for (ChainPoint& q : c.points) q.p *= scale, q.curvature /= scale;
    chains.push_back(std::move(c));
  }
  return chains;
}

// Line colours go over the filtered image, so the filter never smears them.
void composite_lines(const FilmLines& lines, const ResolveSettings& settings, const DisplayEncoding& display,
                     RgbImage& image) {
  if (image.width != lines.width || image.height != lines.height) return;
  if (!settings.sets.empty()) {
    if (lines.chained)
      draw_strokes(
          stroke_chains(chains_to_draw(lines.chains, settings, image.width), settings.sets, image.height),
          display, image);
    return;
  }
  const DisplayMapping mapping(display);
  for (size_t i = 0; i < lines.pixels.size(); ++i) {
    const LineSample& m = lines.means[i];
    // Objects that override the line colour own that share of the pixel's lines.
    const float override_share = std::clamp(m.override_weight / m.weight, 0.f, 1.f);
    const Color override_color = m.override_weight > 0.f ? m.override_color / m.override_weight : Color(0.f);
    Color& c = image.pixels[lines.pixels[i]];
    Color shown(0.f);
    bool drawn = false;
    for (int t = 0; t < kLineTypeCount; ++t) {
      const LineLook& style = settings.lines[size_t(t)];
      const float alpha = style.opacity * line_opacity(m.coverage[size_t(t)]);
      if (alpha <= 0.f) continue;
      if (!drawn) shown = mapping.to_display(c), drawn = true;
      const Color line = glm::mix(style.color, override_color, override_share);
      shown = glm::mix(shown, line, alpha);
    }
    if (drawn) c = mapping.from_display(shown);
  }
}

RgbImage resolve_final(const Film& film, const ResolveSettings& settings, const DisplayEncoding& display,
                       ThreadBudget* pool, const Cancel& cancel) {
  RgbImage image = resolve_base(film, settings, pool, cancel);
  if (!image.pixels.empty())
    composite_lines(gather_lines(film, settings), settings, display, image);  // else cut short
  return image;
}

RgbImage resolve_final(const Film& film, RgbImage radiance, const ResolveSettings& settings,
                       const DisplayEncoding& display, ThreadBudget* pool, const Cancel& cancel) {
  RgbImage image = resolve_base(std::move(radiance), settings, film.height(), pool, cancel);
  if (!image.pixels.empty()) composite_lines(gather_lines(film, settings), settings, display, image);
  return image;
}

double estimate_painterly_seconds(const ResolveSettings& settings, int width, int height,
                                  ThreadBudget* pool) {
  if (settings.painterly == PainterlyFilter::none || width <= 0 || height <= 0) return 0.0;
  // A crop with edges in both directions, so the anisotropic filter's ellipses take
  // every shape; a pixel's cost depends on the radius, hardly on the picture.
  const int w = std::min(width, 64), h = std::min(height, 64);
  RgbImage crop{w, h, std::vector<Color>(size_t(w) * size_t(h))};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) crop.at(x, y) = Color(float((x / 8 + y / 8) % 2), float(x) / float(w), 0.5f);
  const auto start = std::chrono::steady_clock::now();
  apply_painterly(std::move(crop), settings, pool, Cancel{}, height);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return seconds * (double(width) * double(height)) / (double(w) * double(h));
}

}  // namespace inkray
