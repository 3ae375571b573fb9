// The input of the fuzz harnesses for files inkray writes for itself (partials,
// checkpoints, line decisions): the file is made in-process from a known film, and the
// input says how to damage it, so an oracle knows what the undamaged file reads as.
//
// Input: a mode byte, then up to 64 edits of 5 bytes: a 32-bit little-endian word whose
// top two bits pick the edit (xor a byte, set a byte, cut the file there, insert a byte)
// and whose low 30 bits, modulo the file's size, say where; then the edit's byte.
// Mode bit 0: reseal the file after the edits (recompute its checksums), which reaches
// the parsers behind the checksums, as a file written by another program would;
// bits 1-2: which of the harness's seed files to start from.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace inkray::fuzz_edits {

struct Edits {
  bool reseal = false;
  unsigned seed = 0;
  const std::uint8_t* edits = nullptr;
  std::size_t count = 0;
};

inline Edits parse(const std::uint8_t* data, std::size_t size) {
  Edits e;
  if (size == 0) return e;
  e.reseal = data[0] & 1u;
  e.seed = (data[0] >> 1) & 3u;
  e.edits = data + 1;
  e.count = (size - 1) / 5;
  if (e.count > 64) e.count = 64;
  return e;
}

inline std::string apply(const Edits& e, std::string bytes) {
  for (std::size_t k = 0; k < e.count; ++k) {
    const std::uint8_t* p = e.edits + 5 * k;
    const std::uint32_t word = std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
                               std::uint32_t(p[3]) << 24;
    const char byte = char(p[4]);
    const std::size_t at = std::size_t(word & 0x3fffffffu) % (bytes.size() + 1);
    switch (word >> 30) {
      case 0:
        if (at < bytes.size()) bytes[at] = char(bytes[at] ^ byte);
        break;
      case 1:
        if (at < bytes.size()) bytes[at] = byte;
        break;
      case 2:
        bytes.resize(at);
        break;
      default:
        bytes.insert(bytes.begin() + std::ptrdiff_t(at), byte);
        break;
    }
  }
  return bytes;
}

}  // namespace inkray::fuzz_edits
