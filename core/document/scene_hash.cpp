// Asset bytes are hashed each time a partial is written: at about a byte per cycle, a
// 100 MB mesh costs a tenth of a second, against minutes of rendering between checkpoints.
#include "core/document/scene_hash.h"

#include "core/document/json_io.h"
#include "core/document/scene_checks.h"
#include "core/io/json_bounds.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace inkray {

std::vector<AssetHash> hash_scene_assets(const SceneDesc& scene) {
  std::vector<AssetHash> out;
  for (const AssetRef& a : collect_assets(scene)) {
    if (a.written.empty() || a.written.find('\0') != std::string::npos) continue;
    if (std::any_of(out.begin(), out.end(), [&](const AssetHash& h) { return h.path == a.written; }))
      continue;
    std::string error;
    const auto hash = hash_file(scene.base_dir / a.written, &error);
    out.push_back({a.written, hash ? hash_hex(*hash) : std::string("missing")});
  }
  return out;
}

std::string comparable_scene_text(std::string_view text) {
  if (!json_bounds_problem(text, kMaxHeaderJsonDepth, kMaxSceneFileBytes).empty()) return std::string(text);
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded()) return std::string(text);
  if (j.is_object() && j.contains("render") && j["render"].is_object()) {
    j["render"].erase("spp");
    j["render"].erase("time_limit");
  }
  // Replaced, not thrown on: a scene with invalid UTF-8 still hashes (and then differs).
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string assets_to_json(const std::vector<AssetHash>& assets) {
  nlohmann::json list = nlohmann::json::array();
  for (const AssetHash& a : assets) list.push_back({a.path, a.digest});
  return list.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string assets_from_json(std::string_view text, std::vector<AssetHash>* assets) {
  // Two levels: a list of pairs. The bound is that of the scene, whose paths they are.
  if (std::string p = json_bounds_problem(text, 2, kMaxSceneFileBytes); !p.empty()) return p;
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_array()) return "is not a JSON list";
  assets->clear();
  for (const nlohmann::json& e : j) {
    if (!e.is_array() || e.size() != 2 || !e[0].is_string() || !e[1].is_string())
      return "holds an entry that is not a [path, hash] pair";
    AssetHash a{e[0].get<std::string>(), e[1].get<std::string>()};
    if (a.digest != "missing" && !parse_hash_hex(a.digest)) return "holds a hash that is not 16 hex digits";
    assets->push_back(std::move(a));
  }
  return "";
}

uint64_t scene_content_hash(std::string_view scene_text, const std::vector<AssetHash>& assets) {
  ContentHash h;
  h.add_field(comparable_scene_text(scene_text));
  h.add_u64(assets.size());
  for (const AssetHash& a : assets) h.add_field(a.path).add_field(a.digest);
  return h.digest();
}

}  // namespace inkray
