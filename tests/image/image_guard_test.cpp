// Files that break stb_image (found by fuzzing) are refused before it sees them, with
// the file named; every format inkray documents still loads, in the forms stb writes.
#include "core/image/image_guard.h"
#include "core/image/image_io.h"

#include "tests/support/file_helpers.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <filesystem>
#include <string>
#include <vector>

namespace inkray {
namespace {

namespace fs = std::filesystem;

// Minimised by the image fuzzer (tests/fuzz); FuzzCorpus.ImageReader replays them too.
const fs::path kHostile = fs::path(INKRAY_SOURCE_DIR) / "tests" / "fuzz" / "crashes" / "image_reader";

// Each of these hangs stb_image, overflows its heap or its integers, or is UB in it.
TEST(ImageGuard, FilesThatBreakTheDecoderAreRefusedWithTheirName) {
  for (const char* name :
       {"stb_hdr_rle_zero_run_hang.hdr", "stb_jpeg_dht_overflow.jpg", "stb_jpeg_undefined_huffman_table.jpg",
        "stb_pgm16_heap_overread.pgm", "stb_pnm_header_int_overflow.ppm"}) {
    SCOPED_TRACE(name);
    RgbImage image;
    std::string error;
    EXPECT_FALSE(read_image(kHostile / name, true, &image, &error));
    EXPECT_NE(error.find(name), std::string::npos) << error;
    EXPECT_TRUE(image.pixels.empty());
  }
  std::string error;
  EXPECT_FALSE(image_safe_to_decode(kHostile / "stb_hdr_rle_zero_run_hang.hdr", &error));
  EXPECT_NE(error.find("an HDR scanline is cut short"), std::string::npos) << error;
  // The same with the zero run written out rather than implied by the end of the file.
  testing::ScratchFolder dir;
  testing::write_file(dir / "zero.hdr", std::string("#?RADIANCE\n\n-Y 1 +X 8\n\x02\x02\x00\x08\x00\x01", 28));
  EXPECT_FALSE(image_safe_to_decode(dir / "zero.hdr", &error));
  EXPECT_NE(error.find("an HDR scanline has a run of length 0"), std::string::npos) << error;
  // A scan using a Huffman table never defined: stb decodes with uninitialised memory,
  // and its assertions abort or not depending on what the heap held before.
  EXPECT_FALSE(image_safe_to_decode(kHostile / "stb_jpeg_undefined_huffman_table.jpg", &error));
  EXPECT_NE(error.find("a JPEG scan uses a Huffman table the file does not define"), std::string::npos)
      << error;
  EXPECT_FALSE(image_safe_to_decode(kHostile / "stb_pnm_header_int_overflow.ppm", &error));
  EXPECT_NE(error.find("not a PNG, JPEG, HDR, BMP or TGA image"), std::string::npos) << error;
  // A PNG whose IDAT is empty: stb copies from a null pointer (harmless in practice);
  // whatever it decides, the reader answers.
  RgbImage image;
  error.clear();
  if (!read_image(kHostile / "stb_png_empty_idat_null_memcpy.png", true, &image, &error)) {
    EXPECT_FALSE(error.empty());
  }
}

// 718 bytes of JPEG claiming 2568 x 20550 pixels: within the size limits, but a decode
// of 53 million pixels from nothing (a fuzzer's timeout).
TEST(ImageGuard, AHeaderClaimingFarMorePixelsThanItsFileCanHoldIsRefused) {
  const fs::path file = kHostile / "timeout-e692b4dccce9d2add09df3081eebb7ef1c1abeeb";
  RgbImage image;
  std::string error;
  EXPECT_FALSE(read_image(file, true, &image, &error));
  EXPECT_NE(error.find("claims 2568 x 20550 pixels but the file has only 718 bytes"), std::string::npos)
      << error;
  // A 1-bit PNG at deflate's best is the densest legitimate file; it stays readable.
  testing::ScratchFolder dir;
  const int side = 1024;
  std::vector<unsigned char> black(size_t(side) * side * 3, 0);
  ASSERT_TRUE(stbi_write_png((dir / "flat.png").c_str(), side, side, 3, black.data(), side * 3));
  EXPECT_TRUE(read_image(dir / "flat.png", true, &image, &error)) << error;
}

TEST(ImageGuard, EveryDocumentedFormatStillLoads) {
  testing::ScratchFolder dir;
  const int w = 40, h = 24;
  std::vector<unsigned char> rgb(size_t(w) * h * 3);
  std::vector<float> hdr(size_t(w) * h * 3);
  for (size_t i = 0; i < rgb.size(); ++i) {
    rgb[i] = static_cast<unsigned char>((i * 37) % 251);
    hdr[i] = float(i % 97) / 13.f;
  }
  ASSERT_TRUE(stbi_write_png((dir / "a.png").c_str(), w, h, 3, rgb.data(), w * 3));
  ASSERT_TRUE(stbi_write_jpg((dir / "a.jpg").c_str(), w, h, 3, rgb.data(), 90));
  ASSERT_TRUE(stbi_write_bmp((dir / "a.bmp").c_str(), w, h, 3, rgb.data()));
  ASSERT_TRUE(stbi_write_tga((dir / "a.tga").c_str(), w, h, 3, rgb.data()));
  ASSERT_TRUE(stbi_write_hdr((dir / "a.hdr").c_str(), w, h, 3, hdr.data()));  // run-length encoded
  for (const char* name : {"a.png", "a.jpg", "a.bmp", "a.tga", "a.hdr"}) {
    SCOPED_TRACE(name);
    RgbImage image;
    std::string error;
    ASSERT_TRUE(read_image(dir / name, true, &image, &error)) << error;
    EXPECT_EQ(image.width, w);
    EXPECT_EQ(image.height, h);
  }
  // JPEGs of the forms stb does not write: progressive (Huffman tables between scans,
  // each scan with one class of them) and 4:2:0 subsampled, both made by ImageMagick.
  for (const char* name : {"progressive.jpg", "baseline_420.jpg"}) {
    SCOPED_TRACE(name);
    RgbImage image;
    std::string error;
    ASSERT_TRUE(
        read_image(fs::path(INKRAY_SOURCE_DIR) / "tests" / "data" / "images" / name, true, &image, &error))
        << error;
    EXPECT_EQ(image.width, 24);
    EXPECT_EQ(image.height, 16);
  }
  // And the textures and brushes the project ships.
  for (const fs::path& folder : {fs::path(INKRAY_SOURCE_DIR) / "scenes" / "textures",
                                 fs::path(INKRAY_SOURCE_DIR) / "resources" / "brushes"}) {
    for (const auto& entry : fs::directory_iterator(folder)) {
      std::string error;
      EXPECT_TRUE(image_safe_to_decode(entry.path(), &error)) << error;
    }
  }
}

// A folder or a missing file is refused with its name, never an exception.
TEST(ImageGuard, FoldersAndMissingFilesAreRefusedWithAMessage) {
  testing::ScratchFolder dir;
  std::string error;
  EXPECT_FALSE(image_safe_to_decode(dir.path(), &error));
  EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
  RgbImage image;
  EXPECT_FALSE(read_image(dir.path(), true, &image, &error));
  EXPECT_FALSE(image_safe_to_decode(dir / "missing.png", &error));
  EXPECT_NE(error.find("file not found"), std::string::npos) << error;
}

}  // namespace
}  // namespace inkray
