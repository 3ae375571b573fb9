// Chaining (docs/architecture.md, "Lines as strokes"): a render's resolved line
// coverage, one line type at a time, thinned to one-pixel paths, traced into
// polylines, joined straight through crossings, fitted with a spline and
// labelled with the surface under them. What styles draw is built here; how
// lines were found (line_detector.h) and how they are drawn (line_strokes.h)
// are not this file's business.
#pragma once

#include "core/world/chain.h"

#include <array>
#include <cstdint>
#include <vector>

namespace inkray {

// What chains are built from, per pixel of one image. The per-pixel layers are
// optional: an empty one leaves its attribute at the ChainPoint default.
struct ChainSource {
  int width = 0, height = 0;
  std::vector<uint32_t> pixels;                            // row-major indices of pixels with lines
  std::vector<std::array<float, kLineTypeCount>> opacity;  // each one's line opacity per type, [0, 1]
  std::vector<float> depth;   // camera distance of the first hit, 0 where nothing was hit
  std::vector<int> object;    // document object index of the first hit, -1 none
  std::vector<int> material;  // material index of the first hit, -1 none
  std::vector<uint8_t> path;  // LinePath of the pixel's lines
  std::vector<float> light;   // display-encoded luminance of the image
};

struct ChainOptions {
  float threshold = 0.2f;  // a pixel belongs to a line of a type at this opacity and above,
  // or at this one where it touches such a pixel (hysteresis, as Canny's edges): a thin
  // line's noisy coverage at a few samples dips below the threshold without breaking.
  float low_threshold = 0.08f;
  // Chains meeting at a crossing continue into the partner that turns the least,
  // when it turns by less than this (degrees): a cross is two chains, a T a bar and a stem.
  float join_angle = 50.f;
  float fit_tolerance = 0.6f;  // pixels the fitted spline may leave the traced pixel path by
  float spacing = 1.f;         // pixels between points of the fitted chain
};

// The chains of every line type of `source`, in LineType order. Each starts at a
// stable end, whatever the image's scan order: an open chain at its end with the
// smaller x (then y), a closed one at its topmost point running clockwise on screen,
// so a chain keeps its parameterisation from frame to frame.
std::vector<Chain> build_chains(const ChainSource& source, const ChainOptions& options = {});

}  // namespace inkray
