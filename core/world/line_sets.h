// Line sets in their compiled form (docs/architecture.md, "Lines as strokes"):
// which chains a set selects, and the style it draws them with. The compiler
// makes them from the document's outline line sets (core/compiler/compile_view.h);
// the resolve reads them, so editing a set needs no new sample.
#pragma once

#include "core/document/line_set_desc.h"
#include "core/geometry/alpha_mask.h"
#include "core/math/types.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace inkray {

// How one line set draws its chains: the document's style block (lengths in
// pixels at 1080 lines, core/document/line_set_desc.h) with its brush loaded.
struct LineStyle : LineStyleParams {
  // A brush stretched along the chain (u across, v along the stroke); null: a solid line.
  std::shared_ptr<const AlphaTexture> brush;
  bool operator==(const LineStyle&) const = default;
};

// Which chains a set selects.
struct LineSelection {
  uint32_t types = ~0u;                 // bit per LineType
  uint32_t paths = ~0u;                 // bit per LinePath
  bool visible = true, hidden = false;  // lines the camera sees; lines behind surfaces (Chain::covers > 0)
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
