// The files of a finished render: the image and its AOVs, encoded by extension and
// committed together (core/io/output_set.h), so a failed AOV leaves no image behind.
// inkray-render and the editor's export both write through here.
#pragma once

#include "core/base/cancel.h"
#include "core/film/film.h"
#include "core/film/film_partial.h"
#include "core/image/view_transform.h"
#include "core/render/render_session.h"

#include <filesystem>
#include <string>
#include <vector>

namespace inkray {

struct AovFile {
  Aov aov;
  std::filesystem::path file;  // .png gets the AOV's display mapping, .pfm and .exr raw values
};

enum class OutputsWritten { all, failed, cancelled };

// The lines as vector files (core/npr/lines/vector_lines.h), staged with the image:
// the line sets' strokes, or without sets each outline type's lines in its colour.
struct LineFiles {
  std::filesystem::path svg, pdf;  // empty: not written
  bool svg_image = false;          // the image under the lines in the SVG
  bool any() const { return !svg.empty() || !pdf.empty(); }
};

// The display a written image is meant for: PNG files are encoded with it
// (encode_srgb8), and lines are composited for it in every format
// (core/film/resolve.h), so an EXR or PFM shown this way matches the PNG.
inline constexpr DisplayEncoding kFileDisplay{0.f, ViewTransform::standard};

// Where a denoised render puts the image as rendered: "<stem>_raw<ext>" beside it.
std::filesystem::path raw_image_path(const std::filesystem::path& image);

// Stages every file, then renames them all in. On `failed`, *error names the file
// that failed and no target has been touched. `cancel` stops the painterly filter
// (seconds at a large radius): `cancelled`, and nothing is written. `crop`, when
// not empty, writes only those pixels of the image and the AOVs (a crop window
// rendered alone: the painterly filter sees nothing outside it). `denoised`, when given,
// is the film's mean radiance denoised (core/film/denoise.h): the image is resolved from
// it, and the film's own mean, resolved the same way, goes to raw_image_path(image).
OutputsWritten write_render_outputs(RenderSession& session, const std::filesystem::path& image,
                                    const std::vector<AovFile>& aovs, std::string* error,
                                    const Cancel& cancel = {}, const PixelWindow& crop = {},
                                    const RgbImage* denoised = nullptr, const LineFiles& lines = {});
// The same for a film without its session (inkray-merge), resolved with these
// compiled settings exactly as a session's film would be.
OutputsWritten write_film_outputs(const Film& film, const ResolveSettings& settings,
                                  const std::filesystem::path& image, const std::vector<AovFile>& aovs,
                                  std::string* error, ThreadBudget* pool = nullptr, const Cancel& cancel = {},
                                  const PixelWindow& crop = {}, const RgbImage* denoised = nullptr,
                                  const LineFiles& lines = {});
// A partial file (film_partial.h) of info.window of `film`, replaced atomically.
bool write_partial_file(const Film& film, const PartialInfo& info, const std::filesystem::path& file,
                        std::string* error);

}  // namespace inkray
