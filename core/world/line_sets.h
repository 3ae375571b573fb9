// Line sets in their compiled form (docs/architecture.md, "Lines as strokes"):
// which chains a set selects, and the style it draws them with. The compiler
// makes them from the document's outline line sets (core/compiler/compile_view.h);
// the resolve reads them, so editing a set needs no new sample.
#pragma once

#include "core/geometry/alpha_mask.h"
#include "core/math/types.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace inkray {

// What a chain's value along it is taken from, for width, colour and opacity.
enum class LineModulation : uint8_t {
  none,       // constant
  along,      // from the chain's start (0) to its end (1)
  depth,      // near (0) to far (1) over the chains of the image
  curvature,  // straight (0) to turning by a radian per 10 pixels at 1080 lines or more (1)
  light,      // dark (0) to light (1) under the line
  coverage,   // how solidly the line was found: its resolved opacity
};

// How one line set draws its chains. Lengths are pixels of an image 1080 lines
// tall, scaled with the image (as the painterly filter's radius), so a look holds
// from the editor's preview to a 4K render.
struct LineStyle {
  Color color{0.f};
  Color color_end{0.f};  // the colour where color_by reads 1
  LineModulation color_by = LineModulation::none;
  float opacity = 1.f;
  float opacity_min = 1.f;  // opacity multiplier where opacity_by reads 1
  LineModulation opacity_by = LineModulation::none;
  float width = 2.f;      // pixels at 1080 lines
  float width_min = 1.f;  // width multiplier where width_by reads 1
  LineModulation width_by = LineModulation::none;
  float taper_start = 0.f;  // fraction of the chain's length over which it grows from nothing
  float taper_end = 0.f;    // ... and shrinks to nothing at its end
  // A brush stretched along the chain (u across, v along the stroke); null: a solid line.
  std::shared_ptr<const AlphaTexture> brush;
  float brush_repeat = 0.f;   // pixels of chain per brush image; 0: stretched over the whole chain
  float jitter = 0.f;         // amplitude of the noise that displaces the line across itself, pixels
  float jitter_scale = 20.f;  // wavelength of that noise along the chain, pixels
  float overshoot = 0.f;      // extension past both ends along the end tangents, pixels
  int passes = 1;             // strokes drawn over each chain, each with its own noise
  float dash = 0.f;           // dash length, pixels; 0: unbroken
  float gap = 0.f;            // gap between dashes, pixels
  float min_length = 0.f;     // chains shorter than this are not drawn, pixels
  float corner_angle = 0.f;   // degrees: chains split where they turn more sharply than 180 - this; 0 never
  uint32_t seed = 0;          // the noise of jitter and passes
  bool operator==(const LineStyle&) const = default;
};

// Which chains a set selects.
struct LineSelection {
  uint32_t types = ~0u;  // bit per LineType
  uint32_t paths = ~0u;  // bit per LinePath
  // By document object index and compiled material index: empty selects all.
  std::vector<bool> objects, materials;
  bool operator==(const LineSelection&) const = default;
};

struct LineSet {
  std::string name;
  LineSelection select;
  LineStyle style;
  bool operator==(const LineSet&) const = default;
};

}  // namespace inkray
