#include "core/image/image_io.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <system_error>
#include <unistd.h>

namespace inkray {
namespace {

std::filesystem::path temporary_beside(const std::filesystem::path& file) {
  std::random_device rd;
  char suffix[32];
  std::snprintf(suffix, sizeof(suffix), ".tmp-%08x", rd());
  return file.string() + suffix;
}

// Writes bytes to a temporary file, flushes it to disk and renames it over `file`.
bool write_atomically(const std::filesystem::path& file, const void* data, size_t size, std::string* error) {
  const auto tmp = temporary_beside(file);
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) {
    *error = file.string() + ": cannot write (" + std::strerror(errno) + ")";
    return false;
  }
  const bool ok = std::fwrite(data, 1, size, f) == size && std::fflush(f) == 0 && fsync(fileno(f)) == 0;
  std::fclose(f);
  std::error_code ec;
  if (ok) std::filesystem::rename(tmp, file, ec);
  if (!ok || ec) {
    std::filesystem::remove(tmp, ec);
    *error = file.string() + ": write failed" + (ec ? " (" + ec.message() + ")" : "");
    return false;
  }
  return true;
}

bool write_png(const std::filesystem::path& file, const RgbImage& image, std::string* error) {
  const std::vector<uint8_t> rgb = encode_srgb8(image);
  std::vector<uint8_t> bytes;
  auto append = [](void* ctx, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(ctx);
    out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
  };
  if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 3, rgb.data(), image.width * 3)) {
    *error = file.string() + ": PNG encoding failed";
    return false;
  }
  return write_atomically(file, bytes.data(), bytes.size(), error);
}

bool write_pfm(const std::filesystem::path& file, const RgbImage& image, std::string* error) {
  // PFM rows run bottom to top; a negative scale means little-endian.
  std::string header = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  std::vector<char> bytes(header.begin(), header.end());
  for (int y = image.height - 1; y >= 0; --y) {
    const char* row = reinterpret_cast<const char*>(&image.at(0, y));
    bytes.insert(bytes.end(), row, row + sizeof(Color) * size_t(image.width));
  }
  return write_atomically(file, bytes.data(), bytes.size(), error);
}

bool write_exr(const std::filesystem::path& file, const RgbImage& image, std::string* error) {
  const auto tmp = temporary_beside(file);
  const char* err = nullptr;
  const int rc = SaveEXR(reinterpret_cast<const float*>(image.pixels.data()), image.width, image.height, 3,
                         /*save_as_fp16=*/0, tmp.c_str(), &err);
  std::error_code ec;
  if (rc != TINYEXR_SUCCESS) {
    *error = file.string() + ": EXR write failed" + (err ? std::string(" (") + err + ")" : "");
    if (err) FreeEXRErrorMessage(err);
    std::filesystem::remove(tmp, ec);
    return false;
  }
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    *error = file.string() + ": cannot write (" + ec.message() + ")";
    std::filesystem::remove(tmp, ec);
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
  const float scale = std::exp2(exposure_stops);
  std::vector<uint8_t> out(image.pixels.size() * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      out[3 * i + c] = uint8_t(std::lround(255.f * linear_to_srgb(scale * image.pixels[i][c])));
  return out;
}

bool write_image(const std::filesystem::path& file, const RgbImage& image, std::string* error) {
  switch (image_format_of(file)) {
    case ImageFormat::png: return write_png(file, image, error);
    case ImageFormat::pfm: return write_pfm(file, image, error);
    case ImageFormat::exr: return write_exr(file, image, error);
    case ImageFormat::unknown: break;
  }
  *error = file.string() + ": unknown image format (expected .png, .pfm or .exr)";
  return false;
}

bool read_image(const std::filesystem::path& file, bool srgb, RgbImage* image, std::string* error) {
  int w = 0, h = 0, channels = 0;
  const std::string name = file.string();
  auto fail = [&] {
    *error = name + ": cannot read image (" + stbi_failure_reason() + ")";
    return false;
  };
  image->pixels.clear();
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

bool read_pfm(const std::filesystem::path& file, RgbImage* image, std::string* error) {
  std::ifstream in(file, std::ios::binary);
  std::string magic;
  int w = 0, h = 0;
  float scale = 0.f;
  if (!(in >> magic >> w >> h >> scale) || magic != "PF" || w <= 0 || h <= 0 || w > 65536 || h > 65536 ||
      scale >= 0.f) {
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
