// Tracks following the document's edits; docs/architecture.md, "Timeline and keys".
#include "core/document/animation_edit.h"

#include "core/document/animation.h"

#include <algorithm>

namespace inkray {
namespace {

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

// The parameter's value as `desc` shows it at its current frame.
bool read_shown(const SceneDesc& desc, std::string_view path, std::vector<double>* value) {
  if (!find_track(desc, path)) return read_target(desc, path, value);
  return read_target(scene_at_frame(desc, desc.render.frame), path, value);
}

}  // namespace

std::string entry_path(std::string_view section, std::string_view name) {
  return std::string(section) + "/" + std::string(name) + "/";
}

std::string node_path(std::string_view material, std::string_view node_id) {
  return entry_path("materials", material) + "nodes/" + std::string(node_id) + "/";
}

size_t rename_tracks(SceneDesc& desc, std::string_view from, std::string_view to) {
  if (from == to) return 0;
  return desc.animation.update_if(
      [&](const TrackDesc& t) { return starts_with(t.target, from); },
      [&](TrackDesc& t) { t.target = std::string(to) + t.target.substr(from.size()); });
}

size_t delete_tracks(SceneDesc& desc, std::string_view prefix) {
  return desc.animation.erase_if([&](const TrackDesc& t) { return starts_with(t.target, prefix); });
}

size_t copy_tracks(SceneDesc& desc, std::string_view from, std::string_view to) {
  const size_t count = desc.animation.size();
  size_t copied = 0;
  for (size_t i = 0; i < count; ++i) {
    if (!starts_with(desc.animation[i].target, from)) continue;
    TrackDesc copy = desc.animation[i];
    copy.target = std::string(to) + copy.target.substr(from.size());
    desc.animation.push_back(std::move(copy));
    ++copied;
  }
  return copied;
}

size_t drop_vanished_tracks(const SceneDesc& before, SceneDesc& after) {
  const TargetResolver now(after), was(before);
  return after.animation.erase_if(
      [&](const TrackDesc& t) { return !now.target(t.target, nullptr) && was.target(t.target, nullptr); });
}

size_t key_edited(const SceneDesc& before, SceneDesc& after) {
  if (after.animation.empty()) return 0;
  const SceneDesc shown = scene_at_frame(before, before.render.frame);
  size_t keyed = 0;
  for (size_t i = 0; i < after.animation.size(); ++i) {
    const std::string path = after.animation[i].target;
    std::vector<double> now, own, seen;
    if (!read_target(after, path, &now) || !read_target(before, path, &own) ||
        !read_target(shown, path, &seen))
      continue;
    if (now == own || now == seen) continue;
    if (insert_key(after, path, after.render.frame)) ++keyed;
  }
  return keyed;
}

KeyState key_state(const SceneDesc& desc, std::string_view path, double frame) {
  const TrackDesc* track = find_track(desc, path);
  if (!track || track->keys.empty()) return KeyState::none;
  const bool here =
      std::any_of(track->keys.begin(), track->keys.end(), [&](const KeyDesc& k) { return k.frame == frame; });
  return here ? KeyState::keyed : KeyState::animated;
}

bool key_shown_value(SceneDesc& desc, std::string_view path, double frame) {
  std::vector<double> value;
  if (!animation_target(desc, path, nullptr)) return false;
  const bool shown = find_track(desc, path) ? read_target(scene_at_frame(desc, frame), path, &value)
                                            : read_target(desc, path, &value);
  if (!shown || !write_target(desc, path, value)) return false;
  return insert_key(desc, path, frame);
}

bool unkey(SceneDesc& desc, std::string_view path, double frame) {
  std::vector<double> value;
  const bool shown = read_shown(desc, path, &value);
  if (!delete_key(desc, path, frame)) return false;
  if (shown && !find_track(desc, path)) write_target(desc, path, value);
  return true;
}

bool clear_keys(SceneDesc& desc, std::string_view path) {
  std::vector<double> value;
  const bool shown = read_shown(desc, path, &value);
  if (desc.animation.erase_if([&](const TrackDesc& t) { return t.target == path; }) == 0) return false;
  if (shown) write_target(desc, path, value);
  return true;
}

std::vector<double> key_frames(const SceneDesc& desc, std::string_view prefix) {
  std::vector<double> frames;
  for (const TrackDesc& track : desc.animation) {
    if (!starts_with(track.target, prefix)) continue;
    for (const KeyDesc& key : track.keys) frames.push_back(key.frame);
  }
  std::sort(frames.begin(), frames.end());
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  return frames;
}

}  // namespace inkray
