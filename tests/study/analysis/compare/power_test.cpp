// Power of Student's two-sample t-test and the smallest effect a reported
// p-value implies. References: G*Power's well-known a-priori result for d = 0.5,
// alpha = 0.05 two-sided, 64 + 64 (actual power 0.8014596; Cohen 1988, table
// 2.4.1: 0.80), and values computed with mpmath 1.3.0 at 30 digits from the
// noncentral t written as an integral over the chi-square distribution
// (independent of Boost.Math).
#include "study/analysis/compare/power.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace robozoo {
namespace {

TEST(TTestPower, MatchesGPowerAndMpmath) {
  EXPECT_NEAR(t_test_power(0.5, 64, 64), 0.801459557922254, 1e-9);
  // The experiment's 10 against 10: at the observed fitness effect |d| = 0.62 and
  // at the paper's d = 0.9.
  EXPECT_NEAR(t_test_power(0.62, 10, 10), 0.259345736593627, 1e-9);
  EXPECT_NEAR(t_test_power(0.9, 10, 10), 0.478050412610215, 1e-9);
  EXPECT_NEAR(t_test_power(0.895, 5, 10), 0.328096563039998, 1e-9);
  // Two-sided: the sign of d does not matter.
  EXPECT_NEAR(t_test_power(-0.9, 10, 10), t_test_power(0.9, 10, 10), 1e-12);
}

TEST(TTestPower, AtZeroEffectThePowerIsAlpha) {
  EXPECT_NEAR(t_test_power(0.0, 7, 12), 0.05, 1e-12);
  EXPECT_NEAR(t_test_power(0.0, 30, 30, 0.01), 0.01, 1e-12);
  EXPECT_TRUE(std::isnan(t_test_power(0.5, 1, 1)));
  EXPECT_THROW(t_test_power(0.5, 10, 10, 0.0), std::invalid_argument);
}

TEST(TTestPower, SmallestEffectOfAReportedP) {
  // The paper's fitness: p < 0.001 with 30 against 30, df 58: t(0.9995, 58) =
  // 3.46632879493101 (mpmath), d = t sqrt(2/30) = 0.895002246349802.
  EXPECT_NEAR(smallest_effect_for_p(0.001, 30, 30), 0.895002246349802, 1e-9);
  // p < 0.05: t(0.975, 58) = 2.00171748414524, d = 0.516841231993781.
  EXPECT_NEAR(smallest_effect_for_p(0.05, 30, 30), 0.516841231993781, 1e-9);
  // At that effect the test of 30 against 30 sits at its critical value: power
  // just above one half.
  const double p = t_test_power(smallest_effect_for_p(0.05, 30, 30), 30, 30);
  EXPECT_GT(p, 0.5);
  EXPECT_LT(p, 0.52);
}

}  // namespace
}  // namespace robozoo
