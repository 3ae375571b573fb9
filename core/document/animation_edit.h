// Edits of the tracks that go with edits of the document (docs/architecture.md,
// "Timeline and keys"): an entry renamed, duplicated or deleted takes its tracks along,
// an edited animated parameter is keyed at the frame it was edited on, and keys set or
// removed by hand keep what the frame shows. Pure functions, like graph_edit.h.
#pragma once

#include "core/document/desc.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// "objects/ball/": how every path of a named entry's parameters starts (`section` is
// objects, lights, materials or strokes). A graph node's: "materials/toon/nodes/rim/".
std::string entry_path(std::string_view section, std::string_view name);
std::string node_path(std::string_view material, std::string_view node_id);

// Tracks whose target starts with `from` start with `to` instead (a renamed entry).
size_t rename_tracks(SceneDesc& desc, std::string_view from, std::string_view to);
// Removes the tracks whose target starts with `prefix` (a deleted entry).
size_t delete_tracks(SceneDesc& desc, std::string_view prefix);
// Adds a copy, starting with `to`, of every track starting with `from` (a duplicated entry).
size_t copy_tracks(SceneDesc& desc, std::string_view from, std::string_view to);
// Removes the tracks of `after` whose target existed in `before` and is gone: what an
// edit took away (a deleted graph node, a material switched to a type without that
// parameter). Tracks that did not resolve before are left for check_animation to report.
size_t drop_vanished_tracks(const SceneDesc& before, SceneDesc& after);

// Auto-key: sets a key at after.render.frame on every track whose parameter the edit
// changed. Edits start from the document's own values or from the values shown at the
// frame (the properties panel, the gizmo), so a parameter counts as changed when it
// differs from both; others the edit copied along keep their keys.
size_t key_edited(const SceneDesc& before, SceneDesc& after);

// How a parameter is animated at a frame: not at all, by a track without a key there, or keyed there.
enum class KeyState { none, animated, keyed };
KeyState key_state(const SceneDesc& desc, std::string_view path, double frame);

// Keys by hand, keeping the picture: a key takes the value the frame shows, and a
// parameter whose last key goes keeps the value it showed at desc.render.frame.
// Each returns false when there was nothing to do (a path that cannot be keyed, no key).
bool key_shown_value(SceneDesc& desc, std::string_view path, double frame);
bool unkey(SceneDesc& desc, std::string_view path, double frame);
bool clear_keys(SceneDesc& desc, std::string_view path);

// The frames holding keys of tracks whose target starts with `prefix` (every track
// for ""), sorted, each once.
std::vector<double> key_frames(const SceneDesc& desc, std::string_view prefix = {});

}  // namespace inkray
