// Writing images: PNG (8-bit sRGB), PFM and EXR (linear float), chosen by the
// file extension. Writes go to a temporary file renamed into place, so a
// failed or interrupted write never leaves a half-written image.
#pragma once

#include "core/math/types.h"

#include <filesystem>
#include <string>
#include <vector>

namespace inkray {

// Linear float RGB, row 0 at the top.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<Color> pixels;
  Color& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  const Color& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

enum class ImageFormat { png, pfm, exr, unknown };
ImageFormat image_format_of(const std::filesystem::path& file);

float linear_to_srgb(float linear);
// 8-bit sRGB, clamped, with exposure in stops applied first.
std::vector<uint8_t> encode_srgb8(const RgbImage& image, float exposure_stops = 0.f);

// Writes by extension: .png gets sRGB encoding, .pfm and .exr stay linear.
// On failure returns false and sets *error to a line naming the file.
bool write_image(const std::filesystem::path& file, const RgbImage& image, std::string* error);
// Reads a PFM written by write_image (used by tests and benchmark caches).
bool read_pfm(const std::filesystem::path& file, RgbImage* image, std::string* error);

}  // namespace inkray
