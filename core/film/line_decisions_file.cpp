#include "core/film/line_decisions_file.h"

#include "core/io/file_bytes.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>

namespace inkray {
namespace {

constexpr int64_t kMaxSide = 16384, kMaxPixels = int64_t(8192) * 8192;  // as partials
constexpr size_t kMaxHeaderBytes = size_t(64) << 20;                     // the scene's text, bounded as scene files

void put_u32(std::string& s, uint32_t v) {
  for (int b = 0; b < 4; ++b) s.push_back(char((v >> (8 * b)) & 0xffu));
}

// The first line, the header's JSON and where the pixels start; false with *error.
bool split_lines(const std::string& bytes, std::string* first, std::string* header, size_t* pixels,
                 std::string* error) {
  const size_t a = bytes.find('\n');
  if (a == std::string::npos || a > 64) {
    *error = "not a line decision file (expected a first line \"" + std::string(kLineDecisionsFormat) + " " +
             std::to_string(kLineDecisionsVersion) + "\")";
    return false;
  }
  *first = bytes.substr(0, a);
  const size_t b = bytes.find('\n', a + 1);
  if (b == std::string::npos || b - a - 1 > kMaxHeaderBytes) {
    *error = "no header line after the first (expected a line of JSON)";
    return false;
  }
  *header = bytes.substr(a + 1, b - a - 1);
  *pixels = b + 1;
  return true;
}

bool parse(const std::string& bytes, PartialInfo* info, LineDecisions* d, std::string* error) {
  std::string first, header;
  size_t at = 0;
  if (!split_lines(bytes, &first, &header, &at, error)) return false;
  const std::string format(kLineDecisionsFormat);
  if (first.rfind(format + " ", 0) != 0) {
    *error = "not a line decision file (expected a first line \"" + format + " " +
             std::to_string(kLineDecisionsVersion) + "\")";
    return false;
  }
  if (first != format + " " + std::to_string(kLineDecisionsVersion)) {
    *error = "line decision format \"" + first.substr(format.size() + 1, 16) + "\"; this inkray reads version " +
             std::to_string(kLineDecisionsVersion);
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
      *error = std::string("header: ") + key + (it == j.end() ? " is missing" : " is not " + std::string(what)) +
               " (expected " + what + ")";
      return false;
    }
    return true;
  };
  if (!need("width", &nlohmann::json::is_number_integer, "an integer") ||
      !need("height", &nlohmann::json::is_number_integer, "an integer") ||
      !need("frame", &nlohmann::json::is_number, "a number") ||
      !need("seed", &nlohmann::json::is_number_integer, "an integer") ||
      !need("decided_at", &nlohmann::json::is_number_unsigned, "a sample count") ||
      !need("scene", &nlohmann::json::is_string, "a string"))
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
  if (!std::isfinite(frame) || std::abs(frame) > 1e7 || seed < 0 || seed > 2147483647 || decided_at > (1u << 30)) {
    *error = "header: frame, seed or decided_at out of range";
    return false;
  }
  const size_t n = size_t(width) * size_t(height);
  // A scene without lines has no pixels to keep.
  const bool pixels = bytes.size() > at;
  if (pixels && bytes.size() - at != 5 * n) {
    *error = "holds " + std::to_string(bytes.size() - at) + " bytes of pixels, expected " + std::to_string(5 * n) +
             " (a truncated or damaged file)";
    return false;
  }
  d->width = int(width);
  d->height = int(height);
  d->decided_at = uint32_t(decided_at);
  d->rays.assign(pixels ? n : 0, 0);
  d->kinds.assign(pixels ? n : 0, LineKind::probing);
  for (size_t i = 0; pixels && i < n; ++i) {
    const auto* w = reinterpret_cast<const unsigned char*>(bytes.data() + at + 4 * i);
    d->rays[i] = uint32_t(w[0]) | uint32_t(w[1]) << 8 | uint32_t(w[2]) << 16 | uint32_t(w[3]) << 24;
    const auto kind = uint8_t(bytes[at + 4 * n + i]);
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
  info->scene = j["scene"].get<std::string>();
  info->aovs = {};
  info->lines = pixels;
  info->nonfinite = 0;
  return true;
}

}  // namespace

std::string encode_line_decisions(const LineDecisions& d, const PartialInfo& info) {
  const nlohmann::json header = {{"width", d.width},         {"height", d.height}, {"frame", info.frame},
                                 {"seed", info.seed},        {"decided_at", d.decided_at},
                                 {"scene", info.scene}};
  std::string s = std::string(kLineDecisionsFormat) + " " + std::to_string(kLineDecisionsVersion) + "\n" +
                  header.dump() + "\n";
  s.reserve(s.size() + 5 * d.rays.size());
  for (const uint32_t r : d.rays) put_u32(s, r);
  for (const LineKind k : d.kinds) s.push_back(char(k));
  return s;
}

bool read_line_decisions(const std::filesystem::path& file, PartialInfo* info, LineDecisions* decisions,
                         std::string* error) {
  std::string bytes;
  if (!read_file_bytes(file, kMaxHeaderBytes + 64 + 5 * uint64_t(kMaxPixels), &bytes, error)) return false;
  std::string problem;
  if (!parse(bytes, info, decisions, &problem)) {
    *error = file.string() + ": " + problem;
    return false;
  }
  return true;
}

}  // namespace inkray
