// The style the document's outline settings give each line type. It reads both the
// document (OutlineDesc) and the world's LineType, so it stands above the two, beside
// its readers (make_line_setup here, compile_resolve_settings in the compiler), and
// neither the world nor the document includes the other.
#pragma once

#include "core/document/npr_desc.h"
#include "core/world/line_types.h"

namespace inkray {

inline const LineStyleDesc& line_style(const OutlineDesc& d, LineType t) {
  switch (t) {
    case LineType::depth:
      return d.depth;
    case LineType::crease:
      return d.crease;
    case LineType::intersection:
      return d.intersection;
    case LineType::material:
      return d.material;
    case LineType::object:
      return d.object;
    case LineType::silhouette:
      break;
  }
  return d.silhouette;
}

}  // namespace inkray
