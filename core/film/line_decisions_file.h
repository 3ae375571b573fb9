// Line decision files: what adaptive line sampling decided for every pixel of a
// render (core/npr/outlines/line_sampling.h, LineDecisions), written once for a
// render split into sample slices and read by the slices that start after the
// decisions, so none of them traces the decisions again (docs/final-renders.md,
// "Line decisions"). The file says what it was made from as a partial does
// (film_partial.h: image size, frame, seed, the scene and its assets' hashes), so a
// render refuses the decisions of another, and is sealed by checksums, so a damaged
// one is refused.
//
// Layout: a first line "inkray-line-decisions 2"; a second line "checksums H P", H the
// content_hash of the third line and P of the pixel bytes (16 hex digits each); a third
// line of JSON {"width", "height", "frame", "seed", "decided_at", "scene", "assets",
// "content"}; then each pixel's ray count (32-bit little-endian) row by row, then each
// pixel's kind (one byte).
#pragma once

#include "core/film/film_partial.h"
#include "core/npr/outlines/line_sampling.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace inkray {

inline constexpr std::string_view kLineDecisionsFormat = "inkray-line-decisions";
// 2: the checksums line, and the assets and content hash in the header.
inline constexpr int kLineDecisionsVersion = 2;

// The file's bytes. `info` names the render (width, height, frame, seed, scene,
// assets); its window, passes and AOVs are not kept.
std::string encode_line_decisions(const LineDecisions& decisions, const PartialInfo& info);

// Reads a file written by encode_line_decisions: *info gets the render it names
// (the whole image as its window, passes 0 to decided_at) and *decisions its
// pixels. Every problem (not a regular file, another version, a damaged line or
// pixels, a header nested too deep) is one line in *error naming the file and what
// was expected.
bool read_line_decisions(const std::filesystem::path& file, PartialInfo* info, LineDecisions* decisions,
                         std::string* error);
// The same from bytes in memory; `label` names them in messages.
bool read_line_decisions_bytes(std::string_view bytes, const std::string& label, PartialInfo* info,
                               LineDecisions* decisions, std::string* error);

}  // namespace inkray
