// Strokes as filled outlines, for vector files (vector_lines.h): the shapes
// draw_strokes rasterises, as polygons of one colour each.
#pragma once

#include "core/npr/lines/line_strokes.h"

#include <vector>

namespace inkray {

// Colour and opacity within a run differ from its first sample's by at most these:
// the sRGB-encoded channels by 2 % (5 of 255 steps), opacity by 0.04. Past that a new
// run starts, so a stroke whose colour varies becomes a few shapes of near-constant
// colour, each filled with its samples' mean.
inline constexpr float kRunColorTolerance = 0.02f;
inline constexpr float kRunOpacityTolerance = 0.04f;

// One filled shape: closed polygons (fill rule nonzero; even-odd gives the same),
// one colour, one opacity.
struct OutlineShape {
  std::vector<std::vector<Vec2>> rings;
  Color color{0.f};  // a display colour, as the stroke's
  float opacity = 1.f;
};

// The shapes of one stroke. Each run of samples is a polygon: the left offsets
// forward, the right ones back, flat across at its ends as draw_strokes' ends are.
// An unbroken loop is two rings, its outer and inner edges, wound against each other.
// Runs break where colour or opacity drift past the tolerances above, and where the
// line turns too sharply for its width (an offset edge would fold over itself): there
// a disc of the local width fills the join, as the round joins of draw_strokes do.
// Brush textures have no outline: vector files draw strokes solid.
std::vector<OutlineShape> stroke_outline(const LineStroke& stroke);

}  // namespace inkray
