// Line decision files: what adaptive line sampling decided for every pixel of a
// render (core/npr/outlines/line_sampling.h, LineDecisions), written once for a
// render split into sample slices and read by the slices that start after the
// decisions, so none of them traces the decisions again (docs/final-renders.md,
// "Line decisions"). The file says what it was made from as a partial does
// (film_partial.h: image size, frame, seed, the scene), so a render refuses the
// decisions of another.
//
// Layout: a first line "inkray-line-decisions 1", a second line of JSON
// {"width", "height", "frame", "seed", "decided_at", "scene"}, then each pixel's
// ray count (32-bit little-endian) row by row, then each pixel's kind (one byte).
#pragma once

#include "core/film/film_partial.h"
#include "core/npr/outlines/line_sampling.h"

#include <filesystem>
#include <string>

namespace inkray {

inline constexpr std::string_view kLineDecisionsFormat = "inkray-line-decisions";
inline constexpr int kLineDecisionsVersion = 1;

// The file's bytes. `info` names the render (width, height, frame, seed, scene);
// its window, passes and AOVs are not kept.
std::string encode_line_decisions(const LineDecisions& decisions, const PartialInfo& info);

// Reads a file written by encode_line_decisions: *info gets the render it names
// (the whole image as its window, passes 0 to decided_at) and *decisions its
// pixels. Every problem is one line in *error naming the file and what was expected.
bool read_line_decisions(const std::filesystem::path& file, PartialInfo* info, LineDecisions* decisions,
                         std::string* error);

}  // namespace inkray
