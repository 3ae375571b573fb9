// Checked in the order the bytes come: the format and version line, the checksums
// line, the header line against its checksum (before any JSON parser sees it), the
// pixels against theirs, and only then what the header says.
#include "core/film/line_decisions_file.h"

#include "core/document/json_io.h"
#include "core/document/scene_hash.h"
#include "core/io/content_hash.h"
#include "core/io/file_bytes.h"
#include "core/io/json_bounds.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>

namespace inkray {
namespace {

constexpr int64_t kMaxSide = 16384, kMaxPixels = int64_t(8192) * 8192;  // as partials
// The scene's text, bounded as scene files, its assets' list and the other keys.
constexpr size_t kMaxHeaderBytes = 2 * size_t(kMaxSceneFileBytes) + 4096;
constexpr std::string_view kChecksums = "checksums ";

void put_u32(std::string& s, uint32_t v) {
  for (int b = 0; b < 4; ++b) s.push_back(char((v >> (8 * b)) & 0xffu));
}

std::string first_line_expected() {
  return "expected a first line \"" + std::string(kLineDecisionsFormat) + " " +
         std::to_string(kLineDecisionsVersion) + "\"";
}

// The line starting at *at, of at most `longest` bytes, without its '\n'; advances past it.
bool next_line(std::string_view bytes, size_t* at, size_t longest, std::string_view* line) {
  const size_t end = bytes.find('\n', *at);
  if (end == std::string_view::npos || end - *at > longest) return false;
  *line = bytes.substr(*at, end - *at);
  *at = end + 1;
  return true;
}

bool parse(std::string_view bytes, PartialInfo* info, LineDecisions* d, std::string* error) {
  size_t at = 0;
  std::string_view first, sums, header;
  const std::string format(kLineDecisionsFormat);
  if (!next_line(bytes, &at, 64, &first) || first.substr(0, format.size() + 1) != format + " ") {
    *error = "not a line decision file (" + first_line_expected() + ")";
    return false;
  }
  if (first != format + " " + std::to_string(kLineDecisionsVersion)) {
    std::string version;
    for (const char c : first.substr(format.size() + 1, 16)) version += (c >= 32 && c < 127) ? c : '?';
    *error = "line decision format version \"" + version + "\"; this inkray reads version " +
             std::to_string(kLineDecisionsVersion) +
             " only: decide the lines again (inkray-render --decide-lines)";
    return false;
  }
  // "checksums " + 16 hex + " " + 16 hex.
  std::optional<uint64_t> header_sum, pixel_sum;
  if (next_line(bytes, &at, 64, &sums) && sums.size() == kChecksums.size() + 33 &&
      sums.substr(0, kChecksums.size()) == kChecksums && sums[kChecksums.size() + 16] == ' ') {
    header_sum = parse_hash_hex(sums.substr(kChecksums.size(), 16));
    pixel_sum = parse_hash_hex(sums.substr(kChecksums.size() + 17, 16));
  }
  if (!header_sum || !pixel_sum) {
    *error = "its checksums line is damaged (expected \"checksums\" and two hashes of 16 hex digits)";
    return false;
  }
  if (!next_line(bytes, &at, kMaxHeaderBytes, &header)) {
    *error = "its header line is damaged or missing (expected a line of JSON of at most " +
             std::to_string(kMaxHeaderBytes) + " bytes after the checksums)";
    return false;
  }
  if (content_hash(header) != *header_sum) {
    *error = "its header line is damaged (it does not match its checksum)";
    return false;
  }
  const std::string_view pixel_bytes = bytes.substr(at);
  if (content_hash(pixel_bytes) != *pixel_sum) {
    *error = "its pixels are damaged or truncated (they do not match their checksum)";
    return false;
  }
  // One object of plain values and a list of pairs: nothing nests deeper than 3.
  if (std::string p = json_bounds_problem(header, 3, kMaxHeaderBytes); !p.empty()) {
    *error = "the header line " + p + " (expected the JSON object inkray writes)";
    return false;
  }
  const nlohmann::json j = nlohmann::json::parse(header, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    *error = "the header line is not a JSON object";
    return false;
  }
  // Each key: present and of its kind.
  const auto need = [&](const char* key, bool (nlohmann::json::*is)() const noexcept, const char* what) {
    const auto it = j.find(key);
    if (it == j.end() || !((*it).*is)()) {
      *error = std::string("header: ") + key +
               (it == j.end() ? " is missing" : " is not " + std::string(what)) + " (expected " + what + ")";
      return false;
    }
    return true;
  };
  if (!need("width", &nlohmann::json::is_number_integer, "an integer") ||
      !need("height", &nlohmann::json::is_number_integer, "an integer") ||
      !need("frame", &nlohmann::json::is_number, "a number") ||
      !need("seed", &nlohmann::json::is_number_integer, "an integer") ||
      !need("decided_at", &nlohmann::json::is_number_unsigned, "a sample count") ||
      !need("scene", &nlohmann::json::is_string, "a string") ||
      !need("assets", &nlohmann::json::is_array, "a list of [path, hash] pairs") ||
      !need("content", &nlohmann::json::is_string, "a string"))
    return false;
  const int64_t width = j["width"].get<int64_t>(), height = j["height"].get<int64_t>();
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide || width * height > kMaxPixels) {
    *error = "header: image size " + std::to_string(width) + "x" + std::to_string(height) +
             " out of range (at most 8192x8192 pixels)";
    return false;
  }
  const double frame = j["frame"].get<double>();
  const int64_t seed = j["seed"].get<int64_t>();
  const uint64_t decided_at = j["decided_at"].get<uint64_t>();
  if (!std::isfinite(frame) || std::abs(frame) > 1e7 || seed < 0 || seed > 2147483647 ||
      decided_at > (1u << 30)) {
    *error = "header: frame, seed or decided_at out of range";
    return false;
  }
  std::string scene = j["scene"].get<std::string>();
  if (std::string p = json_bounds_problem(scene, kMaxHeaderJsonDepth, kMaxSceneFileBytes); !p.empty()) {
    *error = "header: the scene " + p + " (expected a scene as inkray writes it)";
    return false;
  }
  std::vector<AssetHash> assets;
  if (std::string p = assets_from_json(j["assets"].dump(), &assets); !p.empty()) {
    *error = "header: assets " + p + " (expected a list of [path, hash] pairs)";
    return false;
  }
  const auto content = parse_hash_hex(j["content"].get<std::string>());
  if (!content || *content != scene_content_hash(scene, assets)) {
    *error = "header: content is not the hash of the scene and its assets";
    return false;
  }
  const size_t n = size_t(width) * size_t(height);
  // A scene without lines has no pixels to keep.
  const bool pixels = !pixel_bytes.empty();
  if (pixels && pixel_bytes.size() != 5 * n) {
    *error =
        "holds " + std::to_string(pixel_bytes.size()) + " bytes of pixels, expected " + std::to_string(5 * n);
    return false;
  }
  d->width = int(width);
  d->height = int(height);
  d->decided_at = uint32_t(decided_at);
  d->rays.assign(pixels ? n : 0, 0);
  d->kinds.assign(pixels ? n : 0, LineKind::probing);
  for (size_t i = 0; pixels && i < n; ++i) {
    const auto* w = reinterpret_cast<const unsigned char*>(pixel_bytes.data() + 4 * i);
    d->rays[i] = uint32_t(w[0]) | uint32_t(w[1]) << 8 | uint32_t(w[2]) << 16 | uint32_t(w[3]) << 24;
    const auto kind = uint8_t(pixel_bytes[4 * n + i]);
    if (kind > uint8_t(LineKind::edge) || LineKind(kind) == LineKind::finding) {
      *error = "pixel (" + std::to_string(i % size_t(width)) + "," + std::to_string(i / size_t(width)) +
               ") has kind " + std::to_string(kind) + ", expected a decided one (0, 1, 3, 4 or 5)";
      return false;
    }
    d->kinds[i] = LineKind(kind);
  }
  info->width = int(width);
  info->height = int(height);
  info->window = {0, 0, int(width), int(height)};
  info->first_pass = 0;
  info->end_pass = d->decided_at;
  info->tiles_done.clear();
  info->frame = float(frame);
  info->seed = int(seed);
  info->scene = std::move(scene);
  info->assets = std::move(assets);
  info->aovs = {};
  info->lines = pixels;
  info->nonfinite = 0;
  return true;
}

}  // namespace

