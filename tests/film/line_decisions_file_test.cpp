// Line decision files (core/film/line_decisions_file.h): what is written is read back
// bit for bit, and every damaged or foreign file is one error line naming the file
// and what was expected.
#include "core/film/line_decisions_file.h"
#include "core/film/partial_merge.h"
#include "core/io/content_hash.h"

#include "tests/support/file_helpers.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

namespace inkray {
namespace {

using testing::ScratchFolder;

LineDecisions some_decisions() {
  LineDecisions d;
  d.width = 5;
  d.height = 3;
  d.decided_at = 17;
  const LineKind kinds[] = {LineKind::quiet, LineKind::beside, LineKind::solid, LineKind::edge};
  for (int i = 0; i < 15; ++i) {
    d.rays.push_back(uint32_t(i * 7919 + (i == 4 ? 0x80000000u : 0u)));
    d.kinds.push_back(kinds[i % 4]);
  }
  return d;
}

PartialInfo some_render() {
  PartialInfo info;
  info.width = 5;
  info.height = 3;
  info.window = {0, 0, 5, 3};
  info.frame = 12.5f;
  info.seed = 42;
  info.lines = true;
  info.scene = "{\n  \"format\": \"inkray-scene\"\n}\n";
  return info;
}

void write(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

TEST(LineDecisionsFile, RoundTripKeepsEveryPixel) {
  ScratchFolder dir;
  const LineDecisions d = some_decisions();
  write(dir / "d.bin", encode_line_decisions(d, some_render()));
  PartialInfo info;
  LineDecisions back;
  std::string error;
  ASSERT_TRUE(read_line_decisions(dir / "d.bin", &info, &back, &error)) << error;
  EXPECT_EQ(back, d);
  EXPECT_EQ(info.frame, 12.5f);
  EXPECT_EQ(info.seed, 42);
  EXPECT_EQ(info.scene, some_render().scene);
  EXPECT_EQ(partial_mismatch(info, some_render()), "");
  EXPECT_EQ(info.end_pass, 17u);

  // A scene without lines keeps no pixels.
  LineDecisions none;
  none.width = 5, none.height = 3;
  write(dir / "none.bin", encode_line_decisions(none, some_render()));
  ASSERT_TRUE(read_line_decisions(dir / "none.bin", &info, &back, &error)) << error;
  EXPECT_EQ(back, none);
}

// A file with valid checksums around `header` and `pixels`: damage the checksums would
// catch first is not what these cases test.
std::string sealed(const std::string& header, const std::string& pixels = "") {
  return "inkray-line-decisions 2\nchecksums " + hash_hex(content_hash(header)) + " " +
         hash_hex(content_hash(pixels)) + "\n" + header + "\n" + pixels;
}

TEST(LineDecisionsFile, DamagedOrForeignFilesAreOneErrorNamingTheFile) {
  ScratchFolder dir;
  const std::string good = encode_line_decisions(some_decisions(), some_render());
  const size_t second = good.find('\n') + 1, third = good.find('\n', second) + 1;
  const size_t pixels_at = good.find('\n', third) + 1;
  const std::string header = good.substr(third, pixels_at - third - 1);
  const std::string pixels = good.substr(pixels_at);
  const auto with_kind = [&](char kind) {
    std::string p = pixels;
    p[p.size() - 1] = kind;
    return sealed(header, p);
  };
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const std::string deep_scene =
      "{\"width\":5,\"height\":3,\"frame\":1,\"seed\":0,\"decided_at\":1,\"scene\":\"" +
      std::string(100000, '[') + "\",\"assets\":[],\"content\":\"0\"}";
  struct Case {
    const char* name;
    std::string bytes;
    const char* expected;
  };
  const std::vector<Case> cases = {
      {"empty", "", "not a line decision file"},
      {"png", "\x89PNG\r\n\x1a\n", "not a line decision file"},
      {"newer", "inkray-line-decisions 3\n{}\n", "this inkray reads version 2 only"},
      {"older", "inkray-line-decisions 1\n{}\n", "decide the lines again"},
      {"no checksums", "inkray-line-decisions 2\n{}\n", "checksums line is damaged"},
      {"no header", "inkray-line-decisions 2\nchecksums 0000000000000000 0000000000000000\n{\"width\": 5",
       "header line is damaged or missing"},
      {"header flipped", good.substr(0, third + 3) + char(good[third + 3] ^ 4) + good.substr(third + 4),
       "header line is damaged (it does not match its checksum)"},
      {"checksum flipped",
       good.substr(0, second + 12) + char(good[second + 12] ^ 1) + good.substr(second + 13), "damaged"},
      {"pixel flipped",
       good.substr(0, good.size() - 20) + char(good[good.size() - 20] ^ 0x10) + good.substr(good.size() - 19),
       "pixels are damaged"},
      {"truncated", good.substr(0, good.size() - 3), "pixels are damaged or truncated"},
      {"longer", good + "x", "pixels are damaged or truncated"},
      {"deep header", sealed(deep), "nests deeper than 3 levels"},
      {"deep scene", sealed(deep_scene), "the scene nests deeper than 256 levels"},
      {"not json", sealed("{width}"), "not a JSON object"},
      {"no width", sealed("{\"height\":3}"), "header: width is missing"},
      {"text width", sealed("{\"width\":\"5\"}"), "header: width is not an integer"},
      {"huge",
       sealed("{\"width\":100000,\"height\":3,\"frame\":1,\"seed\":0,\"decided_at\":1,"
              "\"scene\":\"\",\"assets\":[],\"content\":\"0\"}"),
       "out of range"},
      {"content",
       sealed("{\"width\":5,\"height\":3,\"frame\":1,\"seed\":0,\"decided_at\":1,"
              "\"scene\":\"{}\",\"assets\":[],\"content\":\"0000000000000000\"}"),
       "content is not the hash"},
      {"pixels lost", sealed(header, "abc"), "expected 75"},
      {"kind 9", with_kind(9), "pixel (4,2) has kind 9"},
      {"finding", with_kind(char(LineKind::finding)), "expected a decided one"},
  };
  for (const Case& c : cases) {
    const auto file = dir / (std::string(c.name) + ".bin");
    write(file, c.bytes);
    PartialInfo info;
    LineDecisions d;
    std::string error;
    EXPECT_FALSE(read_line_decisions(file, &info, &d, &error)) << c.name;
    EXPECT_EQ(error.rfind(file.string() + ": ", 0), 0u) << c.name << ": " << error;
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.name << ": " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << c.name << ": " << error;
  }
  PartialInfo info;
  LineDecisions d;
  std::string error;
  EXPECT_FALSE(read_line_decisions(dir / "absent.bin", &info, &d, &error));
  EXPECT_NE(error.find("no such file"), std::string::npos) << error;
}

// Every bit of a file is covered: flipping any one byte's bit is refused, never read
// as other decisions.
TEST(LineDecisionsFile, EveryBitFlipIsRefused) {
  const std::string good = encode_line_decisions(some_decisions(), some_render());
  for (size_t i = 0; i < good.size(); ++i) {
    std::string bad = good;
    bad[i] = char(bad[i] ^ (1 << (i % 8)));
    PartialInfo info;
    LineDecisions d;
    std::string error;
    EXPECT_FALSE(read_line_decisions_bytes(bad, "d.bin", &info, &d, &error)) << "byte " << i;
    EXPECT_EQ(error.rfind("d.bin: ", 0), 0u) << error;
  }
}

// The assets' hashes travel with the decisions: one whose mesh changed is another render's.
TEST(LineDecisionsFile, AssetsAreKeptAndCompared) {
  PartialInfo render = some_render();
  render.assets = {{"meshes/bunny.obj", hash_hex(content_hash("v 0 0 0"))}, {"textures/a.png", "missing"}};
  PartialInfo info;
  LineDecisions back;
  std::string error;
  ASSERT_TRUE(read_line_decisions_bytes(encode_line_decisions(some_decisions(), render), "d.bin", &info,
                                        &back, &error))
      << error;
  EXPECT_EQ(info.assets, render.assets);
  EXPECT_EQ(partial_mismatch(info, render), "");
  render.assets[0].digest = hash_hex(content_hash("v 0 0 1"));
  EXPECT_NE(partial_mismatch(info, render).find("the asset meshes/bunny.obj changed"), std::string::npos)
      << partial_mismatch(info, render);
}

}  // namespace
}  // namespace inkray
