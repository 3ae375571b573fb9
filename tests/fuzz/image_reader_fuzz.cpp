// Fuzz harness for the image readers (stb_image through read_image, and read_pfm).
// Both take a path, so each input goes through one temporary file per process.
#include "core/image/image_io.h"
#include "tests/fuzz/fuzz_targets.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

namespace inkray {
namespace {

// Removed at exit, so a fuzzing run leaves nothing in /tmp behind.
struct TemporaryFile {
  std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("inkray_fuzz_image_" + std::to_string(::getpid()) + ".bin");
  ~TemporaryFile() {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
};

void check_image(const RgbImage& image, const std::string& reader) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != std::size_t(image.width) * std::size_t(image.height)) {
    fuzz_fail(reader + " returned a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
              " image with " + std::to_string(image.pixels.size()) + " pixels");
  }
}

}  // namespace

int fuzz_image_reader(const std::uint8_t* data, std::size_t size) {
  static const TemporaryFile file;
  std::FILE* out = std::fopen(file.path.c_str(), "wb");
  if (!out) fuzz_fail("cannot write " + file.path.string());
  const bool written = std::fwrite(data, 1, size, out) == size;
  if (std::fclose(out) != 0 || !written) fuzz_fail("cannot write " + file.path.string());

  RgbImage image;
  std::string error;
  if (read_image(file.path, /*srgb=*/true, &image, &error)) {
    check_image(image, "read_image");
  } else if (error.empty()) {
    fuzz_fail("read_image failed without an error message");
  }
  RgbImage pfm;
  error.clear();
  if (read_pfm(file.path, &pfm, &error)) {
    check_image(pfm, "read_pfm");
  } else if (error.empty()) {
    fuzz_fail("read_pfm failed without an error message");
  }
  return 0;
}

}  // namespace inkray
