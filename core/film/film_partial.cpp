// Partial files: the film's sums as 32-bit EXR channels (doubles split into two
// unsigned words, so nothing is rounded), with inkray.* header attributes.
#include "core/film/film_partial.h"

#include "core/document/json_io.h"
#include "core/document/scene_hash.h"
#include "core/film/partial_channels.h"
#include "core/film/partial_seal.h"
#include "core/image/exr_memory.h"
#include "core/io/file_bytes.h"
#include "core/io/json_bounds.h"

#include <tinyexr.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>

namespace inkray {
namespace {

// ------------------------------------------------------------- attributes

// OpenEXR attribute values are little-endian.
void put_u32(std::string& s, uint32_t v) {
  for (int b = 0; b < 4; ++b) s.push_back(char((v >> (8 * b)) & 0xffu));
}
uint32_t get_u32(const std::string& s, size_t at) {
  uint32_t v = 0;
  for (int b = 0; b < 4; ++b) v |= uint32_t(uint8_t(s[at + size_t(b)])) << (8 * b);
  return v;
}

std::string ints(std::initializer_list<int> values) {
  std::string s;
  for (const int v : values) put_u32(s, uint32_t(v));
  return s;
}

std::string float_bytes(float f) {
  uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  std::string s;
  put_u32(s, bits);
  return s;
}

std::string tiles_text(const std::vector<uint8_t>& tiles) {
  std::string s(tiles.size(), '0');
  for (size_t i = 0; i < tiles.size(); ++i)
    if (tiles[i]) s[i] = '1';
  return s;
}

std::map<std::string, ExrAttribute> partial_attributes(const PartialInfo& info,
                                                       const std::string& channel_checksums) {
  std::map<std::string, ExrAttribute> a;
  a["inkray.format"] = {"string", std::string(kPartialFormat)};
  a["inkray.version"] = {"int", ints({kPartialVersion})};
  a["inkray.imageSize"] = {"v2i", ints({info.width, info.height})};
  // box2i: inclusive corners, as OpenEXR's own windows.
  a["inkray.window"] = {"box2i",
                        ints({info.window.x0, info.window.y0, info.window.x1 - 1, info.window.y1 - 1})};
  a["inkray.samples"] = {"v2i", ints({int(info.first_pass), int(info.end_pass)})};
  a["inkray.frame"] = {"float", float_bytes(info.frame)};
  a["inkray.seed"] = {"int", ints({info.seed})};
  a["inkray.scene"] = {"string", info.scene};
  a["inkray.aovs"] = {"string", first_hit_aov_names(info.aovs)};
  a["inkray.lines"] = {"int", ints({info.lines ? 1 : 0})};
  a["inkray.nonfinite"] = {"string", std::to_string(info.nonfinite)};
  if (!info.tiles_done.empty()) a["inkray.passInProgress"] = {"string", tiles_text(info.tiles_done)};
  a["inkray.assets"] = {"string", assets_to_json(info.assets)};
  a["inkray.contentHash"] = {"string", hash_hex(scene_content_hash(info.scene, info.assets))};
  a["inkray.channelChecksums"] = {"string", channel_checksums};
  a[std::string(kHeaderChecksumAttribute)] = {"string", std::string(kUnsealed)};
  a[std::string(kDataChecksumAttribute)] = {"string", std::string(kUnsealed)};
  return a;
}

// ------------------------------------------------------------ tinyexr RAII

// tinyexr 1.0.1 fills the header with what it read even when parsing fails, so it is
// always freed.
struct ParsedHeader {
  EXRHeader header;
  ParsedHeader() { InitEXRHeader(&header); }
  ~ParsedHeader() { FreeEXRHeader(&header); }
  ParsedHeader(const ParsedHeader&) = delete;
  ParsedHeader& operator=(const ParsedHeader&) = delete;
};

struct LoadedImage {
  EXRImage image;
  bool loaded = false;
  LoadedImage() { InitEXRImage(&image); }
  ~LoadedImage() {
    if (loaded) FreeEXRImage(&image);
  }
  LoadedImage(const LoadedImage&) = delete;
  LoadedImage& operator=(const LoadedImage&) = delete;
};

// Errors are one line: tinyexr's reasons can end in, or hold, line breaks.
std::string one_line(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s;
}

std::string take_error(const char* err, const char* fallback) {
  std::string s = err ? err : fallback;
  if (err) FreeEXRErrorMessage(err);
  return one_line(std::move(s));
}

// An attribute's name or type as read, for a message: one line of plain characters.
std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text.substr(0, 64)) out += (c >= 32 && c < 127) ? c : '?';
  return out;
}

