// BSDF evaluation, pdf and sampling, after pbrt-v4's bxdfs.cpp. Every model
// works in the local shading frame; each has eval/pdf/sample overloads and the
// public functions dispatch on the variant.
#include "core/materials/bsdf.h"

#include "core/materials/fresnel.h"
#include "core/materials/microfacet.h"
#include "core/sampling/warp.h"

namespace inkray {
namespace {

bool same_hemisphere(const Vec3& a, const Vec3& b) { return a.z * b.z > 0.f; }

// The last gate before a sample leaves: a bad float here would poison a pixel.
std::optional<BsdfSample> checked(const BsdfSample& s) {
  if (!(s.pdf > 0.f) || !std::isfinite(s.pdf) || !is_finite(s.f) || !is_finite(s.wi) || s.wi.z == 0.f)
    return std::nullopt;
  return s;
}

// ---- Lambert: two-sided, reflects on whichever side wo is.

Color eval(const LambertBsdf& b, const Vec3& wo, const Vec3& wi) {
  return same_hemisphere(wo, wi) ? b.albedo * kInvPi : Color(0.f);
}
float pdf(const LambertBsdf&, const Vec3& wo, const Vec3& wi) {
  return same_hemisphere(wo, wi) ? cosine_hemisphere_pdf(std::abs(wi.z)) : 0.f;
}
std::optional<BsdfSample> sample(const LambertBsdf& b, const Vec3& wo, float, Vec2 u) {
  if (wo.z == 0.f) return std::nullopt;
  Vec3 wi = sample_cosine_hemisphere(u);
  if (wo.z < 0.f) wi.z = -wi.z;
  return checked({.f = b.albedo * kInvPi, .wi = wi, .pdf = cosine_hemisphere_pdf(std::abs(wi.z))});
}

// ---- Conductor: GGX with Schlick Fresnel, a mirror when effectively smooth.

Color eval(const ConductorBsdf& b, const Vec3& wo, const Vec3& wi) {
  const TrowbridgeReitz distrib{b.alpha};
  if (distrib.effectively_smooth() || !same_hemisphere(wo, wi)) return Color(0.f);
  const Vec3 wm = wo + wi;
  if (glm::dot(wm, wm) == 0.f) return Color(0.f);
  const Vec3 n = glm::normalize(wm);
  const Color fr = fresnel_schlick(b.f0, glm::dot(wo, n));
  return distrib.d(n) * distrib.g(wo, wi) * fr / (4.f * std::abs(wo.z * wi.z));
}
float pdf(const ConductorBsdf& b, const Vec3& wo, const Vec3& wi) {
  const TrowbridgeReitz distrib{b.alpha};
  if (distrib.effectively_smooth() || !same_hemisphere(wo, wi)) return 0.f;
  Vec3 wm = wo + wi;
  if (glm::dot(wm, wm) == 0.f) return 0.f;
  wm = glm::normalize(wm);
  if (wm.z < 0.f) wm = -wm;
  // Reflection Jacobian dwm/dwi = 1 / (4 |wo . wm|).
  return distrib.pdf(wo, wm) / (4.f * std::abs(glm::dot(wo, wm)));
}
std::optional<BsdfSample> sample(const ConductorBsdf& b, const Vec3& wo, float, Vec2 u) {
  if (wo.z == 0.f) return std::nullopt;
  const TrowbridgeReitz distrib{b.alpha};
  if (distrib.effectively_smooth()) {
    const Vec3 wi(-wo.x, -wo.y, wo.z);
    const float cos_i = std::abs(wi.z);
    return checked({.f = fresnel_schlick(b.f0, cos_i) / cos_i, .wi = wi, .pdf = 1.f, .is_delta = true});
  }
  const Vec3 wm = distrib.sample_wm(wo, u);
  const Vec3 wi = reflect(wo, wm);
  if (!same_hemisphere(wo, wi)) return std::nullopt;
  const float p = distrib.pdf(wo, wm) / (4.f * std::abs(glm::dot(wo, wm)));
  const Color fr = fresnel_schlick(b.f0, glm::dot(wo, wm));
  const Color f = distrib.d(wm) * distrib.g(wo, wi) * fr / (4.f * std::abs(wo.z * wi.z));
  return checked({.f = f, .wi = wi, .pdf = p});
}

// ---- Dielectric: exact Fresnel; smooth (two deltas) or rough (Walter et al.
// 2007). Transmitted radiance is divided by etap^2 because radiance is
// compressed into the smaller solid angle of the denser medium.

bool is_smooth(const DielectricBsdf& b) {
  return b.eta == 1.f || TrowbridgeReitz{b.alpha}.effectively_smooth();
}

// Reflection probability among the two lobes for Fresnel reflectance r.
// Splitting by R keeps the weight of either lobe near 1.
float reflect_probability(float r) { return r; }

std::optional<BsdfSample> sample_smooth(const DielectricBsdf& b, const Vec3& wo, float u_lobe) {
  const float r = fresnel_dielectric(wo.z, b.eta);
  const float pr = reflect_probability(r);
  if (u_lobe < pr) {
    const Vec3 wi(-wo.x, -wo.y, wo.z);
    return checked({.f = Color(r / std::abs(wi.z)), .wi = wi, .pdf = pr, .is_delta = true});
  }
  const auto refr = refract(wo, Vec3(0.f, 0.f, 1.f), b.eta);
  if (!refr) return std::nullopt;
  const Color ft = b.tint * ((1.f - r) / (std::abs(refr->wt.z) * sqr(refr->etap)));
  return checked({.f = ft,
                  .wi = refr->wt,
                  .pdf = 1.f - pr,
                  .is_delta = true,
                  .is_transmission = true,
                  .eta = refr->etap});
}

// The generalised half vector of a (wo, wi) pair, facing +z, and the etap of
// the crossing; nullopt when the pair cannot come from one microfacet.
struct HalfVector {
  Vec3 wm;
  float etap;
  bool reflect;
};
std::optional<HalfVector> half_vector(const DielectricBsdf& b, const Vec3& wo, const Vec3& wi) {
  if (wo.z == 0.f || wi.z == 0.f) return std::nullopt;
  const bool is_reflect = same_hemisphere(wo, wi);
  const float etap = is_reflect ? 1.f : (wo.z > 0.f ? b.eta : 1.f / b.eta);
  Vec3 wm = wi * etap + wo;
  if (glm::dot(wm, wm) == 0.f) return std::nullopt;
  wm = glm::normalize(wm);
  if (wm.z < 0.f) wm = -wm;
  // A microfacet seen from its back side cannot scatter: discard.
  if (glm::dot(wm, wi) * wi.z < 0.f || glm::dot(wm, wo) * wo.z < 0.f) return std::nullopt;
  return HalfVector{wm, etap, is_reflect};
}

// |dwm/dwi| for refraction through wm, and the squared denominator it shares
// with the BTDF.
float transmission_denom(const Vec3& wo, const Vec3& wi, const Vec3& wm, float etap) {
  return sqr(glm::dot(wi, wm) + glm::dot(wo, wm) / etap);
}

Color eval_rough(const DielectricBsdf& b, const Vec3& wo, const Vec3& wi, const HalfVector& h) {
  const TrowbridgeReitz distrib{b.alpha};
  const float r = fresnel_dielectric(glm::dot(wo, h.wm), b.eta);
  const float dg = distrib.d(h.wm) * distrib.g(wo, wi);
  if (h.reflect) return Color(dg * r / std::abs(4.f * wi.z * wo.z));
  const float denom = transmission_denom(wo, wi, h.wm, h.etap) * wi.z * wo.z;
  const float ft = dg * (1.f - r) * std::abs(glm::dot(wi, h.wm) * glm::dot(wo, h.wm) / denom);
  return b.tint * (ft / sqr(h.etap));
}

float pdf_rough(const DielectricBsdf& b, const Vec3& wo, const Vec3& wi, const HalfVector& h) {
  const TrowbridgeReitz distrib{b.alpha};
  const float pr = reflect_probability(fresnel_dielectric(glm::dot(wo, h.wm), b.eta));
  if (h.reflect) return distrib.pdf(wo, h.wm) / (4.f * std::abs(glm::dot(wo, h.wm))) * pr;
  const float dwm_dwi = std::abs(glm::dot(wi, h.wm)) / transmission_denom(wo, wi, h.wm, h.etap);
  return distrib.pdf(wo, h.wm) * dwm_dwi * (1.f - pr);
}

std::optional<BsdfSample> sample_rough(const DielectricBsdf& b, const Vec3& wo, float u_lobe, Vec2 u) {
  const TrowbridgeReitz distrib{b.alpha};
  const Vec3 wm = distrib.sample_wm(wo, u);
  const float r = fresnel_dielectric(glm::dot(wo, wm), b.eta);
  const float pr = reflect_probability(r);
  if (u_lobe < pr) {
    const Vec3 wi = reflect(wo, wm);
    if (!same_hemisphere(wo, wi)) return std::nullopt;
    const float p = distrib.pdf(wo, wm) / (4.f * std::abs(glm::dot(wo, wm))) * pr;
    const float f = distrib.d(wm) * distrib.g(wo, wi) * r / std::abs(4.f * wi.z * wo.z);
    return checked({.f = Color(f), .wi = wi, .pdf = p});
  }
  const auto refr = refract(wo, wm, b.eta);
  if (!refr || same_hemisphere(wo, refr->wt) || refr->wt.z == 0.f) return std::nullopt;
  const Vec3 wi = refr->wt;
  const float denom = transmission_denom(wo, wi, wm, refr->etap);
  const float p = distrib.pdf(wo, wm) * std::abs(glm::dot(wi, wm)) / denom * (1.f - pr);
  const float ft = distrib.d(wm) * distrib.g(wo, wi) * (1.f - r) *
                   std::abs(glm::dot(wi, wm) * glm::dot(wo, wm) / (wi.z * wo.z * denom));
  return checked(
      {.f = b.tint * (ft / sqr(refr->etap)), .wi = wi, .pdf = p, .is_transmission = true, .eta = refr->etap});
}

Color eval(const DielectricBsdf& b, const Vec3& wo, const Vec3& wi) {
  if (is_smooth(b)) return Color(0.f);
  const auto h = half_vector(b, wo, wi);
  return h ? eval_rough(b, wo, wi, *h) : Color(0.f);
}
float pdf(const DielectricBsdf& b, const Vec3& wo, const Vec3& wi) {
  if (is_smooth(b)) return 0.f;
  const auto h = half_vector(b, wo, wi);
  return h ? pdf_rough(b, wo, wi, *h) : 0.f;
}
std::optional<BsdfSample> sample(const DielectricBsdf& b, const Vec3& wo, float u_lobe, Vec2 u) {
  if (wo.z == 0.f) return std::nullopt;
  return is_smooth(b) ? sample_smooth(b, wo, u_lobe) : sample_rough(b, wo, u_lobe, u);
}

// ---- Transparent: a single delta straight through, no bending.

Color eval(const TransparentBsdf&, const Vec3&, const Vec3&) { return Color(0.f); }
float pdf(const TransparentBsdf&, const Vec3&, const Vec3&) { return 0.f; }
std::optional<BsdfSample> sample(const TransparentBsdf& b, const Vec3& wo, float, Vec2) {
  if (wo.z == 0.f) return std::nullopt;
  const Vec3 wi = -wo;
  return checked(
      {.f = b.tint / std::abs(wi.z), .wi = wi, .pdf = 1.f, .is_delta = true, .is_transmission = true});
}

}  // namespace

Color bsdf_eval(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi) {
  return std::visit([&](const auto& b) { return eval(b, wo, wi); }, bsdf);
}

float bsdf_pdf(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi) {
  return std::visit([&](const auto& b) { return pdf(b, wo, wi); }, bsdf);
}

std::optional<BsdfSample> bsdf_sample(const Bsdf& bsdf, const Vec3& wo, float u_lobe, Vec2 u) {
  return std::visit([&](const auto& b) { return sample(b, wo, u_lobe, u); }, bsdf);
}

bool bsdf_is_delta(const Bsdf& bsdf) {
  struct Visitor {
    bool operator()(const LambertBsdf&) const { return false; }
    bool operator()(const ConductorBsdf& b) const { return TrowbridgeReitz{b.alpha}.effectively_smooth(); }
    bool operator()(const DielectricBsdf& b) const { return is_smooth(b); }
    bool operator()(const TransparentBsdf&) const { return true; }
  };
  return std::visit(Visitor{}, bsdf);
}

}  // namespace inkray
