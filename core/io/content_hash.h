// A fast 64-bit content hash (an xxHash64-like single lane) for telling files apart:
// the assets a render read and the bytes of the files inkray writes for other inkray
// processes (partials, line decisions), so that damage or a changed asset is refused.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// A file a render read: its path as the scene writes it and the hash of its bytes
// (hash_hex), or "missing" when there was no file to read.
struct AssetHash {
  std::string path;
  std::string digest;
  bool operator==(const AssetHash&) const = default;
};

// Incremental: add() any pieces, digest() any time. Every round is a bijection of the
// state for a fixed input word and of the word for a fixed state, so a change confined to
// one 8-byte word is always detected; wider changes collide with chance 2^-64.
class ContentHash {
 public:
  explicit ContentHash(uint64_t seed = 0);
  ContentHash& add(std::string_view bytes);
  ContentHash& add_u64(uint64_t v);  // a number, as its 8 little-endian bytes
  // A length-prefixed piece: ("ab","c") and ("a","bc") hash differently.
  ContentHash& add_field(std::string_view bytes);
  uint64_t digest() const;

 private:
  uint64_t state_;
  uint64_t length_ = 0;
  unsigned char tail_[8] = {};
  unsigned tail_size_ = 0;
};

uint64_t content_hash(std::string_view bytes);

// 16 lowercase hex digits, and back (nullopt unless exactly 16 hex digits).
std::string hash_hex(uint64_t hash);
std::optional<uint64_t> parse_hash_hex(std::string_view text);

// The hash of a regular file's bytes, read in pieces (a mesh may be larger than memory
// wants to hold twice); nullopt with *error naming the file when it cannot be read.
std::optional<uint64_t> hash_file(const std::filesystem::path& file, std::string* error);

}  // namespace inkray
