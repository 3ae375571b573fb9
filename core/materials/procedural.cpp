// Procedural node maths: lattice noise, fractal sums, Voronoi cells, HSV edits, MixRGB, colour ramps and
// the Fresnel / Layer Weight factors. Every input is clamped or guarded so the shading loop never sees a
// NaN or infinity coming out of here, whatever finite values a material graph feeds in.
#include "core/materials/procedural.h"

#include "core/materials/fresnel.h"
#include "core/math/hash.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace inkray {
namespace {

// Beyond 2^30 a float has no fractional bits left, so the lattice stops changing anyway; clamping there
// keeps floor() -> int conversions (and their +1 neighbours) inside int32.
constexpr float kLatticeLimit = 0x1p30f;
constexpr float kFloatMax = std::numeric_limits<float>::max();
constexpr int kMaxOctaves = 16;
// Seeds of one fractal channel are channel * kOctaveSeeds + octave, so channels never share a lattice.
constexpr uint32_t kOctaveSeeds = 16;
constexpr uint32_t kDistortionChannel = 3;  // channels 0-2 are fac / colour, 3-5 the distortion vector
// Below this a Voronoi position (feature / scale) could overflow; such scales act as 0.
constexpr float kMinVoronoiScale = 1e-30f;

// NaN goes to lo: every caller picks lo as the neutral choice.
inline float clamp_nan(float x, float lo, float hi) { return x > lo ? (x < hi ? x : hi) : lo; }
inline float finite_or_zero(float x) { return x == x ? glm::clamp(x, -kFloatMax, kFloatMax) : 0.f; }
inline Color finite_or_zero(Color c) {
  return {finite_or_zero(c.r), finite_or_zero(c.g), finite_or_zero(c.b)};
}
inline float lattice_coord(float x) { return x == x ? glm::clamp(x, -kLatticeLimit, kLatticeLimit) : 0.f; }
inline Vec3 lattice_point(Vec3 p) { return {lattice_coord(p.x), lattice_coord(p.y), lattice_coord(p.z)}; }

// Quintic fade 6t^5 - 15t^4 + 10t^3: zero first and second derivatives at the lattice, so the blend is C2.
inline float fade(float t) { return t * t * t * (t * (t * 6.f - 15.f) + 10.f); }
inline float lerp(float a, float b, float t) { return a + t * (b - a); }

struct LatticeCell {
  int x, y, z;  // integer corner below p
  Vec3 f;       // p - corner, in [0,1]
};
inline LatticeCell locate(Vec3 p) {
  p = lattice_point(p);
  const Vec3 c = glm::floor(p);
  return {int(c.x), int(c.y), int(c.z), p - c};
}

inline uint32_t lattice_hash(int x, int y, int z, uint32_t seed) {
  return hash_combine(uint32_t(x), uint32_t(y), uint32_t(z), seed);
}

inline float trilerp(const float c[8], Vec3 u) {
  const float x00 = lerp(c[0], c[1], u.x), x10 = lerp(c[2], c[3], u.x);
  const float x01 = lerp(c[4], c[5], u.x), x11 = lerp(c[6], c[7], u.x);
  return lerp(lerp(x00, x10, u.y), lerp(x01, x11, u.y), u.z);
}

float value_noise_seeded(Vec3 p, uint32_t seed) {
  const LatticeCell cell = locate(p);
  float c[8];
  for (int i = 0; i < 8; ++i)
    c[i] =
        u32_to_unit_float(lattice_hash(cell.x + (i & 1), cell.y + ((i >> 1) & 1), cell.z + (i >> 2), seed));
  const Vec3 u{fade(cell.f.x), fade(cell.f.y), fade(cell.f.z)};
  return trilerp(c, u);
}

// Perlin's 12 cube-edge gradients (16 entries, four repeated) dotted with the offset from the corner.
inline float gradient_dot(uint32_t h, float x, float y, float z) {
  h >>= 28;  // the top bits of the pcg mixer are its best mixed
  const float u = h < 8u ? x : y;
  const float v = h < 4u ? y : (h == 12u || h == 14u ? x : z);
  return ((h & 1u) ? -u : u) + ((h & 2u) ? -v : v);
}

// With Perlin's 12 edge gradients improved noise spans exactly [-1, 1] (the extremes sit at cell face
// centres; 4M samples plus hill climbing found no more), so 0.5 + 0.5 n fills [0,1] and the clamp
// after it only absorbs rounding.
float gradient_noise_seeded(Vec3 p, uint32_t seed) {
  const LatticeCell cell = locate(p);
  float c[8];
  for (int i = 0; i < 8; ++i) {
    const int dx = i & 1, dy = (i >> 1) & 1, dz = i >> 2;
    c[i] = gradient_dot(lattice_hash(cell.x + dx, cell.y + dy, cell.z + dz, seed), cell.f.x - float(dx),
                        cell.f.y - float(dy), cell.f.z - float(dz));
  }
  const Vec3 u{fade(cell.f.x), fade(cell.f.y), fade(cell.f.z)};
  return clamp_nan(0.5f + 0.5f * trilerp(c, u), 0.f, 1.f);
}

inline float single_noise(Vec3 p, NoiseKind kind, uint32_t seed) {
  return kind == NoiseKind::gradient ? gradient_noise_seeded(p, seed) : value_noise_seeded(p, seed);
}

// Weighted mean of the octaves: each lies in [0,1], so the mean does too, centred on 0.5.
float fractal_noise(Vec3 p, NoiseKind kind, int octaves, float roughness, uint32_t channel) {
  float sum = 0.f, total = 0.f, amplitude = 1.f;
  for (int i = 0; i < octaves && amplitude > 0.f; ++i) {
    sum += amplitude * single_noise(p, kind, channel * kOctaveSeeds + uint32_t(i));
    total += amplitude;
    amplitude *= roughness;
    p = lattice_point(p * 2.f);  // stays finite however many doublings follow
  }
  return clamp_nan(sum / total, 0.f, 1.f);  // total >= 1: the first octave always counts
}

// Blender's overlay for one channel.
inline float overlay_channel(float a, float b, float fac) {
  const float facm = 1.f - fac;
  return a < 0.5f ? a * (facm + 2.f * fac * b) : 1.f - (facm + 2.f * fac * (1.f - b)) * (1.f - a);
}

}  // namespace

