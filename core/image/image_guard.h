// What inkray lets stb_image decode. stb_image is small and fast but not hardened:
// fuzzing found an endless loop in its HDR run-length decoder (a run of length 0), a
// heap overflow from a JPEG Huffman table with more than 256 codes, and integer
// overflows in its PNM reader. Before a file reaches it, this checks the container:
// only the formats inkray documents (PNG, JPEG, Radiance HDR, BMP, TGA), JPEG Huffman
// tables that fit, and HDR scanlines whose runs all advance.
#pragma once

#include <filesystem>
#include <string>

namespace inkray {

// False with *error naming the file and the problem when the file must not be decoded.
bool image_safe_to_decode(const std::filesystem::path& file, std::string* error);

}  // namespace inkray
