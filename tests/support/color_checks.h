// Comparing colours and vectors channel by channel in tests.
#pragma once

#include "core/math/types.h"

#include <gtest/gtest.h>

namespace inkray::testing {

inline void expect_color_near(const Color& got, const Color& want, float tolerance = 1e-5f) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
  EXPECT_NEAR(got.z, want.z, tolerance);
}

// For EXPECT_TRUE(near3(...)) with both values printed on failure.
inline ::testing::AssertionResult near3(const Vec3& got, const Vec3& want, float tolerance = 1e-5f) {
  if (glm::all(glm::lessThanEqual(glm::abs(got - want), Vec3(tolerance))))
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "got (" << got.x << ", " << got.y << ", " << got.z << "), want ("
                                       << want.x << ", " << want.y << ", " << want.z << ")";
}

}  // namespace inkray::testing
