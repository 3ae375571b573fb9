// Image files: encoding PNG, PFM and EXR to bytes (written through core/io's atomic
// replacement) and reading textures and PFM back.
#include "core/image/image_io.h"

#include "core/image/exr_memory.h"
#include "core/image/image_header.h"
#include "core/image/view_transform.h"
#include "core/io/atomic_file.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace inkray {
namespace {

bool encode_png(const std::filesystem::path& file, const RgbImage& image, std::string* bytes,
                std::string* error) {
  const std::vector<uint8_t> rgb = encode_srgb8(image);
  auto append = [](void* ctx, void* data, int size) {
    static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), size_t(size));
  };
  if (!stbi_write_png_to_func(append, bytes, image.width, image.height, 3, rgb.data(), image.width * 3)) {
    *error = file.string() + ": PNG encoding failed";
    return false;
  }
  return true;
}

void encode_pfm(const RgbImage& image, std::string* bytes) {
  // PFM rows run bottom to top; a negative scale means little-endian.
  *bytes = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  for (int y = image.height - 1; y >= 0; --y) {
    const char* row = reinterpret_cast<const char*>(&image.at(0, y));
    bytes->append(row, sizeof(Color) * size_t(image.width));
  }
}

// What tinyexr's SaveEXR writes (32-bit float B, G, R planes; ZIP unless tiny), but to
// memory, so the file goes through the same flushed, atomic write as PNG and PFM.
bool encode_exr(const std::filesystem::path& file, const RgbImage& image, std::string* bytes,
                std::string* error) {
  const size_t n = image.pixels.size();
  std::vector<float> planes[3];
  for (int c = 0; c < 3; ++c) {
    planes[c].resize(n);
    for (size_t i = 0; i < n; ++i) planes[c][i] = image.pixels[i][c];
  }
  std::string reason;
  if (!encode_exr_planes(image.width, image.height,
                         {{"B", kExrFloat, planes[2].data()},
                          {"G", kExrFloat, planes[1].data()},
                          {"R", kExrFloat, planes[0].data()}},
                         {},
                         image.width < 16 && image.height < 16 ? ExrCompression::none : ExrCompression::zip,
                         bytes, &reason)) {
    *error = file.string() + ": EXR encoding failed" + (reason.empty() ? "" : " (" + reason + ")");
    return false;
  }
  return true;
}

}  // namespace

ImageFormat image_format_of(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".png") return ImageFormat::png;
  if (ext == ".pfm") return ImageFormat::pfm;
  if (ext == ".exr") return ImageFormat::exr;
  return ImageFormat::unknown;
}

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

float linear_to_srgb(float c) {
  if (!(c > 0.f)) return 0.f;
  if (c >= 1.f) return 1.f;
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.f / 2.4f) - 0.055f;
}

