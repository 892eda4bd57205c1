// The gap between two means with Student's pooled interval, and the difference of two
// gaps with a Welch-Satterthwaite interval. References: R's published output for its
// `sleep` data set, and numbers worked out by hand (written next to each).
#include "study/analysis/compare/mean_gap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "study/analysis/compare/ttest.hpp"

namespace robozoo {
namespace {

// Student (1908), Cushny & Peebles' extra hours of sleep under two drugs: R's `sleep`
// data set, 10 against 10 (18 degrees of freedom, as the sensitivity study's 10 runs per arm).
const std::vector<double> kG1 = {0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
const std::vector<double> kG2 = {1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};

TEST(MeanGap, MatchesRsPooledIntervalOnTheSleepData) {
  // R: t.test(extra ~ group, data = sleep, var.equal = TRUE) prints
  // "95 percent confidence interval: -3.363874 0.203874", means 0.75 and 2.33, df = 18.
  const MeanGap g = student_gap(kG1, kG2);
  EXPECT_EQ(g.n_a, 10u);
  EXPECT_EQ(g.n_b, 10u);
  EXPECT_NEAR(g.mean_a, 0.75, 1e-12);
  EXPECT_NEAR(g.mean_b, 2.33, 1e-12);
  EXPECT_NEAR(g.gap, -1.58, 1e-12);
  EXPECT_EQ(g.df, 18.0);
  EXPECT_NEAR(g.low, -3.363874, 5e-7);
  EXPECT_NEAR(g.high, 0.203874, 5e-7);
  // Student's p is ttest_ind's, to the bit.
  EXPECT_EQ(g.p, ttest_ind(kG1, kG2).p);
  EXPECT_TRUE(g.covers(0));
  EXPECT_FALSE(g.covers(-3.4));
}

TEST(MeanGap, ALevelWidensOrNarrowsTheInterval) {
  // The same data at 99 %: -1.58 -+ 2.878440473 (the 0.995 quantile of t(18), tables)
  // x 0.8490910172 (the standard error above: 1.58 / R's t = 1.8608) = [-4.024058, 0.864058].
  const MeanGap g = student_gap(kG1, kG2, 0.99);
  EXPECT_NEAR(g.low, -4.024058, 5e-6);
  EXPECT_NEAR(g.high, 0.864058, 5e-6);
  EXPECT_EQ(g.level, 0.99);
}

TEST(MeanGap, HandWorkedExample) {
  // a: mean 3, sum of squares 10; b: mean 4, sum of squares 8; pooled variance 18 / 6 = 3,
  // se = sqrt(3 (1/5 + 1/3)) = sqrt(1.6); t(6) 0.975 quantile 2.446911851 (tables).
  const MeanGap g = student_gap({1, 2, 3, 4, 5}, {2, 4, 6});
  EXPECT_DOUBLE_EQ(g.gap, -1.0);
  EXPECT_DOUBLE_EQ(g.se, std::sqrt(1.6));
  EXPECT_EQ(g.df, 6.0);
  EXPECT_NEAR(g.high - g.gap, 2.446911851 * std::sqrt(1.6), 1e-8);
  EXPECT_NEAR(g.gap - g.low, 2.446911851 * std::sqrt(1.6), 1e-8);
}

TEST(MeanGap, TooFewValuesOrNoSpreadGiveNoInterval) {
  const MeanGap one = student_gap({1.0}, {2.0});
  EXPECT_DOUBLE_EQ(one.gap, -1.0);
  EXPECT_TRUE(std::isnan(one.low));
  EXPECT_TRUE(std::isnan(one.p));
  EXPECT_FALSE(one.covers(-1.0));
  const MeanGap flat = student_gap({2, 2, 2}, {2, 2});
  EXPECT_DOUBLE_EQ(flat.gap, 0.0);
  EXPECT_TRUE(std::isnan(flat.high));
  const MeanGap none = student_gap({}, {1, 2});
  EXPECT_TRUE(std::isnan(none.gap));
  EXPECT_THROW(student_gap(kG1, kG2, 1.0), std::invalid_argument);
  EXPECT_THROW(student_gap(kG1, kG2, 0.0), std::invalid_argument);
}

TEST(MeanGap, DifferenceOfGapsUsesWelchSatterthwaite) {
  MeanGap x, y;
  x.gap = 3;
  x.se = 1;
  x.df = 10;
  y.gap = 1;
  y.se = 2;
  y.df = 20;
  const MeanGap d = gap_difference(x, y);
  // se = sqrt(1 + 4); df = 25 / (1 / 10 + 16 / 20) = 27.777...; the 0.975 quantile of t(27.78)
  // lies between t(27) 2.0518 and t(28) 2.0484 (tables).
  EXPECT_DOUBLE_EQ(d.gap, 2.0);
  EXPECT_DOUBLE_EQ(d.se, std::sqrt(5.0));
  EXPECT_NEAR(d.df, 25.0 / 0.9, 1e-12);
  const double q = (d.high - d.gap) / d.se;
  EXPECT_GT(q, 2.0484);
  EXPECT_LT(q, 2.0518);
  EXPECT_NEAR(d.gap - d.low, d.high - d.gap, 1e-12);
  EXPECT_DOUBLE_EQ(d.mean_a, 3.0);
  EXPECT_DOUBLE_EQ(d.mean_b, 1.0);
  // A gap without an interval gives a difference without one.
  const MeanGap none = gap_difference(x, student_gap({1.0}, {2.0}));
  EXPECT_DOUBLE_EQ(none.gap, 4.0);
  EXPECT_TRUE(std::isnan(none.low));
}

}  // namespace
}  // namespace robozoo
