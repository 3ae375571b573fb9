// Encoding a render's image and AOVs one at a time (only one encoded file is held in
// memory) into a single output set.
#include "core/render/render_outputs.h"

#include "core/film/aov_display.h"
#include "core/film/resolve.h"
#include "core/image/image_io.h"
#include "core/io/output_set.h"

namespace inkray {

OutputsWritten write_render_outputs(RenderSession& session, const std::filesystem::path& image,
                                    const std::vector<AovFile>& aovs, std::string* error, const Cancel& cancel) {
  constexpr OutputsWritten kFailed = OutputsWritten::failed;
  OutputSet outputs;
  std::string bytes;
  // Lines are composited for the display a PNG is encoded with (exposure 0, standard
  // view); a linear file holds the same pixels, so viewing it that way shows them too.
  const RgbImage final_image =
      resolve_final(session.film(), session.scene(), kFileDisplay, &session.pool(), cancel);
  if (final_image.pixels.empty()) {
    *error = image.string() + ": cancelled while applying the painterly filter; nothing was written";
    return OutputsWritten::cancelled;
  }
  if (!encode_image(image, final_image, &bytes, error) || !outputs.stage(image, bytes, error)) return kFailed;
  for (const AovFile& a : aovs) {
    RgbImage img = session.film().resolve_aov(a.aov);
    if (image_format_of(a.file) == ImageFormat::png) img = aov_for_display(a.aov, img);
    if (!encode_image(a.file, img, &bytes, error) || !outputs.stage(a.file, bytes, error)) return kFailed;
  }
  return outputs.commit(error) ? OutputsWritten::all : kFailed;
}

}  // namespace inkray
