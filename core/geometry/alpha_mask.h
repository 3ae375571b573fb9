// Coverage of an alpha-tested triangle mesh (painterly strokes): an 8-bit alpha
// texture over the mesh's uv (the brush), in a few variants so neighbouring items
// (strokes) do not all look alike, and what the mesh itself says about its alpha test.
// EmbreeScene tests hits against it stochastically.
#pragma once

#include "core/math/types.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace inkray {

// What the alpha test reads of one triangle, in one 16-byte load: the texture
// coordinates and alphas of its corners, quantised, and its variant. Meshes
// that carry these need no uvs of their own for the test.
struct AlphaTriangle {
  uint16_t u[3] = {0, 0, 0};  // in 1 / 65535
  uint16_t v[3] = {0, 0, 0};
  uint8_t fade[3] = {255, 255, 255};  // corner alpha, multiplying the texture's, in 1 / 255
  uint8_t pick = 0;                   // the variant is (pick * variants) >> 8
};
static_assert(sizeof(AlphaTriangle) == 16);

// The coverage over uv of one item (a brush), in variants. What an alpha test reads
// besides its mesh: an instance of a mesh may bring its own (EmbreeScene::add), so a
// new brush is a new texture for the same mesh and BVH.
struct AlphaTexture {
  int width = 0;                // texels across u
  int height = 0;               // texels along v
  int variants = 1;             // stacked layers of width x height texels
  std::vector<uint8_t> texels;  // variants * height * width, row v, column u; 255 is opaque

  // Bilinear coverage in [0, 1] at uv (clamped to [0, 1]^2) in one variant, and in a
  // triangle's own terms (corner alphas included) at barycentrics (b1, b2).
  float coverage_in(int variant, Vec2 uv) const;
  float coverage_of(const AlphaTriangle& t, float b1, float b2) const;
  uint8_t& at(int variant, int u, int v) { return texels[(size_t(variant) * height + v) * width + u]; }
  uint8_t at(int variant, int u, int v) const { return texels[(size_t(variant) * height + v) * width + u]; }
};

// An alpha-tested mesh's own alpha data, the layer it lies in, and the texture its
// alpha test reads unless its instance brings another.
struct AlphaMask : AlphaTexture {
  // Consecutive triangles that form one item and share a variant (a stroke's
  // ribbon); 0 puts every triangle on variant 0. Unused when `triangles` is set.
  uint32_t triangles_per_item = 0;
  // Per triangle of the mesh: coordinates, corner alphas and variant. When
  // empty the test reads the mesh's uvs and variant_of().
  std::vector<AlphaTriangle> triangles;
  // A ray that starts within this distance of a hit triangle's plane ignores the
  // hit: the mesh is a thin layer on a surface (paint), and must not shadow the
  // surface it lies on, nor itself.
  float layer_thickness = 0.f;
  // A layer of paint on a surface (strokes): shadow rays pass through it (the
  // surface it lies on casts the shadow), and where its triangles overlap the
  // one painted last is seen, whatever their heights: the triangle with the
  // higher index, of the shape added later (EmbreeScene::intersect).
  bool paint = false;
  // Triangles 2q and 2q + 1 are the halves (a, b, a1) and (b, b1, a1) of the
  // quad (a, b, b1, a1): the mesh is traced as quads, half the primitives.
  bool quads = false;

  // Bilinear coverage in [0, 1] at uv (clamped to [0, 1]^2) of triangle prim, in this
  // mask's own texture.
  float coverage(Vec2 uv, uint32_t prim) const;
  // The variant triangle prim reads in a texture of `texture_variants`, and in this one.
  uint32_t variant_of(uint32_t prim, int texture_variants) const;
  uint32_t variant_of(uint32_t prim) const { return variant_of(prim, variants); }
  size_t memory_bytes() const { return texels.capacity() + triangles.capacity() * sizeof(AlphaTriangle); }
};

// Inline: the filter calls these for every candidate hit on paint.
inline float AlphaTexture::coverage_in(int variant, Vec2 uv) const {
  if (width <= 0 || height <= 0) return 1.f;
  // Texel centres sit at (i + 0.5) / width; beyond the outer centres the edge texel holds.
  // Compared so that a NaN uv lands on texel 0 instead of reaching the cast
  // (and inlined, where std::fmin and std::fmax are library calls).
  auto clamp = [](float v, float hi) {
    const float lo = v > 0.f ? v : 0.f;
    return lo < hi ? lo : hi;
  };
  const float x = clamp(uv.x * float(width) - 0.5f, float(width - 1));
  const float y = clamp(uv.y * float(height) - 0.5f, float(height - 1));
  const int x0 = int(x), y0 = int(y);  // x, y >= 0: truncation is floor
  const int dx = x0 + 1 < width ? 1 : 0;
  const size_t dy = y0 + 1 < height ? size_t(width) : 0;
  const float tx = x - float(x0), ty = y - float(y0);
  const uint8_t* row =
      texels.data() + (size_t(variant) * size_t(height) + size_t(y0)) * size_t(width) + size_t(x0);
  const float t00 = row[0], t10 = row[dx], t01 = row[dy], t11 = row[dy + size_t(dx)];
  const float top = t00 + tx * (t10 - t00);
  const float bottom = t01 + tx * (t11 - t01);
  return (top + ty * (bottom - top)) * (1.f / 255.f);
}

inline float AlphaTexture::coverage_of(const AlphaTriangle& t, float b1, float b2) const {
  const float b0 = 1.f - b1 - b2;
  const float fade = (b0 * float(t.fade[0]) + b1 * float(t.fade[1]) + b2 * float(t.fade[2])) * (1.f / 255.f);
  if (fade <= 0.f) return 0.f;
  const Vec2 uv((b0 * float(t.u[0]) + b1 * float(t.u[1]) + b2 * float(t.u[2])) * (1.f / 65535.f),
                (b0 * float(t.v[0]) + b1 * float(t.v[1]) + b2 * float(t.v[2])) * (1.f / 65535.f));
  const int variant = int((uint32_t(t.pick) * uint32_t(variants)) >> 8);
  return std::min(fade, 1.f) * coverage_in(variant, uv);
}

// Quantises a coordinate in [0, 1] (clamped) for AlphaTriangle.
inline uint16_t alpha_coordinate(float x) {
  const float c = x > 0.f ? (x < 1.f ? x : 1.f) : 0.f;  // a NaN lands on 0
  return uint16_t(c * 65535.f + 0.5f);
}

}  // namespace inkray
