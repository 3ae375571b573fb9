// Container checks in front of stb_image: format by signature, JPEG Huffman tables,
// HDR run lengths. Each walks the file's structure without decoding a pixel.
#include "core/image/image_guard.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string_view>
#include <vector>

namespace inkray {
namespace {

using Bytes = std::vector<std::uint8_t>;

bool starts_with(const Bytes& b, std::string_view prefix) {
  return b.size() >= prefix.size() && std::memcmp(b.data(), prefix.data(), prefix.size()) == 0;
}

// JPEG: every DHT segment declares at most 256 codes per table, and each table fits in
// its segment (stb_image trusts both); every scan uses only Huffman tables defined
// before it (stb_image decodes with an undefined table's uninitialised memory, and
// its assertions abort on what it finds there).
std::string jpeg_problem(const Bytes& b) {
  bool defined[2][4] = {};  // [DC 0, AC 1][table 0-3]
  bool progressive = false;
  std::size_t at = 2;  // after SOI
  while (at + 4 <= b.size()) {
    if (b[at] != 0xff) return "a JPEG segment does not start with a marker";
    const std::uint8_t marker = b[at + 1];
    if (marker == 0xff) {  // fill byte
      ++at;
      continue;
    }
    if (marker == 0xd9) return {};  // end of image
    const std::size_t length = (std::size_t(b[at + 2]) << 8) | b[at + 3];
    if (length < 2 || at + 2 + length > b.size()) return "a JPEG segment runs past the end of the file";
    const std::size_t end = at + 2 + length;
    if (marker == 0xc2) progressive = true;
    if (marker == 0xc4) {
      std::size_t p = at + 4;
      while (p < end) {
        if (p + 17 > end) return "a JPEG Huffman table is cut short";
        const int table_class = b[p] >> 4, id = b[p] & 15;
        if (table_class > 1 || id > 3) return "a JPEG Huffman table has a bad class or number";
        defined[table_class][id] = true;
        std::size_t codes = 0;
        for (int i = 1; i <= 16; ++i) codes += b[p + std::size_t(i)];
        if (codes > 256)
          return "a JPEG Huffman table declares " + std::to_string(codes) + " codes (at most 256)";
        p += 17 + codes;
        if (p > end) return "a JPEG Huffman table runs past its segment";
      }
    }
    if (marker == 0xda) {
      // Ns, then Ns (component, DC table << 4 | AC table), then Ss, Se, Ah/Al. A
      // progressive scan codes DC (Ss = 0) or AC coefficients, with that class only.
      const std::size_t components = at + 4 < end ? b[at + 4] : 0;
      const std::size_t spectral = at + 5 + 2 * components;
      if (components == 0 || spectral >= end) return "a JPEG scan header is cut short";
      const bool dc = !progressive || b[spectral] == 0, ac = !progressive || b[spectral] != 0;
      for (std::size_t c = 0; c < components; ++c) {
        const std::uint8_t tables = b[at + 6 + 2 * c];
        if ((dc && !defined[0][(tables >> 4) & 3]) || (ac && !defined[1][tables & 3]))
          return "a JPEG scan uses a Huffman table the file does not define";
      }
      // The entropy-coded data runs to the next marker that is not a stuffed 0xff00
      // or a restart marker.
      std::size_t p = end;
      while (p + 1 < b.size() && !(b[p] == 0xff && b[p + 1] != 0x00 && (b[p + 1] < 0xd0 || b[p + 1] > 0xd7)))
        ++p;
      if (p + 1 >= b.size()) return {};  // the data runs to the end: stb stops there
      at = p;
      continue;
    }
    at = end;
  }
  return {};
}

// Radiance HDR: after the header and the "-Y h +X w" line, each new-style RLE
// scanline's runs must be non-empty and stay inside the scanline.
std::string hdr_problem(const Bytes& b) {
  std::size_t at = 0;
  const auto line = [&]() -> std::string {
    std::string out;
    while (at < b.size() && b[at] != '\n') out += char(b[at++]);
    if (at < b.size()) ++at;
    return out;
  };
  while (at < b.size() && !line().empty()) {
  }
  int height = 0, width = 0;
  if (std::sscanf(line().c_str(), "-Y %d +X %d", &height, &width) != 2) return {};  // stb reports it
  if (width < 8 || width >= 32768) return {};  // flat scanlines: no runs to check
  for (int y = 0; y < height; ++y) {
    if (at + 4 > b.size()) return "the HDR image data is cut short";
    if (b[at] != 2 || b[at + 1] != 2 || (b[at + 2] & 0x80)) return {};  // old-style file: read flat
    at += 4;
    for (int channel = 0; channel < 4; ++channel) {
      for (int x = 0; x < width;) {
        // Past the end stb reads zeros, which are runs of length 0: it would never return.
        if (at >= b.size()) return "an HDR scanline is cut short";
        int count = b[at++];
        if (count > 128) {
          count -= 128;
          ++at;
        } else {
          at += std::size_t(count);
        }
        if (at > b.size()) return "an HDR scanline is cut short";
        if (count == 0) return "an HDR scanline has a run of length 0";
        if (count > width - x) return "an HDR run goes past the end of its scanline";
        x += count;
      }
    }
  }
  return {};
}

}  // namespace

bool image_safe_to_decode(const std::filesystem::path& file, std::string* error) {
  // Reading a folder as a stream throws in libstdc++; say what it is instead.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    *error = file.string() + ": cannot read image (" +
             (std::filesystem::exists(file, ec) ? "not a regular file" : "file not found") + ")";
    return false;
  }
  std::ifstream in(file, std::ios::binary);
  const Bytes b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string problem;
  // PNG and BMP pass here, TGA below: it has no signature, so it is tried last.
  // NOLINTNEXTLINE(bugprone-branch-clone)
  if (starts_with(b, "\x89PNG\r\n\x1a\n") || starts_with(b, "BM")) {
    return true;
  } else if (starts_with(b, "\xff\xd8")) {
    problem = jpeg_problem(b);
  } else if (starts_with(b, "#?RADIANCE") || starts_with(b, "#?RGBE")) {
    problem = hdr_problem(b);
  } else if (b.size() >= 18 &&
             (b[2] == 1 || b[2] == 2 || b[2] == 3 || b[2] == 9 || b[2] == 10 || b[2] == 11)) {
    return true;  // TGA has no signature; its image type byte is the best there is
  } else {
    problem = "not a PNG, JPEG, HDR, BMP or TGA image";
  }
  if (problem.empty()) return true;
  *error = file.string() + ": cannot read image (" + problem + ")";
  return false;
}

}  // namespace inkray
