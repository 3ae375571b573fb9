// The header checksum covers bytes [0, header end) with its own value counted as 16
// zeros, the data checksum covers [header end, file end): a flip of the data checksum's
// own value is a damaged header, any other byte is in one of the two ranges.
#include "core/film/partial_seal.h"

#include "core/io/content_hash.h"

#include <cstring>

namespace inkray {
namespace {

// OpenEXR's magic number, and the version field's flags that a partial never sets.
constexpr unsigned char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr unsigned kTiled = 0x200, kLongNames = 0x400, kNonImage = 0x800, kMultipart = 0x1000;
constexpr size_t kMaxAttributes = 1024;

uint32_t le32(std::string_view s, size_t at) {
  uint32_t v = 0;
  for (int b = 0; b < 4; ++b) v |= uint32_t(uint8_t(s[at + size_t(b)])) << (8 * b);
  return v;
}

// A NUL-terminated name of at most `longest` characters at *at; advances past the NUL.
bool read_name(std::string_view bytes, size_t* at, size_t longest, std::string* name) {
  const size_t end = bytes.find('\0', *at);
  if (end == std::string_view::npos || end - *at > longest) return false;
  *name = std::string(bytes.substr(*at, end - *at));
  *at = end + 1;
  return true;
}

const RawAttribute* find(const std::vector<RawAttribute>& attributes, std::string_view name) {
  const RawAttribute* found = nullptr;
  for (const RawAttribute& a : attributes)
    if (a.name == name) {
      if (found) return nullptr;  // twice: no one checksum to trust
      found = &a;
    }
  return found;
}

uint64_t header_hash(std::string_view bytes, size_t header_end, const RawAttribute& own) {
  ContentHash h;
  h.add(bytes.substr(0, own.value_at)).add(kUnsealed);
  h.add(bytes.substr(own.value_at + own.size, header_end - own.value_at - own.size));
  return h.digest();
}

// The attribute `name`: once, a string of 16 characters.
const RawAttribute* checksum_of(const std::vector<RawAttribute>& attributes, std::string_view name) {
  const RawAttribute* a = find(attributes, name);
  return a && a->type == "string" && a->size == kUnsealed.size() ? a : nullptr;
}

}  // namespace

bool walk_exr_header(std::string_view bytes, std::vector<RawAttribute>* attributes, size_t* header_end,
                     std::string* error) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kMagic, 4) != 0) {
    *error = "not an OpenEXR file (expected an inkray partial .exr)";
    return false;
  }
  const uint32_t version = le32(bytes, 4);
  if ((version & 0xff) != 2 || (version & (kTiled | kNonImage | kMultipart))) {
    *error = "a multi-part, deep, tiled or unknown version of EXR, not an inkray partial";
    return false;
  }
  const size_t longest = (version & kLongNames) ? 255 : 31;
  attributes->clear();
  size_t at = 8;
  for (;;) {
    if (at >= bytes.size()) {
      *error = "the EXR header ends before its last attribute (a truncated or damaged file)";
      return false;
    }
    if (bytes[at] == '\0') {
      *header_end = at + 1;
      return true;
    }
    RawAttribute a;
    if (attributes->size() >= kMaxAttributes || !read_name(bytes, &at, longest, &a.name) ||
        !read_name(bytes, &at, longest, &a.type) || at + 4 > bytes.size()) {
      *error = "the EXR header's attribute " + std::to_string(attributes->size() + 1) +
               " is broken (a truncated or damaged file)";
      return false;
    }
    a.size = le32(bytes, at);
    a.value_at = at + 4;
    if (a.size > bytes.size() - a.value_at) {
      *error = "the EXR header's attribute " + std::to_string(attributes->size() + 1) +
               " runs past the end of the file (a truncated or damaged file)";
      return false;
    }
    at = a.value_at + a.size;
    attributes->push_back(std::move(a));
  }
}

bool seal_partial(std::string* bytes, std::string* error) {
  std::vector<RawAttribute> attributes;
  size_t header_end = 0;
  if (!walk_exr_header(*bytes, &attributes, &header_end, error)) return false;
  const RawAttribute* header = checksum_of(attributes, kHeaderChecksumAttribute);
  const RawAttribute* data = checksum_of(attributes, kDataChecksumAttribute);
  if (!header || !data) {
    *error = "partial: no checksum placeholders in the encoded header";
    return false;
  }
  const std::string d = hash_hex(content_hash(std::string_view(*bytes).substr(header_end)));
  bytes->replace(data->value_at, d.size(), d);
  const std::string h = hash_hex(header_hash(*bytes, header_end, *header));
  bytes->replace(header->value_at, h.size(), h);
  return true;
}

SealCheck check_partial_seal(std::string_view bytes, std::string* problem) {
  std::vector<RawAttribute> attributes;
  size_t header_end = 0;
  if (!walk_exr_header(bytes, &attributes, &header_end, problem)) return SealCheck::header_damaged;
  const RawAttribute* header = checksum_of(attributes, kHeaderChecksumAttribute);
  const RawAttribute* data = checksum_of(attributes, kDataChecksumAttribute);
  if (!header || !data) {
    *problem = "its header is damaged (no attributes " + std::string(kHeaderChecksumAttribute) + " and " +
               std::string(kDataChecksumAttribute) + " of 16 hex digits each)";
    return SealCheck::header_damaged;
  }
  const auto stored_header = parse_hash_hex(bytes.substr(header->value_at, header->size));
  if (!stored_header || *stored_header != header_hash(bytes, header_end, *header)) {
    *problem = "its header is damaged (its bytes do not match " + std::string(kHeaderChecksumAttribute) + ")";
    return SealCheck::header_damaged;
  }
  const auto stored_data = parse_hash_hex(bytes.substr(data->value_at, data->size));
  if (!stored_data || *stored_data != content_hash(bytes.substr(header_end))) {
    *problem = "its pixel data is damaged (the bytes after the header do not match " +
               std::string(kDataChecksumAttribute) + ")";
    return SealCheck::data_damaged;
  }
  return SealCheck::intact;
}

}  // namespace inkray
