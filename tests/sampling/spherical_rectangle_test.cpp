// The spherical rectangle sampler (core/sampling/spherical_rectangle.h): its solid
// angle is the rectangle's, computed independently (Van Oosterom and Strackee's
// triangle formula), and its points are uniform in solid angle: chi-square over a
// grid of sub-rectangles, each expected to take its own solid angle's share.
#include "core/sampling/spherical_rectangle.h"

#include "core/math/hash.h"
#include "tests/support/chi_square.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

namespace inkray {
namespace {

using D3 = glm::dvec3;

// Solid angle of the triangle (a, b, c) seen from the origin.
double triangle_solid_angle(const D3& a, const D3& b, const D3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double num = std::abs(glm::dot(a, glm::cross(b, c)));
  const double den = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
  return 2.0 * std::atan2(num, den);
}

struct Rect {
  const char* name;
  Point3 from, corner;
  Vec3 x, y;
  float width, height;
  // The sub-rectangle [s0, s1] x [t0, t1] (fractions of the edges) seen from `from`.
  double solid_angle(double s0, double s1, double t0, double t1) const {
    const auto at = [&](double s, double t) {
      return D3(corner) + s * double(width) * D3(x) + t * double(height) * D3(y) - D3(from);
    };
    return triangle_solid_angle(at(s0, t0), at(s1, t0), at(s1, t1)) +
           triangle_solid_angle(at(s0, t0), at(s1, t1), at(s0, t1));
  }
};

const Vec3 kTilted = glm::normalize(Vec3(1.f, 0.f, 1.f)), kTiltedY = glm::normalize(Vec3(-1.f, 0.f, 1.f));
const Rect kRects[] = {
    {"under the centre", {0.f, 0.f, 0.f}, {-1.f, 1.f, -1.f}, {1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, 2.f, 2.f},
    {"long, to one side",
     {3.f, -0.5f, 0.2f},
     {-1.f, 1.f, -0.5f},
     {1.f, 0.f, 0.f},
     {0.f, 0.f, 1.f},
     4.f,
     0.5f},
    {"close, from behind", {0.3f, 1.1f, 0.2f}, {-1.f, 1.f, -1.f}, {1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, 2.f, 2.f},
    {"tilted, far", {0.f, 0.f, 0.f}, {4.f, 6.f, 3.f}, kTilted, kTiltedY, 1.f, 0.6f},
    {"grazing", {0.f, 0.f, 0.f}, {2.f, 0.02f, -1.f}, {1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, 3.f, 2.f},
};

TEST(SphericalRectangle, SolidAngleIsTheRectangles) {
  for (const Rect& r : kRects) {
    const auto s = spherical_rectangle(r.from, r.corner, r.x, r.y, r.width, r.height);
    ASSERT_TRUE(s) << r.name;
    const double expected = r.solid_angle(0, 1, 0, 1);
    EXPECT_NEAR(s->solid_angle, expected, 1e-6 * expected + 1e-9) << r.name;
  }
  // In the rectangle's plane it subtends nothing.
  EXPECT_FALSE(
      spherical_rectangle({0.f, 1.f, 0.f}, {-1.f, 1.f, -1.f}, {1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, 2.f, 2.f));
}

TEST(SphericalRectangle, PointsAreUniformInSolidAngle) {
  constexpr int kCells = 10, kSamples = 1000000;
  const double significance = test_support::sidak_significance(0.01, int(std::size(kRects)));
  for (const Rect& r : kRects) {
    const auto s = spherical_rectangle(r.from, r.corner, r.x, r.y, r.width, r.height);
    ASSERT_TRUE(s) << r.name;
    std::vector<double> observed(kCells * kCells, 0.0), expected(kCells * kCells, 0.0);
    for (int i = 0; i < kCells; ++i)
      for (int j = 0; j < kCells; ++j)
        expected[size_t(i * kCells + j)] = kSamples *
                                           r.solid_angle(double(i) / kCells, double(i + 1) / kCells,
                                                         double(j) / kCells, double(j + 1) / kCells) /
                                           s->solid_angle;
    Pcg32 rng(uint64_t(r.width * 1000.f) + 17);
    for (int k = 0; k < kSamples; ++k) {
      const Point3 p = sample_spherical_rectangle(*s, Vec2(rng.next_float(), rng.next_float()));
      // Back to the rectangle's own coordinates, then to its cell.
      const Vec3 d = p - r.corner;
      const float u = glm::dot(d, r.x) / r.width, v = glm::dot(d, r.y) / r.height;
      ASSERT_GE(u, -1e-4f) << r.name;
      ASSERT_LE(u, 1.f + 1e-4f) << r.name;
      ASSERT_GE(v, -1e-4f) << r.name;
      ASSERT_LE(v, 1.f + 1e-4f) << r.name;
      ASSERT_LT(std::abs(glm::dot(d, glm::cross(r.x, r.y))), 1e-3f * (r.width + r.height)) << r.name;
      const int i = std::clamp(int(u * kCells), 0, kCells - 1),
                j = std::clamp(int(v * kCells), 0, kCells - 1);
      observed[size_t(i * kCells + j)] += 1.0;
    }
    const test_support::ChiSquareResult chi = test_support::chi_square(observed, expected);
    EXPECT_TRUE(chi.error.empty()) << r.name << ": " << chi.error;
    EXPECT_GT(chi.p_value, significance)
        << r.name << ": statistic " << chi.statistic << ", " << chi.dof << " dof";
  }
}

}  // namespace
}  // namespace inkray
