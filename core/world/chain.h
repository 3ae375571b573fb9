// Chains: the lines of a render as strokes (docs/architecture.md, "Lines as
// strokes"), the form lines take between finding them and drawing them. Traced
// from the film's coverage (core/npr/lines/chain_builder.h) or found on the
// surfaces' edges (hidden lines, core/npr/lines/hidden_lines.h), they are ordered
// polylines in image space, each point carrying what the surface under it was:
// what line sets select and styles draw along.
#pragma once

#include "core/math/types.h"
#include "core/world/line_types.h"

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace inkray {

struct ChainPoint {
  Vec2 p{0.f};            // image position, pixels of the image the chain was built on (y down)
  float opacity = 1.f;    // the line's resolved opacity there (its coverage)
  float depth = 0.f;      // camera distance of the surface the line lies on (0: the background)
  float curvature = 0.f;  // turning of the chain, radians per pixel
  float light = 0.f;      // luminance of the image under the line, display-encoded [0, 1]
};

struct Chain {
  LineType type = LineType::silhouette;
  LinePath path = LinePath::direct;
  int object = -1;      // document object index of the surface under most of the chain; -1: none
  int material = -1;    // document material index, likewise
  bool closed = false;  // the last point joins the first
  int covers = 0;       // surfaces between the camera and the line: 0 seen, 1 and more hidden
  // Whether the first and the last point stop where the line meets others of its type
  // (a crossing it was not joined through: the stem of a T, a corner of several
  // lines). Which lines are joined there can change from frame to frame; a style
  // draws such an end as it draws the middle, not as a tip.
  std::array<bool, 2> ends_at_crossing{false, false};
  std::vector<ChainPoint> points;
};

// Length of a chain along its points, pixels (the closing segment included).
inline float chain_length(const Chain& c) {
  float len = 0.f;
  for (size_t i = 1; i < c.points.size(); ++i) len += glm::length(c.points[i].p - c.points[i - 1].p);
  if (c.closed && c.points.size() > 2) len += glm::length(c.points.front().p - c.points.back().p);
  return len;
}

}  // namespace inkray
