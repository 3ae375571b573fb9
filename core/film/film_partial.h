// Partial renders: a film's raw sums over a window of pixels and a range of
// passes, in an OpenEXR file that says what it was rendered from, so that
// partials rendered on many machines add up to the film one machine would have
// rendered (docs/final-renders.md, "Partial files"; merging: partial_merge.h).
// Checkpoints of long renders are partials too.
#pragma once

#include "core/film/film.h"
#include "core/io/content_hash.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

inline constexpr std::string_view kPartialFormat = "inkray-partial";
// 2: passes go to the halves by half_of_pass (film.h), and the toon_band and ids_mixed
// channels exist; a version-1 partial cannot be merged with them.
// 3: the header holds the assets' hashes and the content hash, and the file is sealed
// by checksums (partial_seal.h); a version-2 partial cannot be checked for either.
inline constexpr int kPartialVersion = 3;

struct PartialInfo {
  int width = 0, height = 0;  // the full image
  PixelWindow window;         // the pixels held
  // Passes [first_pass, end_pass) of every pixel's sample sequence.
  uint32_t first_pass = 0, end_pass = 0;
  // A checkpoint cut mid-pass also holds pass end_pass on these tiles of the full
  // image (RenderSession::tiles_done); empty otherwise. Only a render resumes it.
  std::vector<uint8_t> tiles_done{};
  float frame = 1.f;
  int seed = 0;
  std::string scene{};     // the document rendered, as inkray writes it (scene_to_string)
  AovSet aovs{};           // first-hit AOVs held (outline AOVs come from the line sums)
  bool lines = false;      // the line sums are held (the scene draws lines)
  uint64_t nonfinite = 0;  // samples dropped as not finite
  // The files the scene refers to and their bytes' hashes (scene_hash.h); the header's
  // content hash is derived from these and the scene. Last: aggregate initialisers
  // of the fields above keep working. (Every field has a default, `{}` at least, so a
  // designated initialiser may leave any out without -Wmissing-field-initializers.)
  std::vector<AssetHash> assets{};
};

// The file's bytes for the pixels of info.window of `film`, which covers the
// full image; the AOVs, lines and non-finite count are the film's. False with
// *error on failure.
bool encode_partial(const Film& film, const PartialInfo& info, std::string* bytes, std::string* error);
// Reads a partial file: its header, and unless `film` is null its pixels as a
// film of the window's size. Every problem (not a regular file, not an EXR, not a
// partial, another version, a damaged header or pixel data, a missing or mistyped
// attribute or channel, a scene nested too deep, a non-finite sum) is one line in
// *error naming the file and what was expected. The whole file is checked against its
// checksums either way.
bool read_partial(const std::filesystem::path& file, PartialInfo* info, std::unique_ptr<Film>* film,
                  std::string* error);
// The same from bytes in memory; `label` names them in messages ("FILE: ...").
bool read_partial_bytes(std::string_view bytes, const std::string& label, PartialInfo* info,
                        std::unique_ptr<Film>* film, std::string* error);

// The largest partial a reader takes: the header (scene and assets) and 64 32-bit
// channels of an 8192x8192 image with RLE's worst overhead.
inline constexpr std::uintmax_t kMaxPartialBytes =
    (std::uintmax_t(160) << 20) + std::uintmax_t(8192) * 8192 * 64 * 4 / 64 * 65;

// "samples 0-64 of pixels (0,0)-(32,16)", "(0,0)-(32,16)", "0-64" and
// "albedo,depth" for messages and headers (ranges and windows half-open).
std::string describe_partial(const PartialInfo& info);
std::string describe_window(const PixelWindow& w);
std::string describe_range(uint32_t first, uint32_t end);
std::string first_hit_aov_names(const AovSet& aovs);

}  // namespace inkray
