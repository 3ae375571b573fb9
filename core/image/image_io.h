// Image files. Writing: PNG (8-bit sRGB), PFM and EXR (linear float), chosen by
// the file extension, encoded to bytes and then replaced atomically (core/io), so a
// failed or interrupted write never leaves a half-written image. Reading: textures
// through stb_image, and PFM.
#pragma once

#include "core/image/rgb_image.h"

#include <filesystem>
#include <string>
#include <vector>

namespace inkray {

enum class ImageFormat { png, pfm, exr, unknown };
ImageFormat image_format_of(const std::filesystem::path& file);

float linear_to_srgb(float linear);
float srgb_to_linear(float encoded);
// 8-bit sRGB of the standard view (view_transform.h) at an exposure in stops.
std::vector<uint8_t> encode_srgb8(const RgbImage& image, float exposure_stops = 0.f);

// The bytes of the file write_image would write, for callers that stage several outputs
// (core/io/output_set.h) before replacing any. False with *error naming the file.
bool encode_image(const std::filesystem::path& file, const RgbImage& image, std::string* bytes,
                  std::string* error);
// Writes by extension: .png gets sRGB encoding, .pfm and .exr stay linear. The write
// is atomic and follows a symbolic link to replace the file it names.
// On failure returns false and sets *error to a line naming the file and the cause.
bool write_image(const std::filesystem::path& file, const RgbImage& image, std::string* error);
// Reads a PFM written by write_image (used by tests and benchmark caches).
bool read_pfm(const std::filesystem::path& file, RgbImage* image, std::string* error);
// Reads the colour of an OpenEXR file (as written by write_image), for viewing exports.
bool read_exr(const std::filesystem::path& file, RgbImage* image, std::string* error);
// Reads PNG/JPEG/TGA/BMP/HDR to linear RGB; 8-bit images are decoded from sRGB
// when srgb is true. Returns false and sets *error naming the file on failure.
bool read_image(const std::filesystem::path& file, bool srgb, RgbImage* image, std::string* error);
// The alpha channel of an 8-bit image with one (grey+alpha or RGBA), in [0, 1], rows as
// read_image's; empty for an image without alpha (and for HDR files, which have none).
bool read_image_alpha(const std::filesystem::path& file, std::vector<float>* alpha, std::string* error);

}  // namespace inkray
