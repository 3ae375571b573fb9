// Owen-scrambled Sobol: stratification of every prefix and order independence.
#include "core/sampling/sampler.h"

#include <gtest/gtest.h>

#include <vector>

namespace inkray {
namespace {

// For N = 2^k points, every elementary interval of area 1/N (2^a by 2^b cells
// with a + b = k) must hold exactly one point: a (0,k,2)-net.
void expect_net(const std::vector<Vec2>& pts) {
  const int n = int(pts.size());
  const int k = std::countr_zero(unsigned(n));
  for (int a = 0; a <= k; ++a) {
    const int cols = 1 << a, rows = 1 << (k - a);
    std::vector<int> cells(size_t(n), 0);
    for (const Vec2& p : pts) {
      ASSERT_GE(p.x, 0.f);
      ASSERT_LT(p.x, 1.f);
      ASSERT_GE(p.y, 0.f);
      ASSERT_LT(p.y, 1.f);
      const int cx = int(p.x * float(cols)), cy = int(p.y * float(rows));
      ++cells[size_t(cy * cols + cx)];
    }
    for (int c = 0; c < n; ++c)
      ASSERT_EQ(cells[size_t(c)], 1) << "n=" << n << " cols=" << cols << " cell " << c;
  }
}

TEST(SamplingSobol, EveryElementaryIntervalHoldsOnePoint) {
  for (uint32_t seed : {0u, 7u, 123456u}) {
    for (uint32_t pixel : {0u, 1u, 99u}) {
      for (int n = 4; n <= 1024; n *= 2) {
        for (uint32_t dim_pair : {0u, 1u, 5u, 37u}) {
          std::vector<Vec2> pts;
          for (int i = 0; i < n; ++i) {
            const Sampler s(pixel, pixel * 3, uint32_t(i), seed);
            pts.push_back(s.get_pair(dim_pair));
          }
          expect_net(pts);
        }
      }
    }
  }
}

TEST(SamplingSobol, ValuesDoNotDependOnDrawOrder) {
  std::vector<std::vector<Vec2>> forward(64);
  for (uint32_t i = 0; i < 64; ++i) {
    const Sampler s(12, 34, i, 5);
    for (uint32_t d = 0; d < 10; ++d) forward[i].push_back(s.get_pair(d));
  }
  // Reverse sample order and dimension order, with fresh samplers.
  for (int i = 63; i >= 0; --i) {
    for (int d = 9; d >= 0; --d) {
      const Sampler s(12, 34, uint32_t(i), 5);
      EXPECT_EQ(s.get_pair(uint32_t(d)), forward[size_t(i)][size_t(d)]);
    }
  }
}

TEST(SamplingSobol, PixelsAndDimensionsAreDecorrelated) {
  // Different pixels and dimension pairs must not produce the same sequence.
  const Sampler a(0, 0, 3, 1), b(1, 0, 3, 1);
  EXPECT_NE(a.get_pair(0), b.get_pair(0));
  EXPECT_NE(a.get_pair(0), a.get_pair(1));
  // The mean over many samples of one dimension is close to 1/2.
  double sum = 0.0;
  for (uint32_t i = 0; i < 4096; ++i) {
    const Sampler s(5, 6, i, 2);
    sum += s.get_pair(11).x;
  }
  EXPECT_NEAR(sum / 4096.0, 0.5, 1e-3);
}

}  // namespace
}  // namespace inkray
