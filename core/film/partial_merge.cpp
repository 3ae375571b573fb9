#include "core/film/partial_merge.h"

#include "core/document/scene_hash.h"
#include "core/io/json_bounds.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <numeric>
#include <sstream>

namespace inkray {
namespace {

// The first place two JSON values differ, as "path: a vs b"; "" when equal.
std::string json_difference(const nlohmann::json& a, const nlohmann::json& b, const std::string& path) {
  const auto at = [&](const std::string& key) { return path.empty() ? key : path + "/" + key; };
  if (a.is_object() && b.is_object()) {
    std::vector<std::string> keys;
    for (const auto& [k, v] : a.items()) keys.push_back(k);
    for (const auto& [k, v] : b.items())
      if (!a.contains(k)) keys.push_back(k);
    for (const std::string& k : keys) {
      if (!a.contains(k)) return at(k) + ": missing vs present";
      if (!b.contains(k)) return at(k) + ": present vs missing";
      if (std::string d = json_difference(a[k], b[k], at(k)); !d.empty()) return d;
    }
    return "";
  }
  if (a.is_array() && b.is_array()) {
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
      if (std::string d = json_difference(a[i], b[i], at(std::to_string(i))); !d.empty()) return d;
    if (a.size() != b.size())
      return (path.empty() ? "the list" : path) + ": " + std::to_string(a.size()) + " vs " +
             std::to_string(b.size()) + " entries";
    return "";
  }
  if (a == b) return "";
  const auto text = [](const nlohmann::json& j) {
    std::string s = j.dump();
    return s.size() > 60 ? s.substr(0, 57) + "..." : s;
  };
  return (path.empty() ? "the document" : path) + ": " + text(a) + " vs " + text(b);
}

// A scene as compared (scene_hash.h), as JSON; discarded when it is not JSON within
// json_bounds' limits (json_difference recurses as deep as the scene nests).
nlohmann::json comparable_scene(const std::string& text) {
  if (!json_bounds_problem(text, kMaxHeaderJsonDepth, text.size()).empty())
    return nlohmann::json::value_t::discarded;
  return nlohmann::json::parse(comparable_scene_text(text), nullptr, false);
}

// The first asset whose path or bytes differ, as "meshes/bunny.obj changed (...)"; "" when none.
std::string asset_difference(const std::vector<AssetHash>& a, const std::vector<AssetHash>& b) {
  for (const AssetHash& x : a) {
    const auto y = std::find_if(b.begin(), b.end(), [&](const AssetHash& h) { return h.path == x.path; });
    if (y == b.end()) return "the asset " + x.path + " is read by one and not by the other";
    if (y->digest != x.digest)
      return "the asset " + x.path + " changed between them (its bytes hash " + x.digest + " vs " +
             y->digest + ")";
  }
  for (const AssetHash& y : b)
    if (std::none_of(a.begin(), a.end(), [&](const AssetHash& h) { return h.path == y.path; }))
      return "the asset " + y.path + " is read by one and not by the other";
  return "";
}

PixelWindow intersect(const PixelWindow& a, const PixelWindow& b) {
  return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

}  // namespace

std::string partial_mismatch(const PartialInfo& a, const PartialInfo& b) {
  if (a.width != b.width || a.height != b.height)
    return "image size " + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " +
           std::to_string(b.width) + "x" + std::to_string(b.height);
  if (a.frame != b.frame) {
    std::ostringstream s;
    s << "frame " << a.frame << " vs " << b.frame;
    return s.str();
  }
  if (a.seed != b.seed) return "seed " + std::to_string(a.seed) + " vs " + std::to_string(b.seed);
  if (a.aovs.bits != b.aovs.bits) {
    const auto list = [](const AovSet& s) {
      const std::string names = first_hit_aov_names(s);
      return names.empty() ? std::string("none") : names;
    };
    return "AOVs " + list(a.aovs) + " vs " + list(b.aovs);
  }
  if (a.scene != b.scene) {
    const nlohmann::json ja = comparable_scene(a.scene), jb = comparable_scene(b.scene);
    if (ja.is_discarded() || jb.is_discarded()) return "the scene is not JSON";
    if (std::string d = json_difference(ja, jb, ""); !d.empty()) return "the scene differs at " + d;
  }
  if (std::string d = asset_difference(a.assets, b.assets); !d.empty()) return d;
  // The content hash covers both; it differs here only where the comparisons above
  // see no difference (the same assets listed in another order), and costs a parse of
  // each scene, so it is computed only then.
  if (!(a.assets == b.assets) &&
      scene_content_hash(a.scene, a.assets) != scene_content_hash(b.scene, b.assets))
    return "the scene content differs (content hash " + hash_hex(scene_content_hash(a.scene, a.assets)) +
           " vs " + hash_hex(scene_content_hash(b.scene, b.assets)) + ")";
  if (a.lines != b.lines)
    return std::string("lines ") + (a.lines ? "on" : "off") + " vs " + (b.lines ? "on" : "off");
  return "";
}

bool merge_partials(const std::vector<std::filesystem::path>& files, bool whole, MergedFilm* merged,
                    std::string* error) {
  if (files.empty()) {
    *error = "no partial files given";
    return false;
  }
  std::vector<PartialInfo> infos(files.size());
  for (size_t i = 0; i < files.size(); ++i) {
    if (!read_partial(files[i], &infos[i], nullptr, error)) return false;
    if (!infos[i].tiles_done.empty()) {
      *error = files[i].string() + ": a checkpoint cut in the middle of pass " +
               std::to_string(infos[i].end_pass) + "; finish it with inkray-render --resume before merging";
      return false;
    }
    if (i == 0) continue;
    if (std::string d = partial_mismatch(infos[0], infos[i]); !d.empty()) {
      *error = files[0].string() + " and " + files[i].string() + " are of different renders: " + d;
      return false;
    }
  }
  for (size_t i = 0; i < files.size(); ++i)
    for (size_t j = i + 1; j < files.size(); ++j) {
      const PixelWindow both = intersect(infos[i].window, infos[j].window);
      const uint32_t first = std::max(infos[i].first_pass, infos[j].first_pass);
      const uint32_t end = std::min(infos[i].end_pass, infos[j].end_pass);
      if (!both.empty() && first < end) {
        *error = files[i].string() + " and " + files[j].string() + " both hold samples " +
                 describe_range(first, end) + " of pixels " + describe_window(both) +
                 (files[i] == files[j] ? " (the same file twice)" : "");
        return false;
      }
    }

  // Per pixel: the samples held, and the first and last pass.
  const int width = infos[0].width, height = infos[0].height;
  const size_t n = size_t(width) * size_t(height);
  std::vector<uint32_t> samples(n, 0), lowest(n, UINT32_MAX), highest(n, 0);
  for (const PartialInfo& p : infos)
    for (int y = p.window.y0; y < p.window.y1; ++y)
      for (int x = p.window.x0; x < p.window.x1; ++x) {
        const size_t i = size_t(y) * size_t(width) + size_t(x);
        samples[i] += p.end_pass - p.first_pass;
        lowest[i] = std::min(lowest[i], p.first_pass);
        highest[i] = std::max(highest[i], p.end_pass);
      }
  PixelWindow covered{width, height, 0, 0};
  size_t uncovered = 0;
  PixelWindow missing{width, height, 0, 0};
  merged->min_samples = UINT32_MAX;
  merged->max_samples = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      if (lowest[i] == UINT32_MAX) {
        ++uncovered;
        missing = {std::min(missing.x0, x), std::min(missing.y0, y), std::max(missing.x1, x + 1),
                   std::max(missing.y1, y + 1)};
        continue;
      }
      covered = {std::min(covered.x0, x), std::min(covered.y0, y), std::max(covered.x1, x + 1),
                 std::max(covered.y1, y + 1)};
      merged->min_samples = std::min(merged->min_samples, samples[i]);
      merged->max_samples = std::max(merged->max_samples, samples[i]);
      if (samples[i] != highest[i] - lowest[i] || (whole && lowest[i] != 0)) {
        // Name the gap: the passes below the lowest, or between two partials.
        std::vector<std::pair<uint32_t, uint32_t>> ranges;
        for (const PartialInfo& p : infos)
          if (p.window.contains(x, y)) ranges.push_back({p.first_pass, p.end_pass});
        std::sort(ranges.begin(), ranges.end());
        uint32_t gap_first = 0, gap_end = ranges.front().first;
        if (!(whole && gap_end > 0))
          for (size_t r = 0; r + 1 < ranges.size(); ++r)
            if (ranges[r].second != ranges[r + 1].first) {
              gap_first = ranges[r].second;
              gap_end = ranges[r + 1].first;
              break;
            }
        *error = "no partial holds samples " + describe_range(gap_first, gap_end) + " of pixel (" +
                 std::to_string(x) + "," + std::to_string(y) + ")" +
                 (whole ? "" : " between the samples the others hold");
        return false;
      }
    }
  if (whole && uncovered) {
    *error = std::to_string(uncovered) + " pixels are in no partial, within " + describe_window(missing) +
             " of the " + std::to_string(width) + "x" + std::to_string(height) + " image";
    return false;
  }
  if (!whole) {
    for (int y = covered.y0; y < covered.y1; ++y)
      for (int x = covered.x0; x < covered.x1; ++x) {
        const size_t i = size_t(y) * size_t(width) + size_t(x);
        const size_t c = size_t(covered.y0) * size_t(width) + size_t(covered.x0);
        if (lowest[i] != lowest[c] || highest[i] != highest[c]) {
          *error = "a partial holds one window and one range of samples, but pixel (" + std::to_string(x) +
                   "," + std::to_string(y) + ") of " + describe_window(covered) +
                   (lowest[i] == UINT32_MAX ? " is in no partial"
                                            : " holds samples " + describe_range(lowest[i], highest[i])) +
                   " and pixel (" + std::to_string(covered.x0) + "," + std::to_string(covered.y0) +
                   ") samples " + describe_range(lowest[c], highest[c]);
          return false;
        }
      }
  }

  // Earlier passes first: ids stay those of each pixel's first sample, and sums
  // add in the order one render would have added them.
  std::vector<size_t> order(files.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return infos[a].first_pass < infos[b].first_pass; });
  merged->film = std::make_unique<Film>(width, height, infos[0].aovs, infos[0].lines);
  uint64_t nonfinite = 0;
  for (const size_t k : order) {
    PartialInfo again;
    std::unique_ptr<Film> part;
    if (!read_partial(files[k], &again, &part, error)) return false;
    const PixelWindow& w = again.window;
    for (int y = 0; y < w.height(); ++y)
      for (int x = 0; x < w.width(); ++x) merged->film->add_pixel(w.x0 + x, w.y0 + y, part->pixel(x, y));
    nonfinite += again.nonfinite;
  }
  merged->film->add_nonfinite(nonfinite);
  merged->info = infos[0];
  merged->info.window = covered;
  merged->info.first_pass = *std::min_element(lowest.begin(), lowest.end());
  merged->info.end_pass = *std::max_element(highest.begin(), highest.end());
  merged->info.nonfinite = nonfinite;
  return true;
}

}  // namespace inkray
