// Fuzz harness for animation tracks, structure-aware: the input writes tracks on a small
// scene with every shape type (targets from a list of keyable and broken paths, keys
// with hostile frames and values: NaN, infinities, 1e30, zero and negative scales),
// chooses the frame and the shutter, and the scene goes through the JSON reader as a
// file would. Oracles, for a scene the reader accepts:
// - the checks agree with the reader (check_animation finds nothing);
// - written and read again it writes the same text;
// - at every key, between keys and outside them, every keyed parameter is finite and in
//   its range, equals its key at a key's frame, and between two keys stays between
//   their values (linear and eased keys never overshoot);
// - it compiles at its frame, with its shutter, and renders finite pixels (a scale
//   through zero must never reach Embree: docs/architecture.md, "Singular transforms").
// A refused scene must say why.
#include "core/compiler/compile.h"
#include "core/document/animation.h"
#include "core/document/json_io.h"
#include "core/render/batch_render.h"
#include "tests/compiler/graph_edit_ops.h"
#include "tests/fuzz/fuzz_targets.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace inkray {
namespace {

const std::filesystem::path kBase =
    std::filesystem::path(INKRAY_SOURCE_DIR) / "tests" / "data" / "scenes" / "valid";

// The scene the tracks animate: a floor, one of each shape, a light, outlines and strokes
// (a flat brush: a bristle brush's bake would take most of each run).
const char* const kScene = R"({
  "format": "inkray-scene", "version": 1,
  "camera": {"look_from": [0, 2, 7], "look_at": [0, 0.5, 0], "vfov": 40},
  "render": {"width": 8, "height": 6, "spp": 1, "max_depth": 4, "frame_start": 1, "frame_end": 24},
  "outlines": {"enabled": true},
  "materials": [{"name": "toon", "type": "toon"}, {"name": "glass", "type": "dielectric"},
                {"name": "floor", "type": "diffuse"}],
  "objects": [
    {"name": "floor", "material": "floor",
     "shape": {"type": "quad", "corner": [-4, 0, 4], "edge_u": [8, 0, 0], "edge_v": [0, 0, -8]}},
    {"name": "ball", "material": "toon", "shape": {"type": "sphere", "radius": 0.5},
     "transform": {"translate": [-1.5, 0.5, 0], "rotate": [{"axis": [0, 1, 0], "degrees": 10}]}},
    {"name": "box", "material": "toon", "shape": {"type": "box", "min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]},
     "transform": {"translate": [0, 0, 0]}},
    {"name": "card", "material": "glass",
     "shape": {"type": "quad", "corner": [-0.5, 0, 0], "edge_u": [1, 0, 0], "edge_v": [0, 1, 0]},
     "transform": {"translate": [0, 0, 1.5]}},
    {"name": "mesh", "material": "toon", "shape": {"type": "mesh", "path": "meshes/cube.obj"},
     "transform": {"translate": [1.5, 0.5, 0], "scale": [0.5, 0.5, 0.5]}}],
  "lights": [{"name": "key", "type": "point", "position": [2, 4, 3], "intensity": 30}],
  "strokes": [{"name": "dabs", "object": "ball", "count": 6, "seed": 3, "brush": "flat"}]
})";

// Targets: a parameter of every keyable kind on every shape, and paths that must be refused.
const char* const kTargets[] = {
    "objects/ball/transform/scale", "objects/box/transform/scale", "objects/card/transform/scale",
    "objects/mesh/transform/scale", "objects/floor/transform/scale", "objects/ball/transform/translate",
    "objects/mesh/transform/translate", "objects/ball/transform/rotate/0/degrees",
    "objects/ball/transform/rotate/0/axis", "objects/box/visible", "objects/ball/shape/radius",
    "objects/box/shape/max", "objects/card/shape/edge_u", "camera/look_from", "camera/look_at", "camera/vfov",
    "camera/focus_distance", "lights/key/intensity", "lights/key/color", "lights/key/position",
    "materials/toon/threshold", "materials/toon/color", "materials/glass/ior", "outlines/width",
    "outlines/unit", "outlines/silhouette/color", "strokes/dabs/jitter", "strokes/dabs/hue_jitter",
    "render/painterly_radius", "environment/color",
    // refused: unknown entries and parameters, unkeyable ones, groups
    "objects/gone/transform/scale", "objects/box/transform/rotate/0/degrees", "render/width",
    "strokes/dabs/count", "outlines/silhouette", "sky/color", ""};

