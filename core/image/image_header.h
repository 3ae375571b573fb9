// Image sizes read from a file's header before a pixel is decoded, and the largest
// image inkray decodes: a valid 1 MB PNG can claim 18000 x 18000 pixels, which would
// take gigabytes and minutes to decode, so the size is checked first.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace inkray {

// Per image: 8192 x 8192 texels, 768 MiB as linear float RGB (textures, toon ramps).
inline constexpr long long kMaxImageTexels = 8192LL * 8192LL;
// Either side on its own; a 65536 x 1 strip is no harm, a 100000-wide one is a mistake.
inline constexpr int kMaxImageSide = 32768;

// No format inkray reads packs more pixels into a byte than a 1-bit PNG at deflate's
// best ratio (8 pixels a byte, 1032:1): a header claiming more than that many pixels
// per byte of file (beyond a small allowance) is a lie that would cost a huge decode.
inline constexpr long long kMaxTexelsPerFileByte = 8 * 1032;
inline constexpr long long kFreeTexels = 1 << 16;

struct ImageSize {
  int width = 0, height = 0;
  long long texels() const { return static_cast<long long>(width) * height; }
};

// The size stb_image would decode to, from the header alone; nullopt with *error
// naming the file when it is unreadable, not an image, not safe to hand to stb_image
// (image_guard.h), or larger than the limits. Every read of an image starts here.
std::optional<ImageSize> read_image_size(const std::filesystem::path& file, std::string* error);

}  // namespace inkray
