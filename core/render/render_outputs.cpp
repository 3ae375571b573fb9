// Encoding a render's image and AOVs one at a time (only one encoded file is held in
// memory) into a single output set.
#include "core/render/render_outputs.h"

#include "core/film/aov_display.h"
#include "core/film/film_chains.h"
#include "core/film/resolve.h"
#include "core/image/image_io.h"
#include "core/io/atomic_file.h"
#include "core/io/output_set.h"
#include "core/npr/lines/line_strokes.h"
#include "core/npr/lines/vector_lines.h"

namespace inkray {
namespace {

// The window's pixels of an image of the whole film (the image itself without a window).
RgbImage crop_image(RgbImage image, const PixelWindow& crop) {
  if (crop.empty()) return image;
  RgbImage out{crop.width(), crop.height(), std::vector<Color>(size_t(crop.width()) * size_t(crop.height()))};
  for (int y = 0; y < crop.height(); ++y)
    for (int x = 0; x < crop.width(); ++x)
      out.pixels[size_t(y) * size_t(crop.width()) + size_t(x)] = image.at(crop.x0 + x, crop.y0 + y);
  return out;
}

// The film's lines as vector files: its chains drawn by the line sets, or by the
// outline types' plain sets (ResolveSettings::plain_sets) where there are none.
bool stage_line_files(const Film& film, const ResolveSettings& settings, const RgbImage& image,
                      const LineFiles& files, OutputSet& outputs, std::string* error) {
  const std::vector<LineSet>& sets = settings.sets.empty() ? settings.plain_sets : settings.sets;
  const std::vector<LineStroke> strokes =
      stroke_chains(chains_to_draw(film_chains(film, settings.material_paths), settings, film.width()), sets,
                    film.height());
  std::string bytes;
  if (!files.svg.empty()) {
    if (!encode_lines_svg(film.width(), film.height(), strokes, sets, files.svg_image ? &image : nullptr,
                          &bytes, error)) {
      *error = files.svg.string() + ": " + *error;
      return false;
    }
    if (!outputs.stage(files.svg, bytes, error)) return false;
  }
  if (!files.pdf.empty()) {
    if (!encode_lines_pdf(film.width(), film.height(), strokes, nullptr, &bytes, error)) {
      *error = files.pdf.string() + ": " + *error;
      return false;
    }
    if (!outputs.stage(files.pdf, bytes, error)) return false;
  }
  return true;
}

}  // namespace

std::filesystem::path raw_image_path(const std::filesystem::path& image) {
  std::filesystem::path p = image;
  p.replace_filename(image.stem().string() + "_raw" + image.extension().string());
  return p;
}

OutputsWritten write_film_outputs(const Film& film, const ResolveSettings& settings,
                                  const std::filesystem::path& image, const std::vector<AovFile>& aovs,
                                  std::string* error, ThreadBudget* pool, const Cancel& cancel,
                                  const PixelWindow& crop, const RgbImage* denoised, const LineFiles& lines) {
  constexpr OutputsWritten kFailed = OutputsWritten::failed;
  OutputSet outputs;
  std::string bytes;
  const auto cancelled = [&] {
    *error = image.string() + ": cancelled while applying the painterly filter; nothing was written";
    return OutputsWritten::cancelled;
  };
  // Lines are composited for the display a PNG is encoded with (exposure 0, standard
  // view); a linear file holds the same pixels, so viewing it that way shows them too.
  RgbImage final_image = resolve_final(film, settings, kFileDisplay, pool, cancel);
  if (final_image.pixels.empty()) return cancelled();
  if (denoised) {
    const std::filesystem::path raw = raw_image_path(image);
    if (!encode_image(raw, crop_image(std::move(final_image), crop), &bytes, error) ||
        !outputs.stage(raw, bytes, error))
      return kFailed;
    final_image = resolve_final(film, *denoised, settings, kFileDisplay, pool, cancel);
    if (final_image.pixels.empty()) return cancelled();
  }
  if (lines.any() && !stage_line_files(film, settings, final_image, lines, outputs, error)) return kFailed;
  if (!encode_image(image, crop_image(std::move(final_image), crop), &bytes, error) ||
      !outputs.stage(image, bytes, error))
    return kFailed;
  for (const AovFile& a : aovs) {
    RgbImage img = crop_image(film.resolve_aov(a.aov), crop);
    if (image_format_of(a.file) == ImageFormat::png) img = aov_for_display(a.aov, img);
    if (!encode_image(a.file, img, &bytes, error) || !outputs.stage(a.file, bytes, error)) return kFailed;
  }
  return outputs.commit(error) ? OutputsWritten::all : kFailed;
}

OutputsWritten write_render_outputs(RenderSession& session, const std::filesystem::path& image,
                                    const std::vector<AovFile>& aovs, std::string* error,
                                    const Cancel& cancel, const PixelWindow& crop, const RgbImage* denoised,
                                    const LineFiles& lines) {
  return write_film_outputs(session.film(), session.scene().resolve, image, aovs, error, &session.pool(),
                            cancel, crop, denoised, lines);
}

bool write_partial_file(const Film& film, const PartialInfo& info, const std::filesystem::path& file,
                        std::string* error) {
  std::string bytes;
  if (!encode_partial(film, info, &bytes, error)) {
    *error = file.string() + ": " + *error;
    return false;
  }
  return write_file_atomically(file, bytes, error);
}

}  // namespace inkray
