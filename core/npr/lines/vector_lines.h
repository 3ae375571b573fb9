// Lines as vector files: SVG for editing (a layer per line set in Inkscape or
// Illustrator) and PDF for print. Each stroke is written as its filled outline
// (stroke_outline.h), so width, taper and colour along it survive; brush textures
// are raster-only and vector files draw strokes solid. Both are written atomically
// (core/io/atomic_file.h), and errors name the file.
#pragma once

#include "core/image/rgb_image.h"
#include "core/npr/lines/line_strokes.h"
#include "core/world/line_sets.h"

#include <filesystem>
#include <string>
#include <vector>

namespace inkray {

// SVG 1.1, its view box the image in pixels: the background (if any) in a layer of its
// own at the bottom, then one layer (an Inkscape layer group) per line set in set order,
// named after the set, holding the outlines of that set's strokes in drawing order,
// each a path filled with its colour and fill-opacity. Coordinates have two decimals.
// `background`, when given, holds display colours (what DisplayMapping::to_display
// gives; resolve_final's image under the default display already is), embedded as an
// 8-bit sRGB PNG; line colours are display colours too, written sRGB-encoded.
bool write_lines_svg(const std::filesystem::path& file, int width, int height,
                     const std::vector<LineStroke>& strokes, const std::vector<LineSet>& sets,
                     const RgbImage* background, std::string* error);

// The same SVG in memory, for a caller that stages it with other files
// (core/render/render_outputs.h); errors do not name a file.
bool encode_lines_svg(int width, int height, const std::vector<LineStroke>& strokes,
                      const std::vector<LineSet>& sets, const RgbImage* background, std::string* bytes,
                      std::string* error);

// The same drawing as one PDF page of width x height points (a point per pixel),
// through cairo, the background image under the lines.
bool write_lines_pdf(const std::filesystem::path& file, int width, int height,
                     const std::vector<LineStroke>& strokes, const RgbImage* background, std::string* error);

// The same PDF in memory.
bool encode_lines_pdf(int width, int height, const std::vector<LineStroke>& strokes,
                      const RgbImage* background, std::string* bytes, std::string* error);

}  // namespace inkray
