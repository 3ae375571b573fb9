// Coverage of an alpha-tested triangle mesh (painterly strokes): an 8-bit alpha
// texture over the mesh's uv, in a few variants so neighbouring items (strokes)
// do not all look alike. EmbreeScene tests hits against it stochastically.
#pragma once

#include "core/math/types.h"

#include <cstdint>
#include <vector>

namespace inkray {

struct AlphaMask {
  int width = 0;     // texels across u
  int height = 0;    // texels along v
  int variants = 1;  // stacked layers of width x height texels
  std::vector<uint8_t> texels;  // variants * height * width, row v, column u; 255 is opaque

  // Consecutive triangles that form one item and share a variant (a stroke's
  // ribbon); 0 puts every triangle on variant 0.
  uint32_t triangles_per_item = 0;
  // A ray that starts within this distance of a hit triangle's plane ignores the
  // hit: the mesh is a thin layer on a surface (paint), and must not shadow the
  // surface it lies on, nor itself.
  float layer_thickness = 0.f;

  // Bilinear coverage in [0, 1] at uv (clamped to [0, 1]^2) of triangle prim.
  float coverage(Vec2 uv, uint32_t prim) const;
  uint32_t variant_of(uint32_t prim) const;
  uint8_t& at(int variant, int u, int v) { return texels[(size_t(variant) * height + v) * width + u]; }
  uint8_t at(int variant, int u, int v) const { return texels[(size_t(variant) * height + v) * width + u]; }
  size_t memory_bytes() const { return texels.size(); }
};

}  // namespace inkray
