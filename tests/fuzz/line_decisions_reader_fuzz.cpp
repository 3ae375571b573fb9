// Fuzz harness for the line decision reader (line_decisions_file.h): files encoded
// in-process, damaged as the input says (file_edits_fuzz.h). Oracle: a damaged file is
// refused with one line naming it, or reads as exactly the undamaged one; a resealed
// file (checksums recomputed) is refused, or what it reads as writes back to a file that
// reads the same.
#include "core/film/line_decisions_file.h"
#include "core/io/content_hash.h"
#include "tests/fuzz/file_edits_fuzz.h"
#include "tests/fuzz/fuzz_targets.h"

#include <cstring>
#include <string>
#include <vector>

namespace inkray {
namespace {

struct Seed {
  PartialInfo info;
  LineDecisions decisions;
  std::string bytes;
};

Seed make_seed(int w, int h, bool pixels) {
  Seed s;
  LineDecisions& d = s.decisions;
  d.width = w;
  d.height = h;
  d.decided_at = 17;
  const LineKind kinds[] = {LineKind::quiet, LineKind::beside, LineKind::solid, LineKind::edge,
                            LineKind::probing};
  for (int i = 0; pixels && i < w * h; ++i) {
    d.rays.push_back(uint32_t(i * 7919 + (i == 4 ? 0x80000000u : 0u)));
    d.kinds.push_back(kinds[i % 5]);
  }
  const PartialInfo render{
      .width = w,
      .height = h,
      .window = {0, 0, w, h},
      .frame = 12.5f,
      .seed = 42,
      .scene = R"({"format": "inkray-scene", "render": {"spp": 4}, "outlines": {"enabled": true}})",
      .assets = {{"meshes/bunny.obj", "0123456789abcdef"}, {"brushes/dry.png", "missing"}}};
  s.bytes = encode_line_decisions(d, render);
  std::string error;
  if (!read_line_decisions_bytes(s.bytes, "seed.bin", &s.info, &s.decisions, &error))
    fuzz_fail("the seed does not read back: " + error);
  return s;
}

const std::vector<Seed>& seeds() {
  static const std::vector<Seed> s = {make_seed(5, 3, true), make_seed(4, 2, false), make_seed(16, 9, true)};
  return s;
}

// The checksums line recomputed for the header and pixels as they now are.
void reseal(std::string* bytes) {
  const size_t a = bytes->find('\n');
  if (a == std::string::npos) return;
  const size_t b = bytes->find('\n', a + 1);
  if (b == std::string::npos) return;
  const size_t c = bytes->find('\n', b + 1);
  if (c == std::string::npos) return;
  const std::string header = bytes->substr(b + 1, c - b - 1), pixels = bytes->substr(c + 1);
  *bytes = bytes->substr(0, a + 1) + "checksums " + hash_hex(content_hash(header)) + " " +
           hash_hex(content_hash(pixels)) + "\n" + header + "\n" + pixels;
}

std::string difference(const PartialInfo& a, const LineDecisions& da, const PartialInfo& b,
                       const LineDecisions& db) {
  if (a.width != b.width || a.height != b.height || a.window != b.window) return "size";
  if (std::memcmp(&a.frame, &b.frame, sizeof a.frame) != 0 || a.seed != b.seed) return "frame or seed";
  if (a.scene != b.scene || !(a.assets == b.assets)) return "scene or assets";
  if (a.first_pass != b.first_pass || a.end_pass != b.end_pass || a.lines != b.lines)
    return "passes or lines";
  if (!(da == db)) return "decisions";
  return "";
}

}  // namespace

int fuzz_line_decisions_reader(const std::uint8_t* data, std::size_t size) {
  const fuzz_edits::Edits e = fuzz_edits::parse(data, size);
  const Seed& seed = seeds()[e.seed % seeds().size()];
  std::string bytes = fuzz_edits::apply(e, seed.bytes);
  if (e.reseal) reseal(&bytes);
  PartialInfo info;
  LineDecisions d;
  std::string error;
  if (!read_line_decisions_bytes(bytes, "fuzz.bin", &info, &d, &error)) {
    if (error.rfind("fuzz.bin: ", 0) != 0 || error.size() <= 10 || error.find('\n') != std::string::npos)
      fuzz_fail("a refusal is not one line naming the file: \"" + error + "\"");
    return 0;
  }
  if (!e.reseal) {
    if (bytes != seed.bytes) fuzz_fail("a damaged line decision file was accepted");
    if (const std::string diff = difference(seed.info, seed.decisions, info, d); !diff.empty())
      fuzz_fail("the undamaged file reads differently: " + diff);
    return 0;
  }
  if (d.width != info.width || d.height != info.height ||
      (!d.rays.empty() && d.rays.size() != size_t(d.width) * size_t(d.height)) ||
      d.kinds.size() != d.rays.size())
    fuzz_fail("accepted decisions do not cover the image they name");
  PartialInfo info2;
  LineDecisions d2;
  if (!read_line_decisions_bytes(encode_line_decisions(d, info), "fuzz.bin", &info2, &d2, &error))
    fuzz_fail("accepted decisions, written again, are refused: " + error);
  if (const std::string diff = difference(info, d, info2, d2); !diff.empty())
    fuzz_fail("accepted decisions, written again, read differently: " + diff);
  return 0;
}

}  // namespace inkray
