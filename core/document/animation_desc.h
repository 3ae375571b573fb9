// Keyframed parameters in the scene document (docs/architecture.md, "Animation").
// A track names one parameter of the document by path, e.g.
// "objects/ball/transform/translate" or "lights/key/intensity", and holds keys sorted by
// frame. document/animation.h resolves paths and evaluates tracks. Included by desc.h.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace inkray {

// How a key's value goes on to the next key's.
enum class Interpolation { bezier, linear, step };
inline constexpr std::array<std::string_view, 3> kInterpolationNames = {"bezier", "linear", "step"};

struct KeyDesc {
  double frame = 1.0;
  // The parameter's value: one number for a number, integer or toggle (0 or 1) or choice
  // (the index of its name), three for a point, vector, direction or colour.
  std::vector<double> value;
  Interpolation interp = Interpolation::bezier;  // towards the next key
  bool operator==(const KeyDesc&) const = default;
};

struct TrackDesc {
  std::string target;         // "objects/NAME/transform/translate", "camera/look_from", ...
  std::vector<KeyDesc> keys;  // sorted by frame, at most one per frame
  bool operator==(const TrackDesc&) const = default;
};

}  // namespace inkray
