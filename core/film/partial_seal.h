// The seal of a partial file: two checksums in its header, one over the header's own
// bytes and one over everything after it (offset table and pixels), so that any change
// to any byte of a partial is refused (docs/final-renders.md, "Partial files").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// Written as 16 zeros by the encoder, then filled by seal_partial.
inline constexpr std::string_view kHeaderChecksumAttribute = "inkray.headerChecksum";
inline constexpr std::string_view kDataChecksumAttribute = "inkray.dataChecksum";
inline constexpr std::string_view kUnsealed = "0000000000000000";

// An attribute of a single-part OpenEXR header as it sits in the file's bytes.
struct RawAttribute {
  std::string name, type;
  size_t value_at = 0, size = 0;
};
// The attributes of a single-part scanline EXR read straight from its bytes (no
// decoder), and where its header ends; false with *error saying what is wrong.
bool walk_exr_header(std::string_view bytes, std::vector<RawAttribute>* attributes, size_t* header_end,
                     std::string* error);

// Fills the two checksums of an encoded partial; false with *error when it has no
// 16-zero placeholders for them.
bool seal_partial(std::string* bytes, std::string* error);

enum class SealCheck { intact, header_damaged, data_damaged };
// Whether the bytes are as sealed: `problem` says what is not (no file name). The
// header is checked first: when it is intact, its attributes can be trusted.
SealCheck check_partial_seal(std::string_view bytes, std::string* problem);

}  // namespace inkray
