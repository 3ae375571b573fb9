// The compiled forms of the render settings and outlines a view is rendered and
// resolved with (docs/architecture.md, "World and view"): what every sample
// reads, and what the resolve reads. The compiler makes them from the document
// (core/compiler/compile_view.h); render threads and the resolve read only these.
#pragma once

#include "core/document/filter_kinds.h"
#include "core/math/types.h"
#include "core/world/chain.h"
#include "core/world/line_sets.h"
#include "core/world/line_types.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace inkray {

// What every sample reads of the render settings.
struct SampleSettings {
  int width = 0, height = 0;  // the image's, in pixels
  int max_depth = 16;         // path vertices
  uint32_t seed = 0;
  float clamp = 0.f;  // maximum sample luminance; 0: none
  PixelFilter filter = PixelFilter::box;
  float filter_radius = 0.5f;  // pixels
  bool motion_blur = false;    // the shutter is open for a time
};

// How one line type is drawn over the image.
struct LineLook {
  Color color{0.f};
  float opacity = 1.f;
  bool operator==(const LineLook&) const = default;
};

// What the resolve reads: the painterly filter and the lines' colours. Changing
// any of it needs no new sample.
struct ResolveSettings {
  PainterlyFilter painterly = PainterlyFilter::none;
  float painterly_radius = 4.f;  // pixels at the reference height 1080
  float painterly_sharpness = 8.f;
  std::array<LineLook, kLineTypeCount> lines{};  // by LineType
  // Line sets: with any, lines are chained and drawn as their strokes instead of
  // pixel by pixel in the colours above (docs/architecture.md, "Lines as strokes").
  std::vector<LineSet> sets;
  std::vector<uint8_t> material_paths;  // LinePath of a line seen on each material, by index
  // Without sets, what vector files draw the lines with: a set per enabled line
  // type, of its colour, opacity and width.
  std::vector<LineSet> plain_sets;
  // Hidden lines, when a set takes them: chains in pixels of the full image
  // (SampleSettings' width), made by the compiler for this view; null when none is taken.
  std::shared_ptr<const std::vector<Chain>> hidden;
  int hidden_width = 0;  // the full image's width the hidden chains are drawn in
  bool operator==(const ResolveSettings&) const = default;
};

}  // namespace inkray
