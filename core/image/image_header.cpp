// Reads image headers through stb_image's info functions, which decode no pixels.
#include "core/image/image_header.h"

#include "core/image/image_guard.h"

#include <stb_image.h>

namespace inkray {

std::optional<ImageSize> read_image_size(const std::filesystem::path& file, std::string* error) {
  // stb_image's own header parsers are not safe on every file (image_guard.h).
  if (!image_safe_to_decode(file, error)) return std::nullopt;
  ImageSize size;
  int channels = 0;
  if (!stbi_info(file.c_str(), &size.width, &size.height, &channels)) {
    const char* reason = stbi_failure_reason();
    *error = file.string() + ": cannot read image (" + (reason ? reason : "unknown format") + ")";
    return std::nullopt;
  }
  if (size.width <= 0 || size.height <= 0 || size.width > kMaxImageSide || size.height > kMaxImageSide ||
      size.texels() > kMaxImageTexels) {
    *error = file.string() + ": the image is " + std::to_string(size.width) + " x " +
             std::to_string(size.height) +
             " pixels; inkray reads images of at most 8192 x 8192 pixels (67 Mpixels) and " +
             std::to_string(kMaxImageSide) + " on a side";
    return std::nullopt;
  }
  std::error_code ec;
  const auto bytes = static_cast<long long>(std::filesystem::file_size(file, ec));
  if (!ec && size.texels() > kFreeTexels + bytes * kMaxTexelsPerFileByte) {
    *error = file.string() + ": the image claims " + std::to_string(size.width) + " x " +
             std::to_string(size.height) + " pixels but the file has only " + std::to_string(bytes) +
             " bytes: no format inkray reads packs that many pixels into so few bytes";
    return std::nullopt;
  }
  return size;
}

}  // namespace inkray
