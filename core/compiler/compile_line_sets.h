// The document's line sets -> the view's compiled ones (core/world/line_sets.h):
// their selections resolved against the objects' and materials' names, their
// brushes loaded. Also what a merge resolves a film's lines with, without a
// compiled scene.
#pragma once

#include "core/document/desc.h"
#include "core/world/line_sets.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace inkray {

// The pressure a line set's procedural brush is made with (brush.h): how much its
// paint runs out along the line.
inline constexpr float kLineBrushPressure = 0.4f;

// Loads a brush as the painterly strokes' (brush.h) for a line set's style; null with
// *error set when its image cannot be read.
using LineBrushLoader =
    std::function<std::shared_ptr<const AlphaTexture>(const StrokeEmitterDesc& brush, std::string* error)>;
// Reads brushes straight from their files (no cache): for a merge.
LineBrushLoader read_line_brushes(const std::filesystem::path& base_dir);

// The enabled sets, in order. A brush that cannot be read is an error naming the set
// and its file, in *errors; its set draws solid lines meanwhile.
std::vector<LineSet> compile_line_sets(const SceneDesc& desc, const LineBrushLoader& brushes,
                                       std::vector<std::string>* errors);

// How a line seen on each document material reached the camera (LinePath by material
// index): in a mirror on a conductor, through glass on a dielectric, directly on the rest.
std::vector<uint8_t> line_material_paths(const SceneDesc& desc);

// Whether `name` matches one of the comma-separated patterns (* any run, ? one character);
// an empty list matches every name.
bool matches_patterns(std::string_view name, std::string_view patterns);

}  // namespace inkray
