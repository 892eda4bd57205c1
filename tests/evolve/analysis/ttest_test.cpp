// Student's two-sample t-test (equal variances), as SciPy's ttest_ind computes
// it. SciPy is not available on this machine, so every reference below is
// either derived by hand from the formula (long double, in the test) or a
// published value; where each number comes from is written next to it.
#include "evolve/analysis/ttest.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace robozoo {
namespace {

// The pooled t statistic, written out from its textbook definition.
long double pooled_t(const std::vector<double>& a, const std::vector<double>& b) {
  auto mean = [](const std::vector<double>& x) {
    long double s = 0;
    for (double v : x) s += v;
    return s / x.size();
  };
  auto ss = [](const std::vector<double>& x, long double m) {
    long double s = 0;
    for (double v : x) s += (v - m) * (v - m);
    return s;
  };
  const long double m1 = mean(a), m2 = mean(b);
  const long double df = a.size() + b.size() - 2.0L;
  const long double sp2 = (ss(a, m1) + ss(b, m2)) / df;
  return (m1 - m2) / std::sqrt(sp2 * (1.0L / a.size() + 1.0L / b.size()));
}

TEST(TTest, StudentsSleepDataMatchesPublishedResult) {
  // Student (1908), Cushny & Peebles' extra hours of sleep under two drugs: R's
  // `sleep` data set. R's t.test(extra ~ group, data = sleep, var.equal = TRUE)
  // prints "t = -1.8608, df = 18, p-value = 0.07919". The p-value to more
  // digits, 0.0791867142159381, was computed with mpmath 1.3.0 (30 digits) as
  // the regularized incomplete beta I_{df/(df+t^2)}(df/2, 1/2) at this t.
  const std::vector<double> g1 = {0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
  const std::vector<double> g2 = {1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};
  const TTestResult r = ttest_ind(g1, g2);
  EXPECT_NEAR(r.t, -1.8608, 5e-5);
  EXPECT_NEAR(r.t, static_cast<double>(pooled_t(g1, g2)), 1e-12);
  EXPECT_EQ(r.df, 18.0);
  EXPECT_NEAR(r.p, 0.07919, 5e-6);
  EXPECT_NEAR(r.p, 0.0791867142159381, 1e-12);
  // Swapping the samples flips t, not p.
  const TTestResult s = ttest_ind(g2, g1);
  EXPECT_DOUBLE_EQ(s.t, -r.t);
  EXPECT_DOUBLE_EQ(s.p, r.p);
}

TEST(TTest, ClosedFormsForOneAndTwoDegreesOfFreedom) {
  // df = 2: samples {0, 2} and {3, 5}: means 1 and 4, sums of squares 2 and 2,
  // s_p^2 = 4 / 2 = 2, t = -3 / sqrt(2 (1/2 + 1/2)) = -3 / sqrt(2).
  // The t distribution with 2 degrees of freedom has the closed form
  // p = 1 - |t| / sqrt(t^2 + 2), here 1 - sqrt(4.5 / 6.5) = 1 - 3 / sqrt(13).
  const TTestResult r2 = ttest_ind({0, 2}, {3, 5});
  EXPECT_NEAR(r2.t, -3.0 / std::sqrt(2.0), 1e-14);
  EXPECT_EQ(r2.df, 2.0);
  EXPECT_NEAR(r2.p, static_cast<double>(1.0L - 3.0L / std::sqrt(13.0L)), 1e-13);
  // df = 1: {0, 2} and {5}: means 1 and 5, s_p^2 = 2 / 1, t = -4 / sqrt(2 * 1.5) = -4 / sqrt(3).
  // With 1 degree of freedom t is Cauchy: p = 1 - (2 / pi) atan(|t|).
  const TTestResult r1 = ttest_ind({0, 2}, {5});
  EXPECT_NEAR(r1.t, -4.0 / std::sqrt(3.0), 1e-14);
  EXPECT_EQ(r1.df, 1.0);
  const long double pi = 3.141592653589793238462643383279502884L;
  EXPECT_NEAR(r1.p, static_cast<double>(1.0L - 2.0L / pi * std::atan(4.0L / std::sqrt(3.0L))), 1e-13);
}

// Samples a = delta + e and b = e with e = {-1, 1, -1, 1, 0, ...}: the pooled
// t is delta / sqrt(s_p^2 * 2 / n), so delta can be chosen to hit a given t.
std::pair<std::vector<double>, std::vector<double>> samples_with_t(double t, size_t n) {
  std::vector<double> e(n, 0.0);
  for (size_t i = 0; i + 1 < n; i += 2) {
    e[i] = -1;
    e[i + 1] = 1;
  }
  long double ss = 0;
  for (double v : e) ss += v * v;  // mean 0
  const long double sp2 = 2 * ss / (2.0L * n - 2);
  const double delta = static_cast<double>(t * std::sqrt(sp2 * 2.0L / n));
  std::vector<double> a = e;
  for (double& v : a) v += delta;
  return {a, e};
}

TEST(TTest, CriticalValuesOfThePublishedTable) {
  // Two-sided critical values of Student's t from the standard table (e.g.
  // Fisher & Yates; any statistics textbook): t(0.975, 8) = 2.306,
  // t(0.995, 8) = 3.355, t(0.975, 20) = 2.086, t(0.995, 20) = 2.845. The table
  // rounds t to 3 decimals, which moves p by less than 1e-5 here.
  struct Row {
    double t;
    size_t n;  // per sample: df = 2n - 2
    double p;
  };
  for (const Row& row : {Row{2.306, 5, 0.05}, Row{3.355, 5, 0.01}, Row{2.086, 11, 0.05}, Row{2.845, 11, 0.01}}) {
    const auto [a, b] = samples_with_t(row.t, row.n);
    const TTestResult r = ttest_ind(a, b);
    EXPECT_NEAR(r.t, row.t, 1e-12);
    EXPECT_EQ(r.df, 2.0 * row.n - 2);
    EXPECT_NEAR(r.p, row.p, 1e-5) << "t = " << row.t;
  }
}

TEST(TTest, DegenerateSamplesFollowScipy) {
  // Too few observations: nan.
  EXPECT_TRUE(std::isnan(ttest_ind({1.0}, {2.0}).p));
  EXPECT_TRUE(std::isnan(ttest_ind({}, {1.0, 2.0}).p));
  // Two constant samples, equal means: 0/0, nan.
  EXPECT_TRUE(std::isnan(ttest_ind({3, 3}, {3, 3, 3}).t));
  // Two constant samples, different means: t = +-inf, p = 0.
  const TTestResult r = ttest_ind({50, 50}, {10});
  EXPECT_TRUE(std::isinf(r.t) && r.t > 0);
  EXPECT_EQ(r.p, 0.0);
  // Identical samples with spread: t = 0, p = 1.
  const TTestResult z = ttest_ind({1, 2, 3}, {3, 2, 1});
  EXPECT_EQ(z.t, 0.0);
  EXPECT_NEAR(z.p, 1.0, 1e-15);
}

TEST(TTest, PaperStars) {
  EXPECT_EQ(significance_stars(0.0009), "***");
  EXPECT_EQ(significance_stars(0.001), "**");
  EXPECT_EQ(significance_stars(0.0099), "**");
  EXPECT_EQ(significance_stars(0.01), "*");
  EXPECT_EQ(significance_stars(0.049), "*");
  EXPECT_EQ(significance_stars(0.05), "");
  EXPECT_EQ(significance_stars(std::nan("")), "");
}

}  // namespace
}  // namespace robozoo
