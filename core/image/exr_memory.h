// EXR files encoded to memory from planes of 32-bit values, by tinyexr: the images inkray
// writes (image_io.cpp) and its partial files (core/film/film_partial.cpp).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace inkray {

inline constexpr int kExrUint = 0, kExrFloat = 2;  // TINYEXR_PIXELTYPE_UINT, _FLOAT

enum class ExrCompression { none, rle, zip };

struct ExrPlane {
  const char* name;    // the channel's name
  int pixel_type;      // kExrUint or kExrFloat
  const void* pixels;  // width * height 32-bit values, row by row
};

// A custom header attribute: its OpenEXR type ("int", "string", ...) and value bytes.
struct ExrAttribute {
  std::string type;
  std::string value;
};

// The file in *bytes, its channels in the order given. False with tinyexr's reason in
// *reason (empty when it gives none).
bool encode_exr_planes(int width, int height, const std::vector<ExrPlane>& planes,
                       const std::map<std::string, ExrAttribute>& attributes, ExrCompression compression,
                       std::string* bytes, std::string* reason);

}  // namespace inkray