std::string version_problem(int version) {
  return "partial format version " + std::to_string(version) + "; this inkray reads version " +
         std::to_string(kPartialVersion) + " only: render it again with this inkray";
}

// Reads the attributes of a parsed header into `info`; false with *error (no file name).
bool parse_attributes(const EXRHeader& h, PartialInfo* info, std::string* error) {
  std::map<std::string, ExrAttribute> found;
  for (int i = 0; i < h.num_custom_attributes; ++i) {
    const EXRAttribute& a = h.custom_attributes[i];
    std::string value =
        a.value && a.size > 0 ? std::string(reinterpret_cast<const char*>(a.value), size_t(a.size)) : "";
    found[a.name] = {a.type, std::move(value)};
  }
  const auto format = found.find("inkray.format");
  if (format == found.end() || format->second.type != "string" ||
      std::string_view(format->second.value.c_str()) != kPartialFormat) {
    *error = "not an inkray partial (an EXR without the inkray.format attribute \"inkray-partial\")";
    return false;
  }
  // Each attribute: present, of its type, of its size.
  const auto need = [&](const char* name, const char* type, size_t size, const std::string** value) {
    const auto it = found.find(name);
    if (it == found.end()) {
      *error = std::string("missing attribute ") + name + " (" + type + ")";
      return false;
    }
    if (it->second.type != type) {
      *error = std::string("attribute ") + name + " is of type " + printable(it->second.type) +
               ", expected " + type;
      return false;
    }
    if (size && it->second.value.size() != size) {
      *error = std::string("attribute ") + name + " has " + std::to_string(it->second.value.size()) +
               " bytes, expected " + std::to_string(size);
      return false;
    }
    *value = &it->second.value;
    return true;
  };
  const std::string* v = nullptr;
  if (!need("inkray.version", "int", 4, &v)) return false;
  const int version = int(get_u32(*v, 0));
  if (version != kPartialVersion) {
    *error = version_problem(version);
    return false;
  }
  if (!need("inkray.imageSize", "v2i", 8, &v)) return false;
  info->width = int(get_u32(*v, 0));
  info->height = int(get_u32(*v, 4));
  if (!need("inkray.window", "box2i", 16, &v)) return false;
  // Inclusive corners; as 64-bit, so a hostile maximum cannot overflow.
  const auto corner = [&](size_t at) { return int64_t(int32_t(get_u32(*v, at))); };
  const int64_t x0 = corner(0), y0 = corner(4), x1 = corner(8) + 1, y1 = corner(12) + 1;
  if (!need("inkray.samples", "v2i", 8, &v)) return false;
  const int first = int(get_u32(*v, 0)), end = int(get_u32(*v, 4));
  if (!need("inkray.frame", "float", 4, &v)) return false;
  const uint32_t frame_bits = get_u32(*v, 0);
  std::memcpy(&info->frame, &frame_bits, sizeof frame_bits);
  if (!need("inkray.seed", "int", 4, &v)) return false;
  info->seed = int(get_u32(*v, 0));
  if (!need("inkray.scene", "string", 0, &v)) return false;
  info->scene = v->c_str();
  // Bounded before anything parses it: merging compares scenes as JSON.
  if (std::string p = json_bounds_problem(info->scene, kMaxHeaderJsonDepth, kMaxSceneFileBytes); !p.empty()) {
    *error = "attribute inkray.scene " + p + " (expected a scene as inkray writes it)";
    return false;
  }
  if (!need("inkray.assets", "string", 0, &v)) return false;
  if (std::string p = assets_from_json(v->c_str(), &info->assets); !p.empty()) {
    *error = "attribute inkray.assets " + p + " (expected a JSON list of [path, hash] pairs)";
    return false;
  }
  if (!need("inkray.contentHash", "string", 16, &v)) return false;
  const auto content = parse_hash_hex(*v);
  if (!content || *content != scene_content_hash(info->scene, info->assets)) {
    *error = "attribute inkray.contentHash is not the hash of inkray.scene and inkray.assets";
    return false;
  }
  if (!need("inkray.aovs", "string", 0, &v)) return false;
  info->aovs = {};
  std::stringstream names(v->c_str());
  for (std::string name; std::getline(names, name, ',');) {
    const auto aov = aov_from_name(name);
    if (!aov || is_outline_aov(*aov)) {
      *error = "attribute inkray.aovs names \"" + printable(name) +
               "\", expected first-hit AOVs (albedo, normal, depth, "
               "object_id, material_id)";
      return false;
    }
    info->aovs.add(*aov);
  }
  if (!need("inkray.lines", "int", 4, &v)) return false;
  info->lines = get_u32(*v, 0) != 0;
  if (!need("inkray.nonfinite", "string", 0, &v)) return false;
  info->nonfinite = std::strtoull(v->c_str(), nullptr, 10);

  // What the numbers must be: inkray renders at most 8192 x 8192 pixels at once.
  constexpr int64_t kMaxSide = 16384, kMaxPixels = int64_t(8192) * 8192;
  if (info->width < 1 || info->height < 1 || info->width > kMaxSide || info->height > kMaxSide ||
      int64_t(info->width) * info->height > kMaxPixels) {
    *error = "image size " + std::to_string(info->width) + "x" + std::to_string(info->height) +
             " out of range (at most 8192x8192 pixels)";
    return false;
  }
  if (x1 <= x0 || y1 <= y0 || x0 < 0 || y0 < 0 || x1 > info->width || y1 > info->height) {
    *error = "window (" + std::to_string(x0) + "," + std::to_string(y0) + ")-(" + std::to_string(x1) + "," +
             std::to_string(y1) + ") is not inside the image";
    return false;
  }
  info->window = {int(x0), int(y0), int(x1), int(y1)};
  if (first < 0 || end < first) {
    *error = "sample range " + std::to_string(first) + "-" + std::to_string(end) + " is not a range";
    return false;
  }
  info->first_pass = uint32_t(first);
  info->end_pass = uint32_t(end);
  if (!std::isfinite(info->frame)) {
    *error = "attribute inkray.frame is not a number";
    return false;
  }
  info->tiles_done.clear();
  if (const auto it = found.find("inkray.passInProgress"); it != found.end()) {
    const int tiles_x = (info->width + 15) / 16, tiles_y = (info->height + 15) / 16;
    const std::string text = it->second.value.c_str();
    if (it->second.type != "string" || text.size() != size_t(tiles_x) * size_t(tiles_y) ||
        text.find_first_not_of("01") != std::string::npos) {
      *error = "attribute inkray.passInProgress is not a string of one 0 or 1 per 16x16 tile (" +
               std::to_string(tiles_x * tiles_y) + ")";
      return false;
    }
    for (const char c : text) info->tiles_done.push_back(c == '1');
  }
  if (info->end_pass == info->first_pass && info->tiles_done.empty()) {
    *error = "sample range " + std::to_string(first) + "-" + std::to_string(end) + " holds no sample";
    return false;
  }
  return true;
}

