#include "core/film/partial_channels.h"

#include <algorithm>
#include <cstring>
#include <type_traits>

namespace inkray {

std::vector<PartialChannel> partial_channels(const PartialInfo& info) {
  std::vector<PartialChannel> c;
  const char* rgb[3] = {"R", "G", "B"};
  const char* xyz[3] = {"X", "Y", "Z"};
  // A score of names, once per file: not worth counting them first to reserve.
  // NOLINTNEXTLINE(performance-inefficient-vector-operation)
  for (int k = 0; k < 3; ++k) c.push_back({rgb[k], PartialField::preview, k, PartialStored::f32});
  for (int k = 0; k < 3; ++k)
    c.push_back({std::string("radiance.even.") + rgb[k], PartialField::sum_even, k, PartialStored::f64});
  for (int k = 0; k < 3; ++k)
    c.push_back({std::string("radiance.odd.") + rgb[k], PartialField::sum_odd, k, PartialStored::f64});
  c.push_back({"count.even", PartialField::count_even, 0, PartialStored::u32});
  c.push_back({"count.odd", PartialField::count_odd, 0, PartialStored::u32});
  const AovSet& a = info.aovs;
  if (a.has(Aov::albedo))
    for (int k = 0; k < 3; ++k)
      c.push_back({std::string("albedo.") + rgb[k], PartialField::albedo, k, PartialStored::f64});
  if (a.has(Aov::normal))
    for (int k = 0; k < 3; ++k)
      c.push_back({std::string("normal.") + xyz[k], PartialField::normal, k, PartialStored::f64});
  if (a.has(Aov::depth)) c.push_back({"depth.Z", PartialField::depth, 0, PartialStored::f64});
  if (a.has(Aov::toon_band)) c.push_back({"toon_band", PartialField::band, 0, PartialStored::f64});
  if (a.averages_hits()) c.push_back({"hits", PartialField::hits, 0, PartialStored::u32});
  if (a.has(Aov::object_id)) c.push_back({"object_id", PartialField::object_id, 0, PartialStored::i32});
  if (a.has(Aov::material_id)) c.push_back({"material_id", PartialField::material_id, 0, PartialStored::i32});
  if (a.has(Aov::object_id) || a.has(Aov::material_id))
    c.push_back({"ids_mixed", PartialField::ids_mixed, 0, PartialStored::u32});
  if (info.lines) {
    for (int t = 0; t < kLineTypeCount; ++t)
      c.push_back({"lines.coverage." + std::string(kLineTypeNames[size_t(t)]), PartialField::coverage, t,
                   PartialStored::f64});
    c.push_back({"lines.weight", PartialField::weight, 0, PartialStored::f64});
    c.push_back({"lines.override_weight", PartialField::override_weight, 0, PartialStored::f64});
    for (int k = 0; k < 3; ++k)
      c.push_back({std::string("lines.override_color.") + rgb[k], PartialField::override_color, k,
                   PartialStored::f64});
    c.push_back({"lines.rays", PartialField::rays, 0, PartialStored::f64});
    c.push_back({"lines.hit_rays", PartialField::hit_rays, 0, PartialStored::f64});
    c.push_back({"lines.samples", PartialField::line_count, 0, PartialStored::u32});
  }
  return c;
}

namespace {

// Calls `use` with the field that holds channel `f` (component `k`) of `p`, a FilmPixel
// or a const one: reading and writing channels name each field once. The preview,
// worked out from the sums, is held in no field.
template <class Pixel, class Use>
void with_field(Pixel& p, PartialField f, int k, Use&& use) {
  switch (f) {
    case PartialField::preview:
      break;
    case PartialField::sum_even:
      use(p.sum[0][k]);
      break;
    case PartialField::sum_odd:
      use(p.sum[1][k]);
      break;
    case PartialField::count_even:
      use(p.count[0]);
      break;
    case PartialField::count_odd:
      use(p.count[1]);
      break;
    case PartialField::albedo:
      use(p.albedo_sum[k]);
      break;
    case PartialField::normal:
      use(p.normal_sum[k]);
      break;
    case PartialField::depth:
      use(p.depth_sum);
      break;
    case PartialField::band:
      use(p.band_sum);
      break;
    case PartialField::hits:
      use(p.hit_count);
      break;
    case PartialField::object_id:
      use(p.object_id);
      break;
    case PartialField::material_id:
      use(p.material_id);
      break;
    case PartialField::ids_mixed:
      use(p.ids_mixed);
      break;
    case PartialField::coverage:
      use(p.lines.coverage[size_t(k)]);
      break;
    case PartialField::weight:
      use(p.lines.weight);
      break;
    case PartialField::override_weight:
      use(p.lines.override_weight);
      break;
    case PartialField::override_color:
      use(p.lines.override_color[k]);
      break;
    case PartialField::rays:
      use(p.lines.rays);
      break;
    case PartialField::hit_rays:
      use(p.lines.hit_rays);
      break;
    case PartialField::line_count:
      use(p.line_count);
      break;
  }
}

}  // namespace

double channel_value(const FilmPixel& p, PartialField f, int k) {
  if (f == PartialField::preview) {
    const uint32_t n = p.count[0] + p.count[1];
    return n ? (p.sum[0][k] + p.sum[1][k]) / double(n) : 0.0;
  }
  double v = 0.0;
  with_field(p, f, k, [&](const auto& field) { v = double(field); });
  return v;
}

void set_channel_value(FilmPixel& p, PartialField f, int k, double v) {
  with_field(p, f, k, [&](auto& field) { field = std::remove_reference_t<decltype(field)>(v); });
}

std::vector<ExrChannel> exr_channels(const std::vector<PartialChannel>& channels) {
  std::vector<ExrChannel> out;
  for (size_t i = 0; i < channels.size(); ++i) {
    const PartialChannel& c = channels[i];
    switch (c.stored) {
      case PartialStored::f64:
        out.push_back({c.name + ".hi", i, 0, kExrUint, 0});
        out.push_back({c.name + ".lo", i, 1, kExrUint, 0});
        break;
      case PartialStored::u32:
      case PartialStored::i32:
        out.push_back({c.name, i, 0, kExrUint, 0});
        break;
      case PartialStored::f32:
        out.push_back({c.name, i, 0, kExrFloat, 0});
        break;
    }
  }
  std::sort(out.begin(), out.end(), [](const ExrChannel& a, const ExrChannel& b) { return a.name < b.name; });
  for (ExrChannel& hi : out)
    if (channels[hi.channel].stored == PartialStored::f64 && hi.word == 0)
      for (size_t k = 0; k < out.size(); ++k)
        if (out[k].channel == hi.channel && out[k].word == 1) hi.low = k;
  return out;
}

uint32_t to_word(double v, PartialStored stored, int word) {
  switch (stored) {
    case PartialStored::f64: {
      uint64_t bits;
      std::memcpy(&bits, &v, sizeof bits);
      return word == 0 ? uint32_t(bits >> 32) : uint32_t(bits);
    }
    case PartialStored::u32:
      return uint32_t(v);
    case PartialStored::i32:
      return uint32_t(int32_t(v));
    case PartialStored::f32: {
      const float f = float(v);
      uint32_t bits;
      std::memcpy(&bits, &f, sizeof bits);
      return bits;
    }
  }
  return 0;
}

double from_words(uint32_t hi, uint32_t lo, PartialStored stored) {
  switch (stored) {
    case PartialStored::f64: {
      const uint64_t bits = (uint64_t(hi) << 32) | lo;
      double v;
      std::memcpy(&v, &bits, sizeof v);
      return v;
    }
    case PartialStored::u32:
      return double(hi);
    case PartialStored::i32:
      return double(int32_t(hi));
    case PartialStored::f32: {
      float f;
      std::memcpy(&f, &hi, sizeof f);
      return double(f);
    }
  }
  return 0.0;
}

}  // namespace inkray
