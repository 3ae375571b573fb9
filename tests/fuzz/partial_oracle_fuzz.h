// The oracle shared by the partial and checkpoint harnesses (partial_reader_fuzz.cpp,
// checkpoint_reader_fuzz.cpp): a damaged file is refused with one line naming it, or
// read as exactly the undamaged file; a resealed one (file_edits_fuzz.h) is refused, or
// what it reads as is finite and writes back to a file that reads the same.
#pragma once

#include "core/film/film_partial.h"
#include "core/film/partial_channels.h"
#include "core/film/partial_seal.h"
#include "tests/fuzz/file_edits_fuzz.h"
#include "tests/fuzz/fuzz_targets.h"

#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace inkray::partial_oracle {

struct Seed {
  PartialInfo info;            // as read back: the film's AOVs and lines
  std::unique_ptr<Film> film;  // the window's pixels, as read back
  std::string bytes;
};

// Encodes `film` (the full image) for `info`, and reads it back once: the reference.
inline Seed make_seed(const Film& film, const PartialInfo& info) {
  Seed s;
  std::string error;
  if (!encode_partial(film, info, &s.bytes, &error)) fuzz_fail("the seed does not encode: " + error);
  if (!read_partial_bytes(s.bytes, "seed.exr", &s.info, &s.film, &error))
    fuzz_fail("the seed does not read back: " + error);
  return s;
}

inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// "" when equal, else the first difference.
inline std::string difference(const PartialInfo& a, const Film* fa, const PartialInfo& b, const Film* fb) {
  if (a.width != b.width || a.height != b.height || a.window != b.window) return "size or window";
  if (a.first_pass != b.first_pass || a.end_pass != b.end_pass || a.tiles_done != b.tiles_done)
    return "passes";
  if (!same_bits(a.frame, b.frame) || a.seed != b.seed) return "frame or seed";
  if (a.scene != b.scene || !(a.assets == b.assets)) return "scene or assets";
  if (a.aovs.bits != b.aovs.bits || a.lines != b.lines || a.nonfinite != b.nonfinite)
    return "AOVs, lines or count";
  if (!fa || !fb) return "";
  if (fa->width() != fb->width() || fa->height() != fb->height()) return "film size";
  const std::vector<PartialChannel> channels = partial_channels(a);
  for (int y = 0; y < fa->height(); ++y)
    for (int x = 0; x < fa->width(); ++x) {
      const FilmPixel pa = fa->pixel(x, y), pb = fb->pixel(x, y);
      for (const PartialChannel& c : channels)
        if (!same_bits(channel_value(pa, c.field, c.component), channel_value(pb, c.field, c.component)))
          return "channel " + c.name + " at (" + std::to_string(x) + "," + std::to_string(y) + ")";
    }
  return "";
}

inline void check_refusal(const std::string& error) {
  if (error.rfind("fuzz.exr: ", 0) != 0 || error.size() <= 10 || error.find('\n') != std::string::npos)
    fuzz_fail("a refusal is not one line naming the file: \"" + error + "\"");
}

inline int run(const std::uint8_t* data, std::size_t size, const std::vector<Seed>& seeds) {
  const fuzz_edits::Edits e = fuzz_edits::parse(data, size);
  const Seed& seed = seeds[e.seed % seeds.size()];
  std::string bytes = fuzz_edits::apply(e, seed.bytes);
  std::string error;
  if (e.reseal && !seal_partial(&bytes, &error)) error.clear();  // no placeholders found: as damaged

  PartialInfo header, info;
  std::unique_ptr<Film> film;
  if (!read_partial_bytes(bytes, "fuzz.exr", &info, &film, &error)) {
    check_refusal(error);
    return 0;
  }
  // Merging reads every header before any pixels: a header-only read accepts it too.
  std::string header_error;
  if (!read_partial_bytes(bytes, "fuzz.exr", &header, nullptr, &header_error))
    fuzz_fail("the pixels were read but the header alone was refused: " + header_error);
  if (!film) fuzz_fail("accepted without a film");
  if (const std::string d = difference(header, nullptr, info, nullptr); !d.empty())
    fuzz_fail("the header reads differently with and without the pixels: " + d);

  if (!e.reseal) {
    // Any change to a sealed file must be refused.
    if (bytes != seed.bytes) fuzz_fail("a damaged partial was accepted");
    if (const std::string d = difference(seed.info, seed.film.get(), info, film.get()); !d.empty())
      fuzz_fail("the undamaged partial reads differently: " + d);
    return 0;
  }
  // Resealed: what is accepted is a partial, finite, and writes back as itself.
  const PixelWindow& w = info.window;
  if (w.empty() || w.x0 < 0 || w.y0 < 0 || w.x1 > info.width || w.y1 > info.height)
    fuzz_fail("an accepted window is outside the image");
  if (film->width() != w.width() || film->height() != w.height())
    fuzz_fail("the film is not the window's size");
  if (!info.tiles_done.empty() &&
      info.tiles_done.size() != size_t((info.width + 15) / 16) * size_t((info.height + 15) / 16))
    fuzz_fail("an accepted checkpoint's passInProgress is not one flag per 16x16 tile");
  const std::vector<PartialChannel> channels = partial_channels(info);
  Film full(info.width, info.height, info.aovs, info.lines);
  for (int y = 0; y < w.height(); ++y)
    for (int x = 0; x < w.width(); ++x) {
      const FilmPixel p = film->pixel(x, y);
      for (const PartialChannel& c : channels)
        if (!std::isfinite(channel_value(p, c.field, c.component)))
          fuzz_fail("an accepted partial holds a non-finite " + c.name);
      full.add_pixel(w.x0 + x, w.y0 + y, p);
    }
  full.add_nonfinite(info.nonfinite);
  std::string again;
  if (!encode_partial(full, info, &again, &error)) fuzz_fail("an accepted partial does not encode: " + error);
  PartialInfo info2;
  std::unique_ptr<Film> film2;
  if (!read_partial_bytes(again, "fuzz.exr", &info2, &film2, &error))
    fuzz_fail("an accepted partial, written again, is refused: " + error);
  if (const std::string d = difference(info, film.get(), info2, film2.get()); !d.empty())
    fuzz_fail("an accepted partial, written again, reads differently: " + d);
  return 0;
}

// A harness: its seeds, made on its first input (encoding them takes longer than a run).
template <std::vector<Seed> (*make_seeds)()>
int run(const std::uint8_t* data, std::size_t size) {
  static const std::vector<Seed> seeds = make_seeds();
  return run(data, size, seeds);
}

}  // namespace inkray::partial_oracle