// 2^32 samples (a count's range) of the largest float.
constexpr double kMaxSum = 4294967296.0 * double(std::numeric_limits<float>::max());

// One EXR channel's words, as little-endian bytes in row order.
uint64_t plane_checksum(const uint32_t* words, size_t n) {
  ContentHash h;
  if constexpr (std::endian::native == std::endian::little) {
    h.add(std::string_view(reinterpret_cast<const char*>(words), 4 * n));
  } else {
    std::string le;
    for (size_t i = 0; i < n; ++i) put_u32(le, words[i]);
    h.add(le);
  }
  return h.digest();
}

// From the raw attributes: a partial (inkray.format) of this version (inkray.version),
// checked before the checksums so that an older partial, which has none, is named as
// such; "" when it is.
std::string raw_identity_problem(std::string_view bytes, const std::vector<RawAttribute>& raw) {
  const RawAttribute* format = nullptr;
  const RawAttribute* version = nullptr;
  for (const RawAttribute& a : raw) {
    if (a.name == "inkray.format") format = &a;
    if (a.name == "inkray.version") version = &a;
  }
  if (!format || format->type != "string" || bytes.substr(format->value_at, format->size) != kPartialFormat)
    return "not an inkray partial (an EXR without the inkray.format attribute \"inkray-partial\")";
  if (!version || version->type != "int" || version->size != 4)
    return "its header is damaged (no attribute inkray.version of type int)";
  const int v = int(get_u32(std::string(bytes.substr(version->value_at, 4)), 0));
  if (v != kPartialVersion) return version_problem(v);
  return "";
}

