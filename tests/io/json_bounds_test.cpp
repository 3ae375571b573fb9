// JSON bounds (core/io/json_bounds.h): depth counted over arrays and objects, never
// inside strings, and size checked first.
#include "core/io/json_bounds.h"

#include <gtest/gtest.h>

#include <string>

namespace inkray {
namespace {

TEST(JsonBounds, CountsNestingOutsideStrings) {
  EXPECT_EQ(json_bounds_problem(R"({"a": [1, {"b": [2]}]})", 4, 100), "");
  EXPECT_EQ(json_bounds_problem(R"({"a": [1, {"b": [2]}]})", 3, 100), "nests deeper than 3 levels");
  // Brackets and escaped quotes inside strings do not nest.
  EXPECT_EQ(json_bounds_problem(R"(["[[[[", "\"[[[[", "\\", "]]]]"])", 1, 100), "");
  EXPECT_EQ(json_bounds_problem(R"(["\\"], [])", 1, 100), "");
  EXPECT_EQ(json_bounds_problem(R"([["\\"]])", 1, 100), "nests deeper than 1 levels");
  // Closing more than was opened does not go below zero and hide a later depth.
  EXPECT_EQ(json_bounds_problem("]]]]]][[", 1, 100), "nests deeper than 1 levels");
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_EQ(json_bounds_problem(deep, 256, deep.size()), "nests deeper than 256 levels");
  EXPECT_EQ(json_bounds_problem(deep, 256, 1000), "is 200000 bytes, more than 1000");
}

}  // namespace
}  // namespace inkray