float value_noise(Vec3 p) { return value_noise_seeded(p, 0u); }
float gradient_noise(Vec3 p) { return gradient_noise_seeded(p, 0u); }

NoiseResult noise_texture(Vec3 p, NoiseKind kind, float scale, int octaves, float roughness,
                          float distortion) {
  scale = scale > 0.f ? scale : 0.f;
  octaves = glm::clamp(octaves, 1, kMaxOctaves);
  roughness = clamp_nan(roughness, 0.f, 1.f);
  distortion = clamp_nan(distortion, 0.f, kFloatMax);
  Vec3 q = lattice_point(p * scale);
  if (distortion > 0.f) {
    // Signed single-octave noise per axis, on channels of their own so the offset is not fac itself.
    const uint32_t s = kDistortionChannel * kOctaveSeeds;
    const Vec3 offset{single_noise(q, kind, s), single_noise(q, kind, s + kOctaveSeeds),
                      single_noise(q, kind, s + 2u * kOctaveSeeds)};
    q = lattice_point(q + distortion * (2.f * offset - 1.f));
  }
  const float fac = fractal_noise(q, kind, octaves, roughness, 0u);
  return {fac, Color(fac, fractal_noise(q, kind, octaves, roughness, 1u),
                     fractal_noise(q, kind, octaves, roughness, 2u))};
}

VoronoiResult voronoi_texture(Vec3 p, float scale, float randomness) {
  if (!(scale >= kMinVoronoiScale)) scale = 0.f;
  randomness = clamp_nan(randomness, 0.f, 1.f);
  const LatticeCell cell = locate(p * scale);
  // Work relative to the cell holding p: exact distances even at huge coordinates.
  float best = kInfinity;
  Vec3 best_feature(0.5f);
  uint32_t best_hash = lattice_hash(cell.x, cell.y, cell.z, 0u);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const uint32_t h = lattice_hash(cell.x + dx, cell.y + dy, cell.z + dz, 0u);
        Vec3 feature = Vec3(float(dx), float(dy), float(dz)) + 0.5f;
        if (randomness > 0.f) {
          const Vec3 jitter{u32_to_unit_float(hash_u32(h + 1u)), u32_to_unit_float(hash_u32(h + 2u)),
                            u32_to_unit_float(hash_u32(h + 3u))};
          feature += randomness * (jitter - 0.5f);
        }
        const Vec3 d = feature - cell.f;
        const float d2 = glm::dot(d, d);
        if (d2 < best) {
          best = d2;
          best_feature = feature;
          best_hash = h;
        }
      }
  const Color color{u32_to_unit_float(hash_u32(best_hash + 4u)), u32_to_unit_float(hash_u32(best_hash + 5u)),
                    u32_to_unit_float(hash_u32(best_hash + 6u))};
  Vec3 position(0.f);
  if (scale > 0.f) {
    const Vec3 corner{float(cell.x), float(cell.y), float(cell.z)};
    position = finite_or_zero((corner + best_feature) / scale);
  }
  return {std::sqrt(best), color, position};
}