// Which channel a damaged file decodes differently from its inkray.channelChecksums.
std::string damaged_channel(const EXRHeader& h, const std::vector<ExrChannel>& exr,
                            const std::vector<int>& index, const EXRImage& image, size_t n,
                            const std::string& problem) {
  std::string stored;
  for (int i = 0; i < h.num_custom_attributes; ++i)
    if (std::string_view(h.custom_attributes[i].name) == "inkray.channelChecksums" &&
        h.custom_attributes[i].value)
      stored.assign(reinterpret_cast<const char*>(h.custom_attributes[i].value),
                    size_t(std::max(0, h.custom_attributes[i].size)));
  for (size_t c = 0; c < exr.size(); ++c) {
    const std::string want = stored.size() >= 17 * c + 16 ? stored.substr(17 * c, 16) : "";
    std::vector<uint32_t> words(n);
    std::memcpy(words.data(), image.images[index[c]], 4 * n);
    if (want != hash_hex(plane_checksum(words.data(), n)))
      return "its pixel data is damaged: channel " + exr[c].name + " does not match its checksum";
  }
  return problem + " (the offset table or the compressed bytes; every channel decodes as written)";
}

}  // namespace

// ---------------------------------------------------------------- messages

std::string first_hit_aov_names(const AovSet& aovs) {
  std::string s;
  for (size_t i = 0; i < size_t(Aov::outline); ++i)
    if (aovs.has(Aov(i))) s += (s.empty() ? "" : ",") + std::string(kAovNames[i]);
  return s;
}

std::string describe_window(const PixelWindow& w) {
  return "(" + std::to_string(w.x0) + "," + std::to_string(w.y0) + ")-(" + std::to_string(w.x1) + "," +
         std::to_string(w.y1) + ")";
}

std::string describe_range(uint32_t first, uint32_t end) {
  return std::to_string(first) + "-" + std::to_string(end);
}

std::string describe_partial(const PartialInfo& info) {
  return "samples " + describe_range(info.first_pass, info.end_pass) + " of pixels " +
         describe_window(info.window);
}

// ---------------------------------------------------------------- writing

bool encode_partial(const Film& film, const PartialInfo& info, std::string* bytes, std::string* error) {
  const PixelWindow& w = info.window;
  if (film.width() != info.width || film.height() != info.height || w.empty() || w.x0 < 0 || w.y0 < 0 ||
      w.x1 > film.width() || w.y1 > film.height()) {
    *error = "partial: the window " + describe_window(w) + " is not inside the film";
    return false;
  }
  PartialInfo held = info;
  held.aovs = film.aovs().first_hit();
  held.lines = film.has_lines();
  held.nonfinite = film.nonfinite_samples();
  const std::vector<PartialChannel> channels = partial_channels(held);
  const std::vector<ExrChannel> exr = exr_channels(channels);
  const size_t n = size_t(w.width()) * size_t(w.height());
  std::vector<std::vector<uint32_t>> planes(exr.size(), std::vector<uint32_t>(n));
  for (int y = 0; y < w.height(); ++y)
    for (int x = 0; x < w.width(); ++x) {
      const FilmPixel p = film.pixel(w.x0 + x, w.y0 + y);
      const size_t i = size_t(y) * size_t(w.width()) + size_t(x);
      for (size_t c = 0; c < exr.size(); ++c) {
        const PartialChannel& ch = channels[exr[c].channel];
        planes[c][i] = to_word(channel_value(p, ch.field, ch.component), ch.stored, exr[c].word);
      }
    }
  std::string checksums;
  for (size_t c = 0; c < exr.size(); ++c)
    checksums += (c ? "," : "") + hash_hex(plane_checksum(planes[c].data(), n));

  std::vector<ExrPlane> exr_planes;
  for (size_t c = 0; c < exr.size(); ++c)
    exr_planes.push_back({exr[c].name.c_str(), exr[c].pixel_type, planes[c].data()});
  // RLE: the sums' low words are noise that ZIP spends long on for little; RLE packs the
  // runs of zeros (lines, AOVs, empty pixels) at a third of ZIP's time, in twice its size.
  std::string reason;
  if (!encode_exr_planes(w.width(), w.height(), exr_planes, partial_attributes(held, checksums),
                         n < 256 ? ExrCompression::none : ExrCompression::rle, bytes, &reason)) {
    *error = "partial: EXR encoding failed (" + one_line(reason.empty() ? "no reason given" : reason) + ")";
    return false;
  }
  return seal_partial(bytes, error);
}