std::string encode_line_decisions(const LineDecisions& d, const PartialInfo& info) {
  const auto error_handler = nlohmann::json::error_handler_t::replace;
  const nlohmann::json header = {{"width", d.width},
                                 {"height", d.height},
                                 {"frame", info.frame},
                                 {"seed", info.seed},
                                 {"decided_at", d.decided_at},
                                 {"scene", info.scene},
                                 {"assets", nlohmann::json::parse(assets_to_json(info.assets))},
                                 {"content", hash_hex(scene_content_hash(info.scene, info.assets))}};
  const std::string header_line = header.dump(-1, ' ', false, error_handler);
  std::string pixels;
  pixels.reserve(5 * d.rays.size());
  for (const uint32_t r : d.rays) put_u32(pixels, r);
  for (const LineKind k : d.kinds) pixels.push_back(char(k));
  return std::string(kLineDecisionsFormat) + " " + std::to_string(kLineDecisionsVersion) + "\n" +
         std::string(kChecksums) + hash_hex(content_hash(header_line)) + " " +
         hash_hex(content_hash(pixels)) + "\n" + header_line + "\n" + pixels;
}

bool read_line_decisions_bytes(std::string_view bytes, const std::string& label, PartialInfo* info,
                               LineDecisions* decisions, std::string* error) {
  std::string problem;
  if (!parse(bytes, info, decisions, &problem)) {
    *error = label + ": " + problem;
    return false;
  }
  return true;
}

bool read_line_decisions(const std::filesystem::path& file, PartialInfo* info, LineDecisions* decisions,
                         std::string* error) {
  std::string bytes;
  if (!read_file_bytes(file, kMaxHeaderBytes + 256 + 5 * uint64_t(kMaxPixels), &bytes, error)) return false;
  return read_line_decisions_bytes(bytes, file.string(), info, decisions, error);
}

}  // namespace inkray
