// Isotropic Trowbridge-Reitz (GGX) microfacet distribution with Smith
// height-correlated masking and visible-normal sampling, in the local shading
// frame (normal +z). Shared by the conductor and dielectric BSDFs.
#pragma once

#include "core/math/types.h"

#include <cmath>

namespace inkray {

struct TrowbridgeReitz {
  float alpha = 0.f;

  // Below this roughness the lobe is narrower than float precision can sample
  // and evaluate reliably, so the BSDFs switch to a delta (pbrt-v4's cutoff).
  bool effectively_smooth() const { return alpha < 1e-3f; }

  // Normal distribution D(wm); written without tan^2 so that it stays finite
  // for tiny alpha and grazing wm.
  float d(const Vec3& wm) const {
    const float a2 = sqr(alpha);
    const float denom = sqr(wm.z) * (a2 - 1.f) + 1.f;
    if (denom <= 0.f) return 0.f;
    return a2 / (kPi * sqr(denom));
  }

  // sqrt(a^2 + (1 - a^2) cos^2): the common factor of Smith's Lambda,
  // Lambda(w) = (s / |cos| - 1) / 2.
  float smith_s(const Vec3& w) const {
    const float a2 = sqr(alpha);
    return std::sqrt(a2 + (1.f - a2) * sqr(w.z));
  }
  // Masking of one direction, G1 = 1 / (1 + Lambda).
  float g1(const Vec3& w) const {
    const float c = std::abs(w.z);
    return c > 0.f ? 2.f * c / (c + smith_s(w)) : 0.f;
  }
  // Height-correlated masking-shadowing 1 / (1 + Lambda(wo) + Lambda(wi)),
  // rearranged so that a grazing direction gives 0 rather than inf / inf.
  float g(const Vec3& wo, const Vec3& wi) const {
    const float co = std::abs(wo.z), ci = std::abs(wi.z);
    const float denom = smith_s(wo) * ci + smith_s(wi) * co;
    return denom > 0.f ? 2.f * co * ci / denom : 0.f;
  }

  // Distribution of normals visible from w (Heitz 2018), a density over wm.
  float d_visible(const Vec3& w, const Vec3& wm) const {
    const float c = std::abs(w.z);
    if (c == 0.f) return 0.f;
    return g1(w) / c * d(wm) * std::abs(glm::dot(w, wm));
  }
  float pdf(const Vec3& w, const Vec3& wm) const { return d_visible(w, wm); }

  // Samples a visible normal (z >= 0) with the spherical-cap method of Dupuy
  // and Benyoub 2023: in the stretched (alpha = 1) configuration the visible
  // normals are the sum of the view direction and a uniform point on the cap
  // of the unit sphere it sees. A w below the surface sees the distribution
  // from -w, which has the same visible density up to the sign of dot(w, wm).
  Vec3 sample_wm(Vec3 w, Vec2 u) const {
    if (w.z < 0.f) w = -w;
    const Vec3 w_std = glm::normalize(Vec3(alpha * w.x, alpha * w.y, w.z));
    const float phi = 2.f * kPi * u.x;
    const float z = (1.f - u.y) * (1.f + w_std.z) - w_std.z;
    const float sin_theta = safe_sqrt(1.f - sqr(z));
    const Vec3 h = Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), z) + w_std;
    const Vec3 wm = Vec3(alpha * h.x, alpha * h.y, glm::max(0.f, h.z));
    const float len2 = glm::dot(wm, wm);
    return len2 > 0.f ? wm / std::sqrt(len2) : Vec3(0.f, 0.f, 1.f);
  }
};

}  // namespace inkray
