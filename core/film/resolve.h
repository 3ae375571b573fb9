// The film's final image: mean radiance, then the painterly pixel filter, then
// the outline colours composited over it. Colour, opacity and filter settings
// are read here, not while tracing, so editing them needs no re-render.
//
// Lines are composited in the display's space: a line colour is a display colour
// (display-linear, as DisplayMapping gives), so black lines stay black, a grey of
// 0.5 shows as that grey at any exposure, and a half-covered pixel over a light
// brighter than white is half line colour rather than clipped white. The pixel is
// stored mapped back through the display's inverse, so showing or encoding the
// image with that display gives exactly the composite. The raw view has no curve,
// so there it is the linear mix of radiance and the line colour over 2^exposure:
// at 0 EV, plain linear compositing.
#pragma once

#include "core/base/cancel.h"
#include "core/base/parallel.h"
#include "core/film/film.h"
#include "core/image/view_transform.h"
#include "core/world/chain.h"
#include "core/world/render_scene.h"

namespace inkray {

// The image without lines: mean radiance through the painterly filter. The filter's
// rows run within `pool`'s threads when given, else in the caller's arena; the
// result is the same either way. When `cancel` cuts the filter short, the result
// is an empty image.
RgbImage resolve_base(const Film& film, const ResolveSettings& settings, ThreadBudget* pool = nullptr,
                      const Cancel& cancel = {});
// The same over a mean-radiance image of the film other than its own mean (the
// denoiser's, core/film/denoise.h); `full_height` scales the filter as the film's height does.
RgbImage resolve_base(RgbImage radiance, const ResolveSettings& settings, int full_height,
                      ThreadBudget* pool = nullptr, const Cancel& cancel = {});
// Whether resolve_base gives one film the same image under both settings, so a
// cached one serves (only line settings changed).
bool same_base(const ResolveSettings& a, const ResolveSettings& b);
// The pixels of a film that have lines, with their mean line samples (a few
// percent of the image), and, when the settings have line sets, the lines as
// chains: gathered once per state of the film, so compositing again for another
// display, line colour, opacity or style touches only them.
struct FilmLines {
  int width = 0, height = 0;      // the film's
  std::vector<uint32_t> pixels;   // row-major indices into the film's image
  std::vector<LineSample> means;  // Film::line_mean of each
  bool chained = false;           // `chains` were built, with these material paths
  std::vector<uint8_t> chained_paths;
  std::vector<Chain> chains;
  // Whether these lines serve `settings` as they are: chains where it has line sets.
  bool serve(const ResolveSettings& settings) const {
    return settings.sets.empty() || (chained && chained_paths == settings.material_paths);
  }
};
FilmLines gather_lines(const Film& film, const ResolveSettings& settings);
// The chains line sets draw on an image `width` pixels wide: the film's, and the
// view's hidden lines scaled from the full image to it.
std::vector<Chain> chains_to_draw(const std::vector<Chain>& film_chains, const ResolveSettings& settings,
                                  int width);
// Composites the lines for `display` over `image` (resolve_base of their film) in
// place: pixel by pixel in each type's colour, or as the line sets' strokes where
// there are sets (core/npr/lines/line_strokes.h). Pixels without lines are left as
// they are, and an image of another size is not touched. A new exposure or view transform composites again
// over a copy of a cached base.
void composite_lines(const FilmLines& lines, const ResolveSettings& settings, const DisplayEncoding& display,
                     RgbImage& image);

// resolve_base, then composite_lines for the display the image will be shown or
// encoded with: the editor's viewport passes its own; a PNG file is exposure 0 with
// the standard view (encode_srgb8), the default. The settings may differ from those
// the film was rendered with: that is how a line colour or filter edit shows without
// a re-render. Empty when `cancel` cut the painterly filter short.
RgbImage resolve_final(const Film& film, const ResolveSettings& settings, const DisplayEncoding& display = {},
                       ThreadBudget* pool = nullptr, const Cancel& cancel = {});
// resolve_final with `radiance` in place of the film's mean: the lines still come from the film.
RgbImage resolve_final(const Film& film, RgbImage radiance, const ResolveSettings& settings,
                       const DisplayEncoding& display = {}, ThreadBudget* pool = nullptr,
                       const Cancel& cancel = {});
// Seconds the painterly filter will take on a width x height image, timed on a
// 64 x 64 crop and scaled by the pixel count; 0 without a filter. A final render
// with a time limit stops early enough to leave it this time.
double estimate_painterly_seconds(const ResolveSettings& settings, int width, int height,
                                  ThreadBudget* pool = nullptr);

inline RgbImage resolve_final(const Film& film, const RenderScene& scene, const DisplayEncoding& display = {},
                              ThreadBudget* pool = nullptr, const Cancel& cancel = {}) {
  return resolve_final(film, scene.resolve, display, pool, cancel);
}

}  // namespace inkray
