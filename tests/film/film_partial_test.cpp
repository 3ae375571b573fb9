// Partial files: the film's raw state round-trips to the bit, every file that is
// not a whole partial is one clear error naming it (never a crash), and merging
// refuses what would not add up to one render.
#include "core/film/film_partial.h"
#include "core/document/scene_hash.h"
#include "core/film/partial_merge.h"
#include "core/film/partial_seal.h"
#include "core/image/exr_memory.h"
#include "core/image/image_io.h"
#include "core/io/atomic_file.h"
#include "tests/support/odd_film.h"

#include "tests/support/file_helpers.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

namespace inkray {
namespace {

namespace fs = std::filesystem;

class FilmPartial : public ::testing::Test {
 protected:
  testing::ScratchFolder scratch_;  // removed with the fixture
  const std::filesystem::path dir_ = scratch_.path();
};

using testing::every_first_hit_aov;
using testing::odd_film;

PartialInfo info_of(int w, int h, PixelWindow window, uint32_t first, uint32_t end) {
  PartialInfo info;
  info.width = w;
  info.height = h;
  info.window = window;
  info.first_pass = first;
  info.end_pass = end;
  info.frame = 2.5f;
  info.seed = 7;
  info.scene = R"({"format": "inkray-scene", "render": {"spp": 4, "max_depth": 8}})";
  return info;
}

bool write_partial(const Film& film, const PartialInfo& info, const fs::path& file, std::string* error) {
  std::string bytes;
  return encode_partial(film, info, &bytes, error) && write_file_atomically(file, bytes, error);
}

std::string read_error(const fs::path& file) {
  PartialInfo info;
  std::unique_ptr<Film> film;
  std::string error;
  EXPECT_FALSE(read_partial(file, &info, &film, &error)) << file;
  EXPECT_NE(error.find(file.string()), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  return error;
}

TEST_F(FilmPartial, RoundTripKeepsEveryBit) {
  const auto film = odd_film(7, 5);
  film->add_nonfinite(3);
  PartialInfo info = info_of(7, 5, {1, 1, 6, 4}, 3, 6);
  info.tiles_done = {1};
  std::string error;
  ASSERT_TRUE(write_partial(*film, info, dir_ / "p.exr", &error)) << error;

  PartialInfo read;
  std::unique_ptr<Film> back;
  ASSERT_TRUE(read_partial(dir_ / "p.exr", &read, &back, &error)) << error;
  EXPECT_EQ(read.width, 7);
  EXPECT_EQ(read.height, 5);
  EXPECT_EQ(read.window, (PixelWindow{1, 1, 6, 4}));
  EXPECT_EQ(read.first_pass, 3u);
  EXPECT_EQ(read.end_pass, 6u);
  EXPECT_EQ(read.frame, 2.5f);
  EXPECT_EQ(read.seed, 7);
  EXPECT_EQ(read.scene, info.scene);
  EXPECT_EQ(read.aovs.bits, every_first_hit_aov().bits);
  EXPECT_TRUE(read.lines);
  EXPECT_EQ(read.nonfinite, 3u);
  EXPECT_EQ(read.tiles_done, std::vector<uint8_t>{1});
  ASSERT_EQ(back->width(), 5);
  ASSERT_EQ(back->height(), 3);
  EXPECT_EQ(back->nonfinite_samples(), 3u);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) {
      const FilmPixel a = film->pixel(x + 1, y + 1), b = back->pixel(x, y);
      EXPECT_EQ(a.sum, b.sum);
      EXPECT_EQ(a.count, b.count);
      EXPECT_EQ(a.albedo_sum, b.albedo_sum);
      EXPECT_EQ(a.normal_sum, b.normal_sum);
      EXPECT_EQ(a.depth_sum, b.depth_sum);
      EXPECT_EQ(a.hit_count, b.hit_count);
      EXPECT_EQ(a.object_id, b.object_id);
      EXPECT_EQ(a.material_id, b.material_id);
      EXPECT_EQ(a.lines.coverage, b.lines.coverage);
      EXPECT_EQ(a.lines.weight, b.lines.weight);
      EXPECT_EQ(a.lines.override_color, b.lines.override_color);
      EXPECT_EQ(a.lines.rays, b.lines.rays);
      EXPECT_EQ(a.lines.hit_rays, b.lines.hit_rays);
      EXPECT_EQ(a.line_count, b.line_count);
    }
  // A viewer sees the mean radiance in R, G, B.
  RgbImage preview;
  ASSERT_TRUE(read_exr(dir_ / "p.exr", &preview, &error)) << error;
  EXPECT_EQ(preview.pixels[0], film->resolve().at(1, 1));
}

TEST_F(FilmPartial, AnythingElseIsOneErrorNamingTheFile) {
  std::ofstream(dir_ / "garbage.exr") << "this is not an image at all, not even close";
  EXPECT_NE(read_error(dir_ / "garbage.exr").find("not an OpenEXR file"), std::string::npos);
  std::ofstream(dir_ / "empty.exr").close();
  read_error(dir_ / "empty.exr");
  read_error(dir_ / "missing.exr");

  // An EXR image from elsewhere.
  std::string error;
  ASSERT_TRUE(write_image(dir_ / "image.exr", RgbImage{4, 4, std::vector<Color>(16, Color(0.5f))}, &error));
  EXPECT_NE(read_error(dir_ / "image.exr").find("not an inkray partial"), std::string::npos);

  // Cut anywhere: in the magic number, the header, the offsets, the pixels.
  const auto film = odd_film(24, 20);
  std::string bytes;
  ASSERT_TRUE(encode_partial(*film, info_of(24, 20, {0, 0, 24, 20}, 0, 3), &bytes, &error)) << error;
  for (const size_t keep : {size_t(3), size_t(40), bytes.size() / 4, bytes.size() / 2, bytes.size() - 9}) {
    const fs::path cut = dir_ / ("cut_" + std::to_string(keep) + ".exr");
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, keep);
    read_error(cut);
  }
}

// An EXR with these attributes and float channels; attribute values as raw bytes.
using Attributes = std::map<std::string, ExrAttribute>;

std::string le32(std::initializer_list<int> values) {
  std::string s;
  for (const int v : values)
    for (int b = 0; b < 4; ++b) s.push_back(char((uint32_t(v) >> (8 * b)) & 0xffu));
  return s;
}

Attributes good_attributes() {
  float frame = 1.f;
  uint32_t bits;
  std::memcpy(&bits, &frame, 4);
  return {{"inkray.format", {"string", "inkray-partial"}},
          {"inkray.version", {"int", le32({kPartialVersion})}},
          {"inkray.imageSize", {"v2i", le32({2, 2})}},
          {"inkray.window", {"box2i", le32({0, 0, 1, 1})}},
          {"inkray.samples", {"v2i", le32({0, 4})}},
          {"inkray.frame", {"float", le32({int(bits)})}},
          {"inkray.seed", {"int", le32({0})}},
          {"inkray.scene", {"string", "{}"}},
          {"inkray.aovs", {"string", ""}},
          {"inkray.lines", {"int", le32({0})}},
          {"inkray.nonfinite", {"string", "0"}},
          {"inkray.assets", {"string", "[]"}},
          {"inkray.contentHash", {"string", hash_hex(scene_content_hash("{}", {}))}},
          {"inkray.headerChecksum", {"string", std::string(kUnsealed)}},
          {"inkray.dataChecksum", {"string", std::string(kUnsealed)}}};
}

void write_exr(const fs::path& file, const Attributes& attributes, const std::vector<std::string>& channels) {
  const std::vector<float> zeros(4, 0.f);
  std::vector<ExrPlane> planes;
  for (const std::string& name : channels) planes.push_back({name.c_str(), kExrFloat, zeros.data()});
  std::string bytes, error;
  ASSERT_TRUE(encode_exr_planes(2, 2, planes, attributes, ExrCompression::none, &bytes, &error)) << error;
  // Sealed as the encoder seals a partial, so the reader looks past the checksums.
  ASSERT_TRUE(seal_partial(&bytes, &error)) << error;
  std::ofstream(file, std::ios::binary) << bytes;
}

TEST_F(FilmPartial, MistypedOrMissingPartsAreNamed) {
  Attributes a = good_attributes();
  a["inkray.seed"] = {"float", le32({0})};
  write_exr(dir_ / "seed.exr", a, {"R"});
  EXPECT_NE(read_error(dir_ / "seed.exr").find("attribute inkray.seed is of type float, expected int"),
            std::string::npos);

  a = good_attributes();
  a.erase("inkray.samples");
  write_exr(dir_ / "samples.exr", a, {"R"});
  EXPECT_NE(read_error(dir_ / "samples.exr").find("missing attribute inkray.samples"), std::string::npos);

  a = good_attributes();
  a["inkray.version"] = {"int", le32({kPartialVersion + 1})};
  write_exr(dir_ / "future.exr", a, {"R"});
  EXPECT_NE(read_error(dir_ / "future.exr").find("version " + std::to_string(kPartialVersion + 1)),
            std::string::npos);
  // An older partial has no checksums or assets' hashes to check: the render is redone.
  a = good_attributes();
  a["inkray.version"] = {"int", le32({kPartialVersion - 1})};
  write_exr(dir_ / "older.exr", a, {"R"});
  const std::string older = read_error(dir_ / "older.exr");
  EXPECT_NE(
      older.find("partial format version " + std::to_string(kPartialVersion - 1) +
                 "; this inkray reads version " + std::to_string(kPartialVersion) + " only: render it again"),
      std::string::npos)
      << older;

  a = good_attributes();
  a["inkray.contentHash"] = {"string", "0123456789abcdef"};
  write_exr(dir_ / "content.exr", a, {"R"});
  EXPECT_NE(read_error(dir_ / "content.exr").find("inkray.contentHash is not the hash"), std::string::npos);

  a = good_attributes();
  a["inkray.assets"] = {"string", "[[\"meshes/a.obj\", 7]]"};
  write_exr(dir_ / "assets.exr", a, {"R"});
  EXPECT_NE(read_error(dir_ / "assets.exr").find("attribute inkray.assets holds an entry"),
            std::string::npos);

  a = good_attributes();
  a["inkray.window"] = {"box2i", le32({0, 0, 4, 1})};
  write_exr(dir_ / "window.exr", a, {"R"});
  EXPECT_NE(read_error(dir_ / "window.exr").find("not inside the image"), std::string::npos);

  write_exr(dir_ / "channels.exr", good_attributes(), {"B", "G", "R"});
  EXPECT_NE(read_error(dir_ / "channels.exr").find("missing channel count.even"), std::string::npos);

  // Every channel there, but as floats: the sums' words must be unsigned.
  write_exr(dir_ / "types.exr", good_attributes(),
            {"B", "G", "R", "count.even", "count.odd", "radiance.even.B.hi", "radiance.even.B.lo",
             "radiance.even.G.hi", "radiance.even.G.lo", "radiance.even.R.hi", "radiance.even.R.lo",
             "radiance.odd.B.hi", "radiance.odd.B.lo", "radiance.odd.G.hi", "radiance.odd.G.lo",
             "radiance.odd.R.hi", "radiance.odd.R.lo"});
  EXPECT_NE(read_error(dir_ / "types.exr").find("channel count.even is not 32-bit unsigned"),
            std::string::npos);
}

TEST(PartialMismatch, NamesTheSettingThatDiffers) {
  const PartialInfo a = info_of(8, 8, {0, 0, 8, 8}, 0, 4);
  PartialInfo b = a;
  EXPECT_EQ(partial_mismatch(a, b), "");
  b.seed = 9;
  EXPECT_EQ(partial_mismatch(a, b), "seed 7 vs 9");
  b = a;
  b.frame = 3.f;
  EXPECT_EQ(partial_mismatch(a, b), "frame 2.5 vs 3");
  b = a;
  b.width = 16;
  EXPECT_EQ(partial_mismatch(a, b), "image size 8x8 vs 16x8");
  b = a;
  b.aovs.add(Aov::depth);
  EXPECT_EQ(partial_mismatch(a, b), "AOVs none vs depth");
  // How many samples each render was asked for does not matter; what it renders does.
  b = a;
  b.scene = R"({"format": "inkray-scene", "render": {"spp": 64, "max_depth": 8}})";
  EXPECT_EQ(partial_mismatch(a, b), "");
  b.scene = R"({"format": "inkray-scene", "render": {"spp": 64, "max_depth": 16}})";
  EXPECT_EQ(partial_mismatch(a, b), "the scene differs at render/max_depth: 8 vs 16");
  // The same scene text, but a mesh whose bytes changed between the renders.
  PartialInfo c = a, d = a;
  c.assets = {{"meshes/bunny.obj", "0123456789abcdef"}};
  d.assets = {{"meshes/bunny.obj", "fedcba9876543210"}};
  EXPECT_EQ(partial_mismatch(c, d),
            "the asset meshes/bunny.obj changed between them (its bytes hash 0123456789abcdef vs "
            "fedcba9876543210)");
  d.assets.clear();
  EXPECT_EQ(partial_mismatch(c, d), "the asset meshes/bunny.obj is read by one and not by the other");
  // Scenes nested beyond any scene's depth are compared without recursing into them.
  c = a;
  c.scene = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_EQ(partial_mismatch(a, c), "the scene is not JSON");
}

TEST_F(FilmPartial, MergeRefusesOverlapsGapsAndHoles) {
  const auto film = odd_film(8, 6);
  const PixelWindow whole{0, 0, 8, 6};
  std::string error;
  const auto write = [&](const std::string& name, PixelWindow w, uint32_t first, uint32_t end) {
    EXPECT_TRUE(write_partial(*film, info_of(8, 6, w, first, end), dir_ / name, &error)) << error;
    return dir_ / name;
  };
  const fs::path a = write("a.exr", whole, 0, 4), b = write("b.exr", whole, 2, 6),
                 c = write("c.exr", whole, 8, 12), left = write("left.exr", {0, 0, 4, 6}, 4, 8),
                 late = write("late.exr", whole, 4, 8);
  MergedFilm merged;
  ASSERT_TRUE(merge_partials({a, late}, true, &merged, &error)) << error;
  EXPECT_EQ(merged.min_samples, 8u);
  EXPECT_EQ(merged.info.end_pass, 8u);

  EXPECT_FALSE(merge_partials({a, b}, true, &merged, &error));
  EXPECT_NE(error.find("both hold samples 2-4"), std::string::npos) << error;
  EXPECT_NE(error.find("a.exr"), std::string::npos) << error;
  EXPECT_NE(error.find("b.exr"), std::string::npos) << error;
  EXPECT_FALSE(merge_partials({a, c}, true, &merged, &error));
  EXPECT_NE(error.find("no partial holds samples 4-8"), std::string::npos) << error;
  EXPECT_FALSE(merge_partials({a, left}, false, &merged, &error));
  EXPECT_NE(error.find("one window and one range"), std::string::npos) << error;
  EXPECT_FALSE(merge_partials({late}, true, &merged, &error));
  EXPECT_NE(error.find("no partial holds samples 0-4"), std::string::npos) << error;
  const fs::path top = write("top.exr", {0, 0, 8, 3}, 0, 4);
  EXPECT_FALSE(merge_partials({top}, true, &merged, &error));
  EXPECT_NE(error.find("24 pixels are in no partial"), std::string::npos) << error;
  // A partial again: one window, one range.
  ASSERT_TRUE(merge_partials({top}, false, &merged, &error)) << error;
  EXPECT_EQ(merged.info.window, (PixelWindow{0, 0, 8, 3}));

  PartialInfo other = info_of(8, 6, whole, 4, 8);
  other.seed = 1;
  ASSERT_TRUE(write_partial(*film, other, dir_ / "other.exr", &error)) << error;
  EXPECT_FALSE(merge_partials({a, dir_ / "other.exr"}, true, &merged, &error));
  EXPECT_NE(error.find("different renders: seed 7 vs 1"), std::string::npos) << error;
  EXPECT_NE(error.find("other.exr"), std::string::npos) << error;
}

}  // namespace
}  // namespace inkray