// ---------------------------------------------------------------- reading

bool read_partial(const std::filesystem::path& file, PartialInfo* info, std::unique_ptr<Film>* film,
                  std::string* error) {
  std::string bytes;
  if (!read_file_bytes(file, kMaxPartialBytes, &bytes, error)) return false;
  return read_partial_bytes(bytes, file.string(), info, film, error);
}

bool read_partial_bytes(std::string_view bytes, const std::string& label_text, PartialInfo* info,
                        std::unique_ptr<Film>* film, std::string* error) {
  const std::string label = label_text + ": ";
  // From the raw bytes first: what the file is, its version, then its checksums; a
  // decoder sees only a header whose bytes are those written.
  std::vector<RawAttribute> raw;
  size_t header_end = 0;
  std::string problem;
  if (!walk_exr_header(bytes, &raw, &header_end, &problem)) {
    *error = label + problem;
    return false;
  }
  if (std::string p = raw_identity_problem(bytes, raw); !p.empty()) {
    *error = label + p;
    return false;
  }
  const SealCheck seal = check_partial_seal(bytes, &problem);
  if (seal == SealCheck::header_damaged) {
    *error = label + problem;
    return false;
  }
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  EXRVersion version;
  if (ParseEXRVersionFromMemory(&version, data, bytes.size()) != TINYEXR_SUCCESS) {
    *error = label + "not an OpenEXR file (expected an inkray partial .exr)";
    return false;
  }
  if (version.multipart || version.non_image || version.tiled) {
    *error = label + "a multi-part, deep or tiled EXR, not an inkray partial";
    return false;
  }
  ParsedHeader parsed;
  const char* err = nullptr;
  if (ParseEXRHeaderFromMemory(&parsed.header, &version, data, bytes.size(), &err) != TINYEXR_SUCCESS) {
    *error = label + "broken EXR header (" + take_error(err, "unreadable") + ")";
    return false;
  }
  const EXRHeader& h = parsed.header;
  if (!parse_attributes(h, info, &problem)) {
    *error = label + problem;
    return false;
  }
  const PixelWindow& w = info->window;
  // As 64-bit: a hostile data window's corners are any two ints.
  const int64_t data_width = int64_t(h.data_window.max_x) - h.data_window.min_x + 1;
  const int64_t data_height = int64_t(h.data_window.max_y) - h.data_window.min_y + 1;
  if (data_width != w.width() || data_height != w.height()) {
    *error = label + "its pixels are " + std::to_string(data_width) + "x" + std::to_string(data_height) +
             ", expected the window's " + std::to_string(w.width()) + "x" + std::to_string(w.height());
    return false;
  }
  const std::vector<PartialChannel> channels = partial_channels(*info);
  const std::vector<ExrChannel> exr = exr_channels(channels);
  std::vector<int> index(exr.size(), -1);  // of each expected channel in the file
  for (size_t c = 0; c < exr.size(); ++c) {
    for (int k = 0; k < h.num_channels; ++k)
      if (exr[c].name == h.channels[k].name) index[c] = k;
    if (index[c] < 0) {
      *error = label + "missing channel " + exr[c].name;
      return false;
    }
    if (h.pixel_types[index[c]] != exr[c].pixel_type) {
      *error = label + "channel " + exr[c].name + " is not " +
               (exr[c].pixel_type == TINYEXR_PIXELTYPE_UINT ? "32-bit unsigned" : "32-bit float");
      return false;
    }
  }
  if (h.num_channels != int(exr.size())) {
    *error = label + "holds " + std::to_string(h.num_channels) + " channels, expected " +
             std::to_string(exr.size());
    return false;
  }
  if (!film && seal == SealCheck::intact) return true;
  // Partials are written uncompressed or RLE, which packs at most 128 bytes into 2: a
  // header claiming more pixels than the bytes after it can hold is refused before the
  // decoder allocates for them.
  if (h.compression_type != TINYEXR_COMPRESSIONTYPE_NONE &&
      h.compression_type != TINYEXR_COMPRESSIONTYPE_RLE) {
    *error = label + "compressed with EXR compression " + std::to_string(h.compression_type) +
             ", expected none or RLE as inkray writes partials";
    return false;
  }
  const uint64_t decoded_bytes = uint64_t(w.width()) * uint64_t(w.height()) * exr.size() * 4;
  if (decoded_bytes > 64 * uint64_t(bytes.size() - header_end) + 4096) {
    *error = label + (seal == SealCheck::data_damaged
                          ? problem
                          : "its " + std::to_string(w.width()) + "x" + std::to_string(w.height()) +
                                " pixels cannot fit in the " + std::to_string(bytes.size() - header_end) +
                                " bytes after its header (a truncated or damaged file)");
    return false;
  }

  // Every channel is read as the type it is stored in (tinyexr converts only half).
  for (int k = 0; k < h.num_channels; ++k) parsed.header.requested_pixel_types[k] = h.pixel_types[k];
  LoadedImage loaded;
  // tinyexr 1.0.1 frees the planes of pixels it failed to decode by this count, which it
  // sets only on success: set here, a damaged file leaks nothing.
  loaded.image.num_channels = h.num_channels;
  const bool decoded =
      LoadEXRImageFromMemory(&loaded.image, &parsed.header, data, bytes.size(), &err) == TINYEXR_SUCCESS;
  if (!decoded) {
    const std::string why = take_error(err, "truncated or damaged");
    *error = label + (seal == SealCheck::data_damaged ? problem + "; cannot decode it: " + why
                                                      : "cannot read the pixels (" + why + ")");
    return false;
  }
  loaded.loaded = true;
  if (loaded.image.width != w.width() || loaded.image.height != w.height() || !loaded.image.images) {
    *error = label +
             (seal == SealCheck::data_damaged ? problem : "cannot read the pixels (a tiled or damaged file)");
    return false;
  }
  const size_t n = size_t(w.width()) * size_t(w.height());
  if (seal == SealCheck::data_damaged) {
    // The header is intact, so its per-channel checksums name what the damage changed.
    *error = label + damaged_channel(h, exr, index, loaded.image, n, problem);
    return false;
  }
  auto out = std::make_unique<Film>(w.width(), w.height(), info->aovs, info->lines);
  const auto word = [&](size_t c, size_t i) {
    uint32_t v;
    std::memcpy(&v, loaded.image.images[index[c]] + 4 * i, sizeof v);
    return v;
  };
  for (int y = 0; y < w.height(); ++y)
    for (int x = 0; x < w.width(); ++x) {
      const size_t i = size_t(y) * size_t(w.width()) + size_t(x);
      FilmPixel p;
      for (size_t c = 0; c < exr.size(); ++c) {
        const PartialChannel& ch = channels[exr[c].channel];
        if (exr[c].word == 1 || ch.field == PartialField::preview)
          continue;  // low words come with their high word
        uint32_t lo = 0;
        if (ch.stored == PartialStored::f64) lo = word(exr[c].low, i);
        const double v = from_words(word(c, i), lo, ch.stored);
        // A film never sums what is not finite (Film drops such samples): one that
        // does would spread Inf or NaN through the merged image. Nor can it sum more
        // than 2^32 floats' worth: a larger sum would overflow when halves or
        // partials are added.
        if (!std::isfinite(v) || std::abs(v) > kMaxSum) {
          *error = label + "channel " + ch.name + " holds " +
                   (std::isfinite(v) ? "a value larger than any film sums" : "a non-finite value") +
                   " at pixel (" + std::to_string(w.x0 + x) + "," + std::to_string(w.y0 + y) + ")";
          return false;
        }
        set_channel_value(p, ch.field, ch.component, v);
      }
      out->add_pixel(x, y, p);
    }
  out->add_nonfinite(info->nonfinite);
  if (film) *film = std::move(out);
  return true;
}

}  // namespace inkray
