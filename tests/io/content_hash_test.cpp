// The content hash (core/io/content_hash.h): pieces hash as the whole, every single-bit
// change is seen, and a file hashes as its bytes.
#include "core/io/content_hash.h"

#include "tests/support/file_helpers.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>

namespace inkray {
namespace {

TEST(ContentHash, PiecesHashAsTheWhole) {
  std::string text;
  for (int i = 0; i < 100; ++i) text += char('a' + i % 26);
  const uint64_t whole = content_hash(text);
  for (size_t cut = 0; cut <= text.size(); cut += 7)
    for (size_t second = cut; second <= text.size(); second += 11) {
      ContentHash h;
      h.add(text.substr(0, cut)).add(text.substr(cut, second - cut)).add(text.substr(second));
      EXPECT_EQ(h.digest(), whole) << cut << " " << second;
    }
  // Fields carry their length: moving a boundary changes the hash.
  EXPECT_NE(ContentHash().add_field("ab").add_field("c").digest(),
            ContentHash().add_field("a").add_field("bc").digest());
  EXPECT_NE(content_hash(""), content_hash(std::string(1, '\0')));
}

TEST(ContentHash, EverySingleBitFlipChangesTheHash) {
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# a mesh of 42 bytes.";
  std::set<uint64_t> seen{content_hash(text)};
  for (size_t i = 0; i < text.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      std::string flipped = text;
      flipped[i] = char(flipped[i] ^ (1 << bit));
      EXPECT_TRUE(seen.insert(content_hash(flipped)).second) << "byte " << i << " bit " << bit;
    }
}

TEST(ContentHash, HexRoundTripsAndFilesHashAsTheirBytes) {
  for (const uint64_t v : {uint64_t(0), uint64_t(1), ~uint64_t(0), uint64_t(0x0123456789abcdefull)}) {
    EXPECT_EQ(hash_hex(v).size(), 16u);
    EXPECT_EQ(parse_hash_hex(hash_hex(v)), v);
  }
  EXPECT_FALSE(parse_hash_hex("0123456789ABCDEF"));  // written lowercase only
  EXPECT_FALSE(parse_hash_hex("0123456789abcde"));
  EXPECT_FALSE(parse_hash_hex("0123456789abcdeg"));

  testing::ScratchFolder dir;
  std::string big(3 << 20, 'x');  // more than one read piece
  big[2 << 20] = 'y';
  std::ofstream(dir / "big.bin", std::ios::binary) << big;
  std::string error;
  EXPECT_EQ(hash_file(dir / "big.bin", &error), content_hash(big)) << error;
  EXPECT_FALSE(hash_file(dir / "absent.bin", &error));
  EXPECT_NE(error.find("no such file"), std::string::npos) << error;
  EXPECT_FALSE(hash_file(dir.path(), &error));
  EXPECT_NE(error.find("a directory"), std::string::npos) << error;
}

}  // namespace
}  // namespace inkray
