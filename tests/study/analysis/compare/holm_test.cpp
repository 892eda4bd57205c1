// Holm's step-down adjusted p-values, worked out by hand.
#include "study/analysis/compare/holm.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace robozoo {
namespace {

TEST(Holm, AdjustedValuesByHand) {
  // Sorted: 0.005 (x4), 0.01 (x3), 0.03 (x2), 0.04 (x1) -> 0.02, 0.03, 0.06, 0.04;
  // the running maximum makes the last 0.06.
  const auto q = holm_adjust({0.01, 0.04, 0.03, 0.005});
  ASSERT_EQ(q.size(), 4u);
  EXPECT_DOUBLE_EQ(q[0], 0.03);
  EXPECT_DOUBLE_EQ(q[1], 0.06);
  EXPECT_DOUBLE_EQ(q[2], 0.06);
  EXPECT_DOUBLE_EQ(q[3], 0.02);
}

TEST(Holm, NanIsNotAMemberAndValuesStopAtOne) {
  // m = 2: 2 x 0.2 = 0.4, then max(0.4, 1 x 0.6) = 0.6.
  const auto q = holm_adjust({0.2, std::nan(""), 0.6});
  EXPECT_DOUBLE_EQ(q[0], 0.4);
  EXPECT_TRUE(std::isnan(q[1]));
  EXPECT_DOUBLE_EQ(q[2], 0.6);
  const auto one = holm_adjust({0.5, 0.6});
  EXPECT_DOUBLE_EQ(one[0], 1.0);
  EXPECT_DOUBLE_EQ(one[1], 1.0);
  EXPECT_TRUE(holm_adjust({}).empty());
}

TEST(Holm, ThreeSurviveOfTwenty) {
  // 20 tests, 3 with p = 0.0001, 0.001, 0.002 and 17 at 0.04: Holm multiplies by
  // 20, 19 and 18: 0.002, 0.019, 0.036 survive at 0.05; 0.04 x 17 = 0.68 does not,
  // although every one of the 20 is below 0.05 alone.
  std::vector<double> p(17, 0.04);
  p.insert(p.end(), {0.0001, 0.001, 0.002});
  const auto q = holm_adjust(p);
  EXPECT_NEAR(q[17], 0.002, 1e-15);
  EXPECT_NEAR(q[18], 0.019, 1e-15);
  EXPECT_NEAR(q[19], 0.036, 1e-15);
  for (size_t i = 0; i < 17; ++i) EXPECT_NEAR(q[i], 0.68, 1e-15);
}

}  // namespace
}  // namespace robozoo
