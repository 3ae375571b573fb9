// The round and the final avalanche are xxHash64's (its primes); one lane instead of four
// keeps it short, at about one byte per cycle, which hashing a partial or a mesh needs.
#include "core/io/content_hash.h"

#include "core/io/file_bytes.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <fstream>
#include <vector>

namespace inkray {
namespace {

constexpr uint64_t kP1 = 0x9E3779B185EBCA87ull, kP2 = 0xC2B2AE3D27D4EB4Full, kP3 = 0x165667B19E3779F9ull,
                   kP4 = 0x85EBCA77C2B2AE63ull, kP5 = 0x27D4EB2F165667C5ull;

uint64_t rotl(uint64_t v, int r) { return (v << r) | (v >> (64 - r)); }
uint64_t round(uint64_t acc, uint64_t word) { return rotl(acc + word * kP2, 31) * kP1; }
uint64_t load_le(const unsigned char* p) {
  uint64_t v;
  std::memcpy(&v, p, sizeof v);
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
  return v;
}

}  // namespace

ContentHash::ContentHash(uint64_t seed) : state_(seed + kP5) {}

ContentHash& ContentHash::add(std::string_view bytes) {
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  size_t n = bytes.size();
  length_ += n;
  if (n == 0) return *this;  // data() may be null: memcpy must not see it
  if (tail_size_) {          // finish a word begun by the last piece
    const size_t take = std::min<size_t>(8 - tail_size_, n);
    std::memcpy(tail_ + tail_size_, p, take);
    tail_size_ += unsigned(take);
    p += take;
    n -= take;
    if (tail_size_ < 8) return *this;  // all taken
    state_ = round(state_, load_le(tail_));
    tail_size_ = 0;
  }
  for (; n >= 8; p += 8, n -= 8) state_ = round(state_, load_le(p));
  if (n) std::memcpy(tail_, p, n);  // fewer than 8, into an empty tail
  tail_size_ = unsigned(n);
  return *this;
}

ContentHash& ContentHash::add_u64(uint64_t v) {
  unsigned char b[8];
  for (int i = 0; i < 8; ++i) b[i] = static_cast<unsigned char>(v >> (8 * i));
  return add(std::string_view(reinterpret_cast<const char*>(b), 8));
}

ContentHash& ContentHash::add_field(std::string_view bytes) {
  add_u64(bytes.size());
  return add(bytes);
}

uint64_t ContentHash::digest() const {
  uint64_t h = state_ + length_;
  for (unsigned i = 0; i < tail_size_; ++i) h = rotl(h ^ (uint64_t(tail_[i]) * kP5), 11) * kP1;
  h ^= h >> 33;
  h *= kP2;
  h ^= h >> 29;
  h *= kP3;
  h ^= h >> 32;
  return h ^ kP4;
}

uint64_t content_hash(std::string_view bytes) { return ContentHash().add(bytes).digest(); }

std::string hash_hex(uint64_t hash) {
  static const char* digits = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 15; i >= 0; --i, hash >>= 4) s[size_t(i)] = digits[hash & 15u];
  return s;
}

std::optional<uint64_t> parse_hash_hex(std::string_view text) {
  if (text.size() != 16) return std::nullopt;
  uint64_t v = 0;
  for (const char c : text) {
    int d;
    if (c >= '0' && c <= '9')
      d = c - '0';
    else if (c >= 'a' && c <= 'f')
      d = c - 'a' + 10;
    else
      return std::nullopt;
    v = (v << 4) | uint64_t(d);
  }
  return v;
}

std::optional<uint64_t> hash_file(const std::filesystem::path& file, std::string* error) {
  if (!check_regular_file(file, error)) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    *error = file.string() + ": cannot open the file";
    return std::nullopt;
  }
  ContentHash h;
  std::vector<char> buffer(size_t(1) << 20);
  while (in) {
    in.read(buffer.data(), std::streamsize(buffer.size()));
    h.add(std::string_view(buffer.data(), size_t(in.gcount())));
  }
  if (in.bad()) {
    *error = file.string() + ": cannot read the file";
    return std::nullopt;
  }
  return h.digest();
}

}  // namespace inkray
