// The maths behind the procedural shader-graph nodes (Blender semantics): noise, Voronoi, HSV edits,
// MixRGB, colour ramps, Fresnel and Layer Weight. Pure per-shading-point functions for the hot loop:
// no allocation, no exceptions, all float, finite output for any finite input.
#pragma once

#include "core/math/color_space.h"
#include "core/math/types.h"

#include <span>

namespace inkray {

enum class NoiseKind : unsigned char { value, gradient };  // value noise, gradient (Perlin) noise
struct NoiseResult {
  float fac;
  Color color;
};
// Fractal noise in 3D at p * scale: `octaves` in [1, 16] (clamp), each octave doubles the frequency
// and multiplies amplitude by `roughness` in [0,1]; result normalised by the sum of amplitudes so
// fac lies in [0, 1] (0.5 mean). distortion >= 0 offsets p by a noise vector times distortion before
// evaluation (Blender's Distortion). color: three decorrelated fac values (offset seeds) as RGB; as in
// Blender, color.r is fac itself. scale <= 0 (or NaN) evaluates everything at the origin.
// With one octave, no distortion and scale 1, fac is exactly value_noise(p) or gradient_noise(p).
NoiseResult noise_texture(Vec3 p, NoiseKind kind, float scale, int octaves, float roughness,
                          float distortion);
// Single-octave building blocks, each in [0, 1], smooth (C1 at least: quintic fade for gradient noise),
// deterministic, using hash functions from core/math/hash.h on integer lattice coordinates.
// value_noise at an integer point (i, j, k) is exactly the lattice value
// u32_to_unit_float(hash_combine(uint32_t(i), uint32_t(j), uint32_t(k), 0u)); in between it blends the
// eight corners with the quintic fade too (C2). gradient_noise is 0.5 at every integer point.
float value_noise(Vec3 p);
float gradient_noise(Vec3 p);

struct VoronoiResult {
  float distance;
  Color color;
  Vec3 position;
};
// F1 Voronoi (Worley) at p * scale in 3D, Euclidean distance in scaled space, each cell's feature
// point jittered by randomness in [0,1] (0 = cell centres, a regular grid); color = hash colour of the
// nearest cell, position = nearest feature point in unscaled space. Search the 27 neighbour cells.
// scale <= 0 (or below 1e-30, where position would overflow) evaluates at the origin; position is then 0.
VoronoiResult voronoi_texture(Vec3 p, float scale, float randomness);

// rgb_to_hsv and hsv_to_rgb come from core/math/color_space.h (included above) with the same
// signatures; there the hue is in degrees [0, 360) (wrapping) and s, v in [0, 1]. Declaring a second
// pair here with hue in [0, 1] would clash with those inline definitions (an ODR violation).
// Blender's Hue/Saturation/Value node: hue shifts by (hue - 0.5) turns (wrapping), saturation and value
// multiply, result blended with the input by fac in [0,1]. Output never negative. Value is not clamped
// to 1, so HDR colours and value > 1 brighten as in Blender; saturation is clamped to [0, 1].
Color hsv_adjust(Color c, float hue, float saturation, float value, float fac);

enum class BlendMode : unsigned char { mix, multiply, screen, overlay, add };
// Blender's MixRGB: fac clamped to [0,1]; mix = lerp(a,b,fac); multiply = lerp(a, a*b, fac);
// screen = 1 - (1 - fac + fac*(1-b)) * (1-a); overlay per channel: a < 0.5 ? a*(1-fac + 2*fac*b)
// : 1 - (1-fac + 2*fac*(1-b))*(1-a); add = a + fac*b.
Color blend_colors(BlendMode mode, float fac, Color a, Color b);

enum class RampInterpolation : unsigned char { constant, linear, ease };
struct RampStop {
  float position;
  Color color;
};
// Stops sorted by position (caller guarantees; positions in [0,1]); x clamped to [0,1].
// Below the first stop: its colour; above the last: the last's. constant: colour of the last stop
// whose position <= x; linear: lerp between neighbours; ease: lerp with t smoothed by 3t^2-2t^3.
// Zero stops: black. Coincident stops: no division by zero; x at their position takes the later one.
Color ramp_eval(std::span<const RampStop> stops, float x, RampInterpolation interpolation);

// Blender's Fresnel node: dielectric Fresnel reflectance for the view direction, ior >= 1 (clamp to
// 1.0001 min), cos_theta = dot(normal, view) (view points away from the surface); when cos_theta < 0
// the ray is inside: use 1/ior and |cos_theta|. Result in [0,1].
float fresnel_factor(float ior, float cos_theta);
// Blender's Layer Weight node for blend in [0,1]: fresnel output = fresnel_factor(1/(1 - blend) with
// blend clamped to at most 0.99999, cos_theta); facing output = 1 - pow(|cos_theta|, blend<0.5 ? 2*blend
// : 0.5/(1-blend)).
struct LayerWeight {
  float fresnel;
  float facing;
};
LayerWeight layer_weight(float blend, float cos_theta);

}  // namespace inkray
