// Damaged partials and checkpoints (film_partial.h, partial_seal.h): any flipped bit is
// refused naming the file and the part it hit, a non-finite sum or a scene nested
// beyond any scene's depth is refused without a crash, and only regular files are read.
#include "core/film/film_partial.h"
#include "core/film/partial_merge.h"
#include "core/film/partial_seal.h"
#include "core/io/file_bytes.h"

#include "tests/support/file_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <sys/stat.h>

namespace inkray {
namespace {

using testing::ScratchFolder;

// A checkpoint of a small render with lines and AOVs, cut mid-pass.
std::unique_ptr<Film> small_film(int w, int h) {
  AovSet aovs;
  aovs.add(Aov::depth);
  aovs.add(Aov::object_id);
  auto film = std::make_unique<Film>(w, h, aovs, true);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (uint32_t pass = 0; pass < 2; ++pass) {
        film->add_sample(x, y, pass, Color(float(x) / 3.f, float(y) + 0.1f, float(pass) * 1e-3f));
        film->add_first_hit(x, y, {.depth = float(x + y) / 7.f, .object = x % 3});
        film->add_lines(x, y, {.coverage = {0.f, float(x) / 9.f}, .weight = 0.5f, .rays = 2.f});
      }
  return film;
}

PartialInfo small_info(int w, int h) {
  return {.width = w,
          .height = h,
          .window = {0, 0, w, h},
          .first_pass = 0,
          .end_pass = 2,
          .tiles_done = {1},
          .seed = 3,
          .scene = R"({"format": "inkray-scene", "render": {"spp": 4}})",
          .assets = {{"meshes/m.obj", "0123456789abcdef"}}};
}

std::string encoded(const Film& film, const PartialInfo& info) {
  std::string bytes, error;
  EXPECT_TRUE(encode_partial(film, info, &bytes, &error)) << error;
  return bytes;
}

// Every byte of the file, with one bit flipped in turn: each is refused with one line
// naming the file, and the message says which part: the header (up to its end), or the
// pixel data; with the header intact and the pixels decodable, the channel.
TEST(PartialDamage, EveryBitFlipIsRefusedNamingThePart) {
  const auto film = small_film(6, 5);
  const std::string good = encoded(*film, small_info(6, 5));
  std::vector<RawAttribute> raw;
  size_t header_end = 0;
  std::string error;
  ASSERT_TRUE(walk_exr_header(good, &raw, &header_end, &error)) << error;
  PartialInfo info;
  std::unique_ptr<Film> back;
  ASSERT_TRUE(read_partial_bytes(good, "p.exr", &info, &back, &error)) << error;
  size_t named_channels = 0;
  for (size_t i = 0; i < good.size(); ++i) {
    std::string bad = good;
    bad[i] = char(bad[i] ^ (1 << (i % 8)));
    error.clear();
    // With and without the pixels (every 16th byte: the same checks, half the time): a
    // header-only read checks the whole file too.
    for (const bool pixels : i % 16 == 0 ? std::vector<bool>{false, true} : std::vector<bool>{true}) {
      std::unique_ptr<Film> out;
      ASSERT_FALSE(read_partial_bytes(bad, "p.exr", &info, pixels ? &out : nullptr, &error)) << "byte " << i;
      ASSERT_EQ(error.rfind("p.exr: ", 0), 0u) << error;
      ASSERT_EQ(error.find('\n'), std::string::npos) << error;
    }
    if (i >= header_end) {
      EXPECT_NE(error.find("pixel data is damaged"), std::string::npos) << "byte " << i << ": " << error;
      named_channels += error.find("channel ") != std::string::npos;
    }
  }
  // The pixels are stored uncompressed at this size: most flips land in one channel.
  EXPECT_GT(named_channels, (good.size() - header_end) / 2);
}

TEST(PartialDamage, DamagedPartsAreNamed) {
  const auto film = small_film(6, 5);
  const std::string good = encoded(*film, small_info(6, 5));
  PartialInfo info;
  std::unique_ptr<Film> back;
  std::string error;
  std::string bad = good;
  const size_t scene = bad.find("inkray-scene");
  ASSERT_NE(scene, std::string::npos);
  bad[scene] = 'X';
  EXPECT_FALSE(read_partial_bytes(bad, "p.exr", &info, &back, &error));
  EXPECT_NE(error.find("p.exr: its header is damaged (its bytes do not match inkray.headerChecksum)"),
            std::string::npos)
      << error;
  bad = good;
  bad[bad.size() - 1] = char(bad[bad.size() - 1] ^ 0x40);  // the last pixel's last channel
  EXPECT_FALSE(read_partial_bytes(bad, "p.exr", &info, &back, &error));
  EXPECT_NE(error.find("p.exr: its pixel data is damaged: channel "), std::string::npos) << error;
  EXPECT_FALSE(read_partial_bytes(good.substr(0, good.size() - 1), "p.exr", &info, &back, &error));
  EXPECT_NE(error.find("p.exr: its pixel data is damaged"), std::string::npos) << error;
  EXPECT_FALSE(read_partial_bytes(good + '\0', "p.exr", &info, &back, &error));
  EXPECT_NE(error.find("p.exr: its pixel data is damaged"), std::string::npos) << error;
}

// A film never holds Inf or NaN sums; a file that does (written by something else, and
// sealed) is refused, naming the channel and pixel, instead of spreading them in a merge.
TEST(PartialDamage, NonFiniteSumsAreRefused) {
  for (const double bad :
       {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    auto film = small_film(6, 5);
    FilmPixel p;
    p.lines.weight = bad;
    film->add_pixel(4, 3, p);
    const std::string bytes = encoded(*film, small_info(6, 5));
    PartialInfo info;
    std::unique_ptr<Film> back;
    std::string error;
    EXPECT_FALSE(read_partial_bytes(bytes, "p.exr", &info, &back, &error));
    EXPECT_EQ(error, "p.exr: channel lines.weight holds a non-finite value at pixel (4,3)");
  }
  // Finite, but more than 2^32 samples of the largest float: two such halves would add to Inf.
  auto film = small_film(6, 5);
  FilmPixel p;
  p.sum[0].x = 1e300;
  film->add_pixel(1, 2, p);
  PartialInfo info;
  std::unique_ptr<Film> back;
  std::string error;
  EXPECT_FALSE(read_partial_bytes(encoded(*film, small_info(6, 5)), "p.exr", &info, &back, &error));
  EXPECT_EQ(error, "p.exr: channel radiance.even.R holds a value larger than any film sums at pixel (1,2)");
}

// 100,000 nested brackets as the scene: refused before any JSON parser or comparison
// recurses into them.
TEST(PartialDamage, DeeplyNestedSceneIsRefusedWithoutCrashing) {
  const auto film = small_film(4, 4);
  PartialInfo info = small_info(4, 4);
  info.scene = std::string(100000, '[') + std::string(100000, ']');
  const std::string bytes = encoded(*film, info);
  PartialInfo read;
  std::unique_ptr<Film> back;
  std::string error;
  EXPECT_FALSE(read_partial_bytes(bytes, "deep.exr", &read, &back, &error));
  EXPECT_EQ(
      error,
      "deep.exr: attribute inkray.scene nests deeper than 256 levels (expected a scene as inkray writes it)");
  info.scene = std::string(300, '{') + std::string(300, '}');  // also counts objects
  EXPECT_FALSE(read_partial_bytes(encoded(*film, info), "deep.exr", &read, &back, &error));
  EXPECT_NE(error.find("nests deeper than 256 levels"), std::string::npos) << error;
  info.scene = "{\"a\": \"" + std::string(1000, '[') + "\"}";  // brackets in a string do not nest
  EXPECT_TRUE(read_partial_bytes(encoded(*film, info), "string.exr", &read, &back, &error)) << error;
}

TEST(PartialDamage, OnlyRegularFilesAreRead) {
  ScratchFolder dir;
  PartialInfo info;
  std::unique_ptr<Film> film;
  std::string error;
  EXPECT_FALSE(read_partial(dir.path(), &info, &film, &error));
  EXPECT_EQ(error, dir.path().string() + ": not a regular file (a directory), expected a file inkray wrote");
  // A FIFO is refused by its type, before it is opened (opening it would wait for a writer).
  const auto fifo = dir / "fifo.exr";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_FALSE(check_regular_file(fifo, &error));
  EXPECT_EQ(error, fifo.string() + ": not a regular file (a FIFO), expected a file inkray wrote");
  EXPECT_FALSE(check_regular_file("/dev/zero", &error));
  EXPECT_EQ(error, "/dev/zero: not a regular file (a character device), expected a file inkray wrote");
  EXPECT_FALSE(read_partial("/dev/zero", &info, &film, &error));
  EXPECT_NE(error.find("a character device"), std::string::npos) << error;
  std::string bytes;
  EXPECT_FALSE(read_file_bytes(dir / "absent.exr", 100, &bytes, &error));
  EXPECT_EQ(error, (dir / "absent.exr").string() + ": no such file");
  // The size is checked before a byte is read.
  std::ofstream(dir / "big.bin") << std::string(101, 'x');
  EXPECT_FALSE(read_file_bytes(dir / "big.bin", 100, &bytes, &error));
  EXPECT_NE(error.find("is 101 bytes, more than the 100"), std::string::npos) << error;
  ASSERT_TRUE(read_file_bytes(dir / "big.bin", 101, &bytes, &error)) << error;
  EXPECT_EQ(bytes.size(), 101u);
}

// Written as a checkpoint, read back as one: every header field and sum to the bit.
TEST(PartialDamage, IntactCheckpointReadsBackIdentically) {
  const auto film = small_film(6, 5);
  const PartialInfo info = small_info(6, 5);
  PartialInfo read;
  std::unique_ptr<Film> back;
  std::string error;
  ASSERT_TRUE(read_partial_bytes(encoded(*film, info), "c.exr", &read, &back, &error)) << error;
  EXPECT_EQ(read.tiles_done, info.tiles_done);
  EXPECT_EQ(read.assets, info.assets);
  PartialInfo held = info;  // the AOVs and lines are the film's
  held.aovs = film->aovs().first_hit();
  held.lines = true;
  EXPECT_EQ(partial_mismatch(read, held), "");
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 6; ++x) {
      EXPECT_EQ(back->pixel(x, y).sum, film->pixel(x, y).sum);
      EXPECT_EQ(back->pixel(x, y).lines.coverage, film->pixel(x, y).lines.coverage);
    }
}

}  // namespace
}  // namespace inkray