double key_number(graph_ops::ByteStream& in) {
  switch (in.byte() % 8) {
    case 0:
      return 0.0;  // a scale of zero: the singular case
    case 1:
      return -1.0;  // a mirror, and a scale through zero on the way
    case 2:
      return 1e-7;
    default:
      return double(in.number());
  }
}

double key_frame(graph_ops::ByteStream& in, double previous) {
  switch (in.byte() % 6) {
    case 0:
      return double(in.number());
    case 1:
      return previous;  // a repeated frame: refused
    default:
      return previous + 0.25 * (1 + in.byte() % 16);
  }
}

nlohmann::json number_json(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

// What the reader and the writer do to a key's value: the parameter's range, and a
// float field's precision.
double stored(const Param& p, double x) {
  x = std::clamp(x, std::max(p.min, -3.0e38), std::min(p.max, 3.0e38));
  return p.kind == ParamKind::integer ? std::round(x) : double(float(x));
}

bool near(double a, double b) { return std::abs(a - b) <= 1e-5 * std::max({1.0, std::abs(a), std::abs(b)}); }

std::string at(const TrackDesc& t, double frame) { return t.target + " at frame " + std::to_string(frame); }

void check_values(const SceneDesc& scene) {
  for (const TrackDesc& track : scene.animation) {
    std::string error;
    const std::optional<Param> p = animation_target(scene, track.target, &error);
    if (!p) fuzz_fail("an accepted track does not resolve: " + track.target + ": " + error);
    const bool discrete = p->kind == ParamKind::toggle || p->kind == ParamKind::choice;
    std::vector<double> frames{track.keys.front().frame - 1.0, track.keys.back().frame + 1.0};
    for (size_t k = 0; k < track.keys.size(); ++k) {
      frames.push_back(track.keys[k].frame);
      if (k + 1 < track.keys.size()) frames.push_back(0.5 * (track.keys[k].frame + track.keys[k + 1].frame));
    }
    for (const double frame : frames) {
      std::vector<double> value;
      if (!read_target(scene_at_frame(scene, frame), track.target, &value))
        fuzz_fail("cannot read " + at(track, frame));
      for (size_t c = 0; c < value.size(); ++c) {
        if (!std::isfinite(value[c]) || value[c] < p->min || value[c] > p->max)
          fuzz_fail(at(track, frame) + ": " + std::to_string(value[c]) + " is not finite or out of range");
        if (discrete) continue;
        // The keys either side of the frame (both the same one outside the keys or on one).
        const auto next = std::upper_bound(track.keys.begin(), track.keys.end(), frame,
                                           [](double f, const KeyDesc& key) { return f < key.frame; });
        const KeyDesc& after = next == track.keys.end() ? track.keys.back() : *next;
        const KeyDesc& before = next == track.keys.begin() ? track.keys.front() : *(next - 1);
        const double a = stored(*p, before.value[c]), b = stored(*p, after.value[c]);
        if (frame == before.frame && !near(value[c], a))
          fuzz_fail(at(track, frame) + ": " + std::to_string(value[c]) + " is not its key's " +
                    std::to_string(a));
        const double slack =
            p->kind == ParamKind::integer ? 0.5 : 1e-5 * std::max({1.0, std::abs(a), std::abs(b)});
        if (value[c] < std::min(a, b) - slack || value[c] > std::max(a, b) + slack)
          fuzz_fail(at(track, frame) + ": " + std::to_string(value[c]) + " leaves its keys' range [" +
                    std::to_string(std::min(a, b)) + ", " + std::to_string(std::max(a, b)) + "]");
      }
    }
  }
}

}  // namespace

