// Image files: PNG, PFM and EXR writing, atomic replacement, reading back.
#include "core/image/image_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>

namespace inkray {
namespace {

TEST(ImageIo, PfmRoundTripAndAtomicWrite) {
  const auto dir = std::filesystem::temp_directory_path() / "inkray_image_io_test";
  std::filesystem::create_directories(dir);
  RgbImage img{3, 2, {Color(0.f), Color(1.f, 2.f, 3.f), Color(-1.f), Color(1e6f), Color(0.25f), Color(7.f)}};
  std::string error;
  ASSERT_TRUE(write_image(dir / "a.pfm", img, &error)) << error;
  RgbImage back;
  ASSERT_TRUE(read_pfm(dir / "a.pfm", &back, &error)) << error;
  EXPECT_EQ(back.pixels, img.pixels);
  ASSERT_TRUE(write_image(dir / "a.png", img, &error)) << error;
  ASSERT_TRUE(write_image(dir / "a.exr", img, &error)) << error;
  EXPECT_GT(std::filesystem::file_size(dir / "a.exr"), 0u);
  // Nothing but the three images: no temporary files left behind.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 3);
  EXPECT_FALSE(write_image(dir / "missing" / "a.png", img, &error));
  EXPECT_NE(error.find("missing/a.png"), std::string::npos);
  EXPECT_FALSE(write_image(dir / "a.bmp", img, &error));
  EXPECT_NE(error.find("expected .png, .pfm or .exr"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(ImageIo, SrgbEncoding) {
  EXPECT_EQ(linear_to_srgb(0.f), 0.f);
  EXPECT_EQ(linear_to_srgb(1.f), 1.f);
  EXPECT_NEAR(linear_to_srgb(0.5f), 0.7354f, 1e-4f);
  EXPECT_EQ(linear_to_srgb(std::numeric_limits<float>::quiet_NaN()), 0.f);
  for (float c : {0.001f, 0.2f, 0.5f, 0.9f}) EXPECT_NEAR(srgb_to_linear(linear_to_srgb(c)), c, 1e-6f);
}

TEST(ImageIo, PngReadsBackAsLinear) {
  const auto file = std::filesystem::temp_directory_path() / "inkray_image_io_png.png";
  RgbImage img{2, 1, {Color(0.5f, 0.f, 1.f), Color(0.2f)}};
  std::string error;
  ASSERT_TRUE(write_image(file, img, &error)) << error;
  RgbImage back;
  ASSERT_TRUE(read_image(file, true, &back, &error)) << error;
  ASSERT_EQ(back.width, 2);
  // 8-bit quantisation: within half a code value after decoding.
  for (int x = 0; x < 2; ++x)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(back.at(x, 0)[c], img.at(x, 0)[c], 0.004f);
  EXPECT_FALSE(read_image(file.string() + ".missing", true, &back, &error));
  EXPECT_NE(error.find(".missing"), std::string::npos);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace inkray
