// Writes a PNG that is only a header: a small file claiming any size, as a hostile
// or mistaken texture can. Readers that trust the header before decoding are caught.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>

namespace inkray::testing {

// `padding` zero bytes follow, for a file as long as a real one of that size could be.
inline void write_png_header(const std::filesystem::path& file, std::uint32_t width, std::uint32_t height,
                             std::size_t padding = 0) {
  const auto be32 = [](std::uint32_t v) {
    return std::array<char, 4>{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
  };
  std::ofstream out(file, std::ios::binary);
  out.write("\x89PNG\r\n\x1a\n", 8);
  out.write(be32(13).data(), 4);
  out.write("IHDR", 4);
  out.write(be32(width).data(), 4);
  out.write(be32(height).data(), 4);
  out.write("\x08\x02\x00\x00\x00", 5);  // 8-bit RGB, no interlace
  out.write("\0\0\0\0", 4);              // CRC: stb_image does not check it
  for (std::size_t i = 0; i < padding; ++i) out.put('\0');
}

}  // namespace inkray::testing
