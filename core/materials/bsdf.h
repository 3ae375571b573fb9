// BSDFs: a closed set of scattering models evaluated in the local shading
// frame, where the shading normal is +z and both directions point away from the
// surface. f() excludes the cosine; a sample's weight is f * |cos wi| / pdf.
// Delta lobes return pdf = lobe probability and f = F / |cos wi|, so the same
// weight formula holds; eval() and pdf() of a delta lobe are zero.
#pragma once

#include "core/math/types.h"

#include <optional>
#include <variant>

namespace inkray {

struct LambertBsdf {
  Color albedo{0.8f};
};
// GGX microfacet conductor with Schlick Fresnel from F0; alpha 0 is a mirror.
struct ConductorBsdf {
  Color f0{0.95f};
  float alpha = 0.f;  // GGX alpha (= roughness^2)
};
// Smooth or rough (GGX) dielectric. eta = n_inside / n_outside; the outside is
// the side the shading normal points to (local +z).
struct DielectricBsdf {
  float eta = 1.5f;
  float alpha = 0.f;
  Color tint{1.f};
};
// Passes light straight through, unchanged but for the tint.
struct TransparentBsdf {
  Color tint{1.f};
};

using Bsdf = std::variant<LambertBsdf, ConductorBsdf, DielectricBsdf, TransparentBsdf>;

struct BsdfSample {
  Color f{0.f};
  Vec3 wi{0.f};
  float pdf = 0.f;
  bool is_delta = false;         // sampled from a delta lobe: NEE and MIS do not apply
  bool is_transmission = false;  // wi is on the other side of the surface
  float eta = 1.f;               // relative IOR crossed by a transmission, for Russian roulette
};

Color bsdf_eval(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi);
float bsdf_pdf(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi);
// u_lobe picks a lobe (reflect/transmit), u the direction within it.
std::optional<BsdfSample> bsdf_sample(const Bsdf& bsdf, const Vec3& wo, float u_lobe, Vec2 u);
// True when every lobe is a delta: the light sampler is skipped.
bool bsdf_is_delta(const Bsdf& bsdf);

}  // namespace inkray