std::vector<uint8_t> encode_srgb8(const RgbImage& image, float exposure_stops) {
  const DisplayMapping display(DisplayEncoding{exposure_stops, ViewTransform::standard});
  std::vector<uint8_t> out(image.pixels.size() * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      out[3 * i + c] = uint8_t(std::lround(255.f * linear_to_srgb(display.to_display(image.pixels[i][c]))));
  return out;
}

bool encode_image(const std::filesystem::path& file, const RgbImage& image, std::string* bytes,
                  std::string* error) {
  bytes->clear();
  switch (image_format_of(file)) {
    case ImageFormat::png:
      return encode_png(file, image, bytes, error);
    case ImageFormat::pfm:
      encode_pfm(image, bytes);
      return true;
    case ImageFormat::exr:
      return encode_exr(file, image, bytes, error);
    case ImageFormat::unknown:
      break;
  }
  *error = file.string() + ": unknown image format (expected .png, .pfm or .exr)";
  return false;
}

bool write_image(const std::filesystem::path& file, const RgbImage& image, std::string* error) {
  std::string bytes;
  return encode_image(file, image, &bytes, error) && write_file_atomically(file, bytes, error);
}

bool read_image(const std::filesystem::path& file, bool srgb, RgbImage* image, std::string* error) {
  int w = 0, h = 0, channels = 0;
  const std::string name = file.string();
  auto fail = [&] {
    *error = name + ": cannot read image (" + stbi_failure_reason() + ")";
    return false;
  };
  image->pixels.clear();
  if (!read_image_size(file, error)) return false;  // before decoding: the header may ask for gigabytes
  if (stbi_is_hdr(name.c_str())) {
    float* data = stbi_loadf(name.c_str(), &w, &h, &channels, 3);
    if (!data) return fail();
    image->pixels.resize(size_t(w) * size_t(h));
    for (size_t i = 0; i < image->pixels.size(); ++i)
      image->pixels[i] = {data[3 * i], data[3 * i + 1], data[3 * i + 2]};
    stbi_image_free(data);
  } else {
    unsigned char* data = stbi_load(name.c_str(), &w, &h, &channels, 3);
    if (!data) return fail();
    float lut[256];
    for (int i = 0; i < 256; ++i) lut[i] = srgb ? srgb_to_linear(float(i) / 255.f) : float(i) / 255.f;
    image->pixels.resize(size_t(w) * size_t(h));
    for (size_t i = 0; i < image->pixels.size(); ++i)
      image->pixels[i] = {lut[data[3 * i]], lut[data[3 * i + 1]], lut[data[3 * i + 2]]};
    stbi_image_free(data);
  }
  image->width = w;
  image->height = h;
  return true;
}

bool read_image_alpha(const std::filesystem::path& file, std::vector<float>* alpha, std::string* error) {
  const std::string name = file.string();
  alpha->clear();
  if (!read_image_size(file, error)) return false;
  int w = 0, h = 0, channels = 0;
  if (stbi_is_hdr(name.c_str())) return true;  // HDR formats carry no alpha
  if (!stbi_info(name.c_str(), &w, &h, &channels)) {
    *error = name + ": cannot read image (" + stbi_failure_reason() + ")";
    return false;
  }
  if (channels != 2 && channels != 4) return true;
  unsigned char* data = stbi_load(name.c_str(), &w, &h, &channels, 4);
  if (!data) {
    *error = name + ": cannot read image (" + stbi_failure_reason() + ")";
    return false;
  }
  alpha->resize(size_t(w) * size_t(h));
  for (size_t i = 0; i < alpha->size(); ++i) (*alpha)[i] = float(data[4 * i + 3]) / 255.f;
  stbi_image_free(data);
  return true;
}

bool read_exr(const std::filesystem::path& file, RgbImage* image, std::string* error) {
  float* rgba = nullptr;
  int w = 0, h = 0;
  const char* err = nullptr;
  if (LoadEXR(&rgba, &w, &h, file.string().c_str(), &err) != TINYEXR_SUCCESS) {
    *error = file.string() + ": " + (err ? err : "not a readable EXR file");
    if (err) FreeEXRErrorMessage(err);
    return false;
  }
  image->width = w;
  image->height = h;
  image->pixels.resize(size_t(w) * size_t(h));
  for (size_t i = 0; i < image->pixels.size(); ++i)
    image->pixels[i] = Color(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]);
  std::free(rgba);
  return true;
}

bool read_pfm(const std::filesystem::path& file, RgbImage* image, std::string* error) {
  std::ifstream in(file, std::ios::binary);
  std::string magic;
  int w = 0, h = 0;
  float scale = 0.f;
  if (!(in >> magic >> w >> h >> scale) || magic != "PF" || w <= 0 || h <= 0 || w > kMaxImageSide ||
      h > kMaxImageSide || ImageSize{w, h}.texels() > kMaxImageTexels || scale >= 0.f) {
    *error = file.string() + ": not a little-endian RGB PFM file";
    return false;
  }
  in.get();  // the single whitespace byte after the header
  image->width = w;
  image->height = h;
  image->pixels.assign(size_t(w) * size_t(h), Color(0.f));
  for (int y = h - 1; y >= 0; --y)
    in.read(reinterpret_cast<char*>(&image->at(0, y)), std::streamsize(sizeof(Color) * size_t(w)));
  if (!in) {
    *error = file.string() + ": truncated PFM data";
    return false;
  }
  return true;
}

}  // namespace inkray
