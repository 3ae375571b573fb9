// The compiled forms of the render settings and outlines a view is rendered and
// resolved with (docs/architecture.md, "World and view"): what every sample
// reads, and what the resolve reads. The compiler makes them from the document
// (core/compiler/compile_view.h); render threads and the resolve read only these.
#pragma once

#include "core/document/filter_kinds.h"
#include "core/math/types.h"
#include "core/world/line_types.h"

#include <array>
#include <cstdint>

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
  bool operator==(const ResolveSettings&) const = default;
};

}  // namespace inkray