Color hsv_adjust(Color c, float hue, float saturation, float value, float fac) {
  fac = clamp_nan(fac, 0.f, 1.f);
  const Color hsv = rgb_to_hsv(c);  // hue in degrees (core/math/color_space.h)
  // hsv_to_rgb wraps the hue (and maps a non-finite one to 0) but clamps v to 1; it is linear in v, so
  // converting at v = 1 and scaling keeps HDR colours and value > 1 as Blender does.
  const float h = hsv.x + (hue - 0.5f) * 360.f;
  const float s = clamp_nan(hsv.y * saturation, 0.f, 1.f);
  const Color adjusted = hsv_to_rgb({h, s, 1.f}) * (hsv.z * value);
  const Color out = (1.f - fac) * c + fac * adjusted;
  return finite_or_zero(glm::max(out, Color(0.f)));  // over-saturation can dip below 0
}

Color blend_colors(BlendMode mode, float fac, Color a, Color b) {
  fac = clamp_nan(fac, 0.f, 1.f);
  const float facm = 1.f - fac;
  Color out = a;
  switch (mode) {
    case BlendMode::mix:
      out = facm * a + fac * b;
      break;
    case BlendMode::multiply:
      out = facm * a + fac * (a * b);
      break;
    case BlendMode::screen:
      out = Color(1.f) - (Color(facm) + fac * (Color(1.f) - b)) * (Color(1.f) - a);
      break;
    case BlendMode::overlay:
      out = {overlay_channel(a.r, b.r, fac), overlay_channel(a.g, b.g, fac), overlay_channel(a.b, b.b, fac)};
      break;
    case BlendMode::add:
      out = a + fac * b;
      break;
  }
  return finite_or_zero(out);
}

Color ramp_eval(std::span<const RampStop> stops, float x, RampInterpolation interpolation) {
  if (stops.empty()) return Color(0.f);
  x = clamp_nan(x, 0.f, 1.f);
  // Last stop at or below x. Every later stop lies strictly above x, so the segment after it has
  // positive length even when stops coincide.
  size_t i = stops.size();
  for (size_t k = 0; k < stops.size(); ++k)
    if (stops[k].position <= x) i = k;
  if (i == stops.size()) return finite_or_zero(stops.front().color);  // below the first stop
  if (i + 1 == stops.size() || interpolation == RampInterpolation::constant)
    return finite_or_zero(stops[i].color);
  const RampStop& lo = stops[i];
  const RampStop& hi = stops[i + 1];
  float t = clamp_nan((x - lo.position) / (hi.position - lo.position), 0.f, 1.f);  // NaN position -> lo
  if (interpolation == RampInterpolation::ease) t = t * t * (3.f - 2.f * t);
  // Weighted sum rather than a + t*(b-a): no overflow from b - a on huge colours, exact at t = 0 and 1.
  return finite_or_zero((1.f - t) * lo.color + t * hi.color);
}

float fresnel_factor(float ior, float cos_theta) {
  // Upper clamp: 1/ior squared must stay a normal float for the inside case.
  const float eta = clamp_nan(ior, 1.0001f, 1e6f);
  cos_theta = cos_theta == cos_theta ? glm::clamp(cos_theta, -1.f, 1.f) : 1.f;
  return clamp_nan(fresnel_dielectric(cos_theta, eta), 0.f, 1.f);
}

LayerWeight layer_weight(float blend, float cos_theta) {
  blend = clamp_nan(blend, 0.f, 0.99999f);
  const float abs_cos = clamp_nan(std::abs(cos_theta), 0.f, 1.f);
  const float exponent = blend < 0.5f ? 2.f * blend : 0.5f / (1.f - blend);
  return {fresnel_factor(1.f / (1.f - blend), cos_theta),
          clamp_nan(1.f - std::pow(abs_cos, exponent), 0.f, 1.f)};
}

}  // namespace inkray