int fuzz_animation_tracks(const std::uint8_t* data, std::size_t size) {
  static const nlohmann::json base = nlohmann::json::parse(kScene);
  static const SceneDesc probe = *parse_scene(kScene, kBase, "animation.json").scene;
  graph_ops::ByteStream in(data, size);
  nlohmann::json doc = base;
  constexpr double kFrames[] = {1.0, 1.5, 7.5, 12.0, 24.0, 0.0, 30.0};
  const size_t f = in.pick(std::size(kFrames) + 1);
  doc["render"]["frame"] = f < std::size(kFrames) ? kFrames[f] : double(in.number());
  switch (in.byte() % 4) {
    case 0:
      break;  // no motion blur
    case 1:
      doc["render"]["shutter_open"] = -0.25, doc["render"]["shutter_close"] = 0.25;
      break;
    case 2:
      doc["render"]["shutter_open"] = -1.0, doc["render"]["shutter_close"] = 1.0;
      break;
    default:
      doc["render"]["shutter_open"] = 0.0, doc["render"]["shutter_close"] = double(in.byte()) / 64.0;
  }
  nlohmann::json tracks = nlohmann::json::array();
  const int track_count = 1 + in.byte() % 6;
  for (int t = 0; t < track_count && !in.empty(); ++t) {
    const std::string target = kTargets[in.pick(std::size(kTargets))];
    const std::optional<Param> p = animation_target(probe, target, nullptr);
    int width = p ? key_width(p->kind) : 3;
    if (in.byte() % 16 == 0) width = 4 - width;  // a value of the wrong width
    nlohmann::json keys = nlohmann::json::array();
    const int key_count = in.byte() % 8;
    double frame = 1.0 + in.byte() % 24;
    for (int k = 0; k < key_count; ++k) {
      nlohmann::json value = nlohmann::json::array();
      for (int c = 0; c < width; ++c) value.push_back(number_json(key_number(in)));
      nlohmann::json key = {{"frame", number_json(frame)},
                            {"value", width == 1 ? value[0] : value},
                            {"interp", std::string(kInterpolationNames[in.byte() % 3])}};
      keys.push_back(key);
      frame = key_frame(in, frame);
    }
    tracks.push_back({{"target", target}, {"keys", keys}});
  }
  doc["animation"] = tracks;

  const SceneLoadResult loaded = parse_scene(doc.dump(), kBase, "animation.json");
  if (!loaded) {
    if (loaded.errors.empty()) fuzz_fail("a refused scene says nothing");
    return 0;
  }
  const SceneDesc& scene = *loaded.scene;
  if (const std::vector<std::string> problems = check_animation(scene); !problems.empty())
    fuzz_fail("the reader accepted what the checks refuse: " + problems.front());
  const std::string text = scene_to_string(scene);
  const SceneLoadResult again = parse_scene(text, kBase, "again.json");
  if (!again) fuzz_fail("written and read again, refused: " + again.errors.front());
  if (scene_to_string(*again.scene) != text) fuzz_fail("written and read again, written differently");
  check_values(scene);

  const CompileResult c = compile_scene(scene);
  if (!c.scene) {
    if (c.errors.empty()) fuzz_fail("a scene that does not compile says nothing");
    return 0;
  }
  RenderSession session(1);
  session.set_scene(c.scene);
  render_batch(session, {1, 0.0});
  for (const Color& pixel : session.film().resolve().pixels)
    if (!std::isfinite(pixel.x) || !std::isfinite(pixel.y) || !std::isfinite(pixel.z))
      fuzz_fail("a pixel is not finite");
  return 0;
}

}  // namespace inkray
