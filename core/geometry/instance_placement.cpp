#include "core/geometry/instance_placement.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace inkray {
namespace {

bool finite(const Mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

double largest_scale(const Decomposition& d) {
  return std::max({std::abs(d.upper[0][0]), std::abs(d.upper[1][1]), std::abs(d.upper[2][2])});
}

// The decomposition at `t` of the way from `a` to `b` (b's rotation on a's side), as
// Embree interpolates it.
Decomposition interpolate(const Decomposition& a, const Decomposition& b, double t) {
  Decomposition d;
  d.upper = (1.0 - t) * a.upper + t * b.upper;
  d.translation = (1.0 - t) * a.translation + t * b.translation;
  d.rotation = glm::normalize(glm::slerp(a.rotation, b.rotation, t));
  return d;
}

}  // namespace

Decomposition decompose(const Transform& t) {
  const glm::dmat3 linear(glm::dmat4(t.m));
  Decomposition d;
  glm::dmat3 q(0.0);
  for (int c = 0; c < 3; ++c) {
    glm::dvec3 v = linear[c];
    for (int k = 0; k < c; ++k) {  // modified Gram-Schmidt: stable for near-parallel columns
      d.upper[c][k] = glm::dot(q[k], v);
      v -= d.upper[c][k] * q[k];
    }
    const double len = glm::length(v);
    d.upper[c][c] = len;
    q[c] = len > 0.0 ? v / len : glm::dvec3(c == 0, c == 1, c == 2);
    for (int k = c + 1; k < 3; ++k) d.upper[c][k] = 0.0;
  }
  if (glm::determinant(q) < 0.0) {  // a reflection: its sign moves into S's last scale
    q[2] = -q[2];
    d.upper[2][2] = -d.upper[2][2];
  }
  d.rotation = glm::normalize(glm::quat_cast(q));
  d.translation = glm::dvec3(glm::dvec4(t.m[3]));
  return d;
}

RTCQuaternionDecomposition embree_decomposition(const Decomposition& d) {
  RTCQuaternionDecomposition qd;
  rtcInitQuaternionDecomposition(&qd);
  rtcQuaternionDecompositionSetScale(&qd, float(d.upper[0][0]), float(d.upper[1][1]), float(d.upper[2][2]));
  rtcQuaternionDecompositionSetSkew(&qd, float(d.upper[1][0]), float(d.upper[2][0]), float(d.upper[2][1]));
  rtcQuaternionDecompositionSetQuaternion(&qd, float(d.rotation.w), float(d.rotation.x), float(d.rotation.y),
                                          float(d.rotation.z));
  rtcQuaternionDecompositionSetTranslation(&qd, float(d.translation.x), float(d.translation.y),
                                           float(d.translation.z));
  return qd;
}

bool placeable(const Transform& t) {
  if (!finite(t.m) || !finite(t.inv)) return false;
  const Decomposition d = decompose(t);
  const double largest = largest_scale(d);
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(d.upper[i][i]) > kMinScaleRatio * largest)) return false;
  return true;
}

std::vector<MotionPiece> motion_pieces(const Transform& open, const Transform& close) {
  if (!finite(open.m) || !finite(close.m)) return {};
  const Decomposition a = decompose(open);
  Decomposition b = decompose(close);
  if (glm::dot(a.rotation, b.rotation) < 0.0) b.rotation = -b.rotation;
  // S is triangular, so the transform is singular exactly where one of its diagonal
  // scales is zero; each moves linearly over the shutter. The instants to leave out
  // are where one is within kMinScaleRatio of the largest either end reaches.
  const double largest = std::max(largest_scale(a), largest_scale(b));
  const double near_zero = kMinScaleRatio * largest;
  std::vector<std::pair<double, double>> gaps;
  for (int i = 0; i < 3; ++i) {
    const double from = a.upper[i][i], slope = b.upper[i][i] - from;
    if (slope == 0.0) {
      if (!(std::abs(from) > near_zero)) return {};  // singular all the way
      continue;
    }
    // |from + slope t| <= near_zero
    const double t0 = (-near_zero - from) / slope, t1 = (near_zero - from) / slope;
    const double lo = std::min(t0, t1), hi = std::max(t0, t1);
    if (hi >= 0.0 && lo <= 1.0) gaps.emplace_back(lo, hi);
  }
  if (gaps.empty()) {
    MotionPiece whole;
    whole.at_start = embree_decomposition(a);
    whole.at_end = embree_decomposition(b);
    return {whole};
  }
  std::sort(gaps.begin(), gaps.end());
  std::vector<MotionPiece> pieces;
  double start = 0.0;
  const auto piece = [&](double from, double to) {
    // A stretch too short for a float time to land in is no piece.
    if (!(float(to) > float(from))) return;
    MotionPiece p;
    p.start = float(from);
    p.end = float(to);
    p.at_start = embree_decomposition(interpolate(a, b, from));
    p.at_end = embree_decomposition(interpolate(a, b, to));
    pieces.push_back(p);
  };
  for (const auto& [lo, hi] : gaps) {
    if (lo > start) piece(start, std::min(lo, 1.0));
    start = std::max(start, hi);
    if (start >= 1.0) break;
  }
  if (start < 1.0) piece(start, 1.0);
  return pieces;
}

}  // namespace inkray
