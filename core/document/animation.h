// Animation: tracks of keys on document parameters (animation_desc.h), addressed by
// path, and the document they give at a frame (docs/architecture.md, "Animation").
//
// A path walks the document as its JSON does, with list entries by name:
//   camera/look_from, camera/vfov, camera/focus_distance
//   objects/NAME/transform/translate | scale | rotate/INDEX/degrees | rotate/INDEX/axis
//   objects/NAME/visible, objects/NAME/lines/width_scale
//   lights/NAME/intensity, lights/NAME/color, ...           (the light type's parameters)
//   materials/NAME/threshold, materials/NAME/base_color ... (the material type's parameters)
//   materials/NAME/nodes/NODE_ID/PARAM                      (a graph node's settings)
//   environment/color, outlines/width, outlines/silhouette/color
//   strokes/NAME/jitter, render/painterly_radius, ...
// Only parameters that hold numbers, toggles, choices, points, vectors, directions or
// colours can be keyed.
#pragma once

#include "core/document/desc.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// The parameter a path names in `desc` (its kind, range and stage), or nullopt with
// *error saying which part of the path does not exist or why it cannot be keyed.
std::optional<Param> animation_target(const SceneDesc& desc, std::string_view path, std::string* error);

// animation_target for the tracks of a whole document: list entries are found through
// an index of their names built once, so resolving n tracks against n entries takes
// linear time rather than a search of the list per track. Holds `desc` by reference;
// valid while its lists and names are unchanged.
struct AnimationNames;
class TargetResolver {
 public:
  explicit TargetResolver(const SceneDesc& desc);
  ~TargetResolver();
  TargetResolver(const TargetResolver&) = delete;
  TargetResolver& operator=(const TargetResolver&) = delete;
  std::optional<Param> target(std::string_view path, std::string* error) const;

 private:
  const SceneDesc& desc_;
  std::unique_ptr<const AnimationNames> names_;
};

// How many numbers a key of this kind holds (1 or 3); 0 for kinds that cannot be keyed.
int key_width(ParamKind kind);

// The parameter's current value as key numbers; false when the path does not resolve.
bool read_target(const SceneDesc& desc, std::string_view path, std::vector<double>* value);
// Writes key numbers into the parameter, clamped to its range (an integer is rounded, a
// toggle is value >= 0.5, a choice the nearest index); false when the path does not resolve.
bool write_target(SceneDesc& desc, std::string_view path, std::span<const double> value);

// The track's value at `frame`: the first key's before it, the last key's after it, and
// between two keys the earlier key's interpolation. Bezier keys ease with automatic,
// clamped handles (no overshoot past a key's value, as Blender's "auto clamped").
std::vector<double> track_value(const TrackDesc& track, double frame);

// The document at `frame`: every track's value written into its parameter. Tracks whose
// target does not resolve are left out (check_animation reports them).
void apply_animation(SceneDesc& desc, double frame);
SceneDesc scene_at_frame(const SceneDesc& desc, double frame);

// Whether any track's value differs anywhere in [from, to] (a still between them).
bool animated_between(const SceneDesc& desc, double from, double to);

// Problems with the tracks, one line each naming the track: unknown targets, values of
// the wrong width, keys out of order or on the same frame, two tracks on one target.
std::vector<std::string> check_animation(const SceneDesc& desc);

// The track on `path`, or null.
const TrackDesc* find_track(const SceneDesc& desc, std::string_view path);
// Sets a key at `frame` on the track of `path` to the parameter's current value (a track
// is created when there is none, a key on that frame replaced); false when the path
// does not resolve or cannot be keyed.
bool insert_key(SceneDesc& desc, std::string_view path, double frame,
                Interpolation interp = Interpolation::bezier);
// Removes the key at `frame` (and the track when it was the last); false when there was none.
bool delete_key(SceneDesc& desc, std::string_view path, double frame);

}  // namespace inkray
