// The film's raw state as the 32-bit channels of a partial file (film_partial.h):
// which channels a partial holds, and each pixel's values in and out of them.
#pragma once

#include "core/film/film_partial.h"
#include "core/image/exr_memory.h"

#include <cstdint>
#include <string>
#include <vector>

namespace inkray {

enum class PartialField : uint8_t {
  preview,
  sum_even,
  sum_odd,
  count_even,
  count_odd,
  albedo,
  normal,
  depth,
  band,
  hits,
  object_id,
  material_id,
  ids_mixed,
  coverage,
  weight,
  override_weight,
  override_color,
  rays,
  hit_rays,
  line_count
};
// How a value is stored: a double as two unsigned words (NAME.hi, NAME.lo), counts
// as unsigned, ids as the unsigned word of a signed one, the preview as float.
enum class PartialStored : uint8_t { f64, u32, i32, f32 };

struct PartialChannel {
  std::string name;
  PartialField field;
  int component;
  PartialStored stored;
};

// One EXR channel: a film channel, or one word of a double.
struct ExrChannel {
  std::string name;
  size_t channel;  // into partial_channels
  int word;        // f64: 0 the high word, 1 the low word
  int pixel_type;  // kExrUint or kExrFloat
  size_t low = 0;  // f64's high word: the EXR channel of its low word
};

// What a partial of `info` holds (its AOVs and lines), in the film's terms.
std::vector<PartialChannel> partial_channels(const PartialInfo& info);
// Their EXR channels, sorted by name as OpenEXR stores them.
std::vector<ExrChannel> exr_channels(const std::vector<PartialChannel>& channels);

// A pixel's value of a channel (every one is exact as a double), and back.
double channel_value(const FilmPixel& p, PartialField f, int component);
void set_channel_value(FilmPixel& p, PartialField f, int component, double v);
// A value as the 32-bit word `word` of its stored form, and back from its words.
uint32_t to_word(double v, PartialStored stored, int word);
double from_words(uint32_t hi, uint32_t lo, PartialStored stored);

}  // namespace inkray
