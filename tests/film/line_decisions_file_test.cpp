// Line decision files (core/film/line_decisions_file.h): what is written is read back
// bit for bit, and every damaged or foreign file is one error line naming the file
// and what was expected.
#include "core/film/line_decisions_file.h"
#include "core/film/partial_merge.h"

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

TEST(LineDecisionsFile, DamagedOrForeignFilesAreOneErrorNamingTheFile) {
  ScratchFolder dir;
  const std::string good = encode_line_decisions(some_decisions(), some_render());
  const size_t header_end = good.find('\n', good.find('\n') + 1) + 1;
  const std::string header = good.substr(0, header_end);
  const auto with_kind = [&](char kind) {
    std::string s = good;
    s[s.size() - 1] = kind;
    return s;
  };
  struct Case {
    const char* name;
    std::string bytes;
    const char* expected;
  };
  const std::vector<Case> cases = {
      {"empty", "", "not a line decision file"},
      {"png", "\x89PNG\r\n\x1a\n", "not a line decision file"},
      {"newer", "inkray-line-decisions 2\n{}\n", "this inkray reads version 1"},
      {"no header", "inkray-line-decisions 1\n{\"width\": 5", "no header line"},
      {"not json", "inkray-line-decisions 1\n{width}\n", "not a JSON object"},
      {"no width", "inkray-line-decisions 1\n{\"height\":3}\n", "header: width is missing"},
      {"text width", "inkray-line-decisions 1\n{\"width\":\"5\"}\n", "header: width is not an integer"},
      {"huge", "inkray-line-decisions 1\n{\"width\":100000,\"height\":3,\"frame\":1,\"seed\":0,\"decided_at\":1,"
               "\"scene\":\"\"}\n",
       "out of range"},
      {"truncated", good.substr(0, good.size() - 3), "expected 75"},
      {"longer", good + "x", "expected 75"},
      {"pixels lost", header + "abc", "expected 75"},
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
  EXPECT_NE(error.find("cannot open"), std::string::npos) << error;
}

}  // namespace
}  // namespace inkray
