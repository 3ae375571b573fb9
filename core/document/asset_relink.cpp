// Relinking resolves every path the way the compiler does (base_dir / written) and
// compares files by their absolute, normalised path, so "tex/a.png" and
// "./tex/../tex/a.png" are one file.
#include "core/document/asset_relink.h"

#include <algorithm>
#include <map>
#include <system_error>

namespace inkray {
namespace {

namespace fs = std::filesystem;

fs::path scene_folder(const SceneDesc& scene) {
  std::error_code ec;
  const fs::path folder = scene.base_dir.empty() ? fs::current_path(ec) : fs::absolute(scene.base_dir, ec);
  return folder.lexically_normal();
}

// Empty for a path no file can have (an embedded NUL: the OS would read a shorter one).
fs::path resolve(const fs::path& folder, const std::string& written) {
  if (written.find('\0') != std::string::npos) return {};
  return (folder / fs::path(written)).lexically_normal();
}

bool is_file(const fs::path& file) {
  std::error_code ec;
  return fs::is_regular_file(file, ec);
}

// How the document writes `file`: relative to its folder when there is a relative form.
std::string written_for(const fs::path& file, const fs::path& folder) {
  const fs::path relative = file.lexically_relative(folder);
  return (relative.empty() ? file : relative).generic_string();
}

}  // namespace

std::vector<AssetReference> list_asset_references(const SceneDesc& scene) {
  const fs::path folder = scene_folder(scene);
  std::vector<AssetReference> references;
  std::map<fs::path, bool> on_disk;  // a file many objects share is looked up once
  for_each_asset_path(scene, [&](const AssetSite& site, const std::string& path) {
    if (!site.in_use || path.empty()) return;
    const fs::path resolved = resolve(folder, path);
    if (resolved.empty()) return;
    const auto [it, added] = on_disk.try_emplace(resolved, false);
    if (added) it->second = is_file(resolved);
    references.push_back({site, path, resolved, it->second});
  });
  return references;
}

std::vector<MissingAsset> missing_assets(const std::vector<AssetReference>& references) {
  std::vector<MissingAsset> missing;
  for (const AssetReference& r : references) {
    if (r.exists) continue;
    auto it = std::find_if(missing.begin(), missing.end(),
                           [&](const MissingAsset& m) { return m.resolved == r.resolved; });
    if (it == missing.end()) it = missing.insert(missing.end(), {r.written, r.resolved, r.site.type, {}});
    if (std::find(it->users.begin(), it->users.end(), r.site.user) == it->users.end())
      it->users.push_back(r.site.user);
  }
  return missing;
}

std::string users_text(const std::vector<std::string>& users) {
  std::string text;
  for (const std::string& user : users) text += (text.empty() ? "" : ", ") + user;
  return text;
}

std::string describe(const MissingAsset& missing) {
  return "file not found: " + missing.written + " (resolved to " + missing.resolved.string() + "), used by " +
         users_text(missing.users);
}

std::vector<MissingAsset> missing_assets(const SceneDesc& scene) {
  return missing_assets(list_asset_references(scene));
}

size_t relink(SceneDesc& scene, const std::string& missing_path, const fs::path& chosen_file) {
  const fs::path folder = scene_folder(scene);
  const fs::path lost = resolve(folder, missing_path);
  std::error_code ec;
  const fs::path chosen = fs::absolute(chosen_file, ec).lexically_normal();
  if (lost.empty() || ec) return 0;
  const fs::path found_in = chosen.parent_path();
  size_t changed = 0;
  for_each_asset_path(scene, [&](const AssetSite& site, std::string& path) {
    if (!site.in_use || path.empty()) return;
    const fs::path resolved = resolve(folder, path);
    if (resolved.empty()) return;
    fs::path target;
    if (resolved == lost) {
      target = chosen;
    } else if (resolved.parent_path() == lost.parent_path() && !is_file(resolved)) {
      // Files that went missing together were most likely moved together.
      const fs::path beside = found_in / resolved.filename();
      if (!is_file(beside)) return;
      target = beside;
    } else {
      return;
    }
    const std::string written = written_for(target, folder);
    if (written == path) return;
    path = written;
    ++changed;
  });
  return changed;
}

}  // namespace inkray
