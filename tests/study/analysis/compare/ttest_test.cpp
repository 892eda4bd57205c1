// Student's two-sample t-test (equal variances), as SciPy's ttest_ind computes
// it. SciPy is not available on this machine, so every reference below is
// either derived by hand from the formula (long double, in the test) or a
// published value; where each number comes from is written next to it.
#include "study/analysis/compare/ttest.hpp"

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

TEST(WelchTTest, SleepDataMatchesPublishedResult) {
  // R's t.test(extra ~ group, data = sleep) (Welch's test, R's default) prints
  // "t = -1.8608, df = 17.776, p-value = 0.07939". More digits, from the
  // Welch-Satterthwaite formula and the regularized incomplete beta in mpmath
  // 1.3.0 (30 digits): df = 17.7764735161785, p = 0.0793941401873581.
  const std::vector<double> g1 = {0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
  const std::vector<double> g2 = {1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};
  const TTestResult w = welch_ttest(g1, g2);
  EXPECT_NEAR(w.t, -1.86081346748685, 1e-12);  // equal n: Welch's t is Student's t
  EXPECT_NEAR(w.df, 17.7764735161785, 1e-10);
  EXPECT_NEAR(w.p, 0.0793941401873581, 1e-12);
  EXPECT_NEAR(w.p, 0.07939, 5e-6);
}

TEST(WelchTTest, DegreesOfFreedomByHand) {
  // a = {0, 2}: mean 1, s^2 = 2, v1 = 2/2 = 1; b = {0, 2, 4, 6}: mean 3, s^2 = 20/3,
  // v2 = 5/3. t = -2 / sqrt(8/3) = -sqrt(1.5);
  // df = (8/3)^2 / (1^2 / 1 + (5/3)^2 / 3) = (64/9) / (52/27) = 48/13.
  // p: mpmath 1.3.0, I_{df/(df+t^2)}(df/2, 1/2) = 0.293016342066964.
  const TTestResult w = welch_ttest({0, 2}, {0, 2, 4, 6});
  EXPECT_NEAR(w.t, -std::sqrt(1.5), 1e-14);
  EXPECT_NEAR(w.df, 48.0 / 13.0, 1e-13);
  EXPECT_NEAR(w.p, 0.293016342066964, 1e-12);
  // Student's test of the same samples: s_p^2 = (2 + 20) / 4 = 5.5, t = -2 / sqrt(5.5 * 0.75), df 4.
  const TTestResult s = ttest_ind({0, 2}, {0, 2, 4, 6});
  EXPECT_NEAR(s.t, -2.0 / std::sqrt(5.5 * 0.75), 1e-14);
  EXPECT_EQ(s.df, 4.0);
  // One constant sample: df = n - 1 of the other (v2 = 0).
  const TTestResult c = welch_ttest({0, 2, 4}, {5, 5, 5, 5});
  EXPECT_NEAR(c.df, 2.0, 1e-14);
  EXPECT_NEAR(c.t, -3.0 / std::sqrt(4.0 / 3.0), 1e-14);
  // Two degrees of freedom: closed form p = 1 - |t| / sqrt(t^2 + 2).
  EXPECT_NEAR(c.p, 1.0 - std::fabs(c.t) / std::sqrt(c.t * c.t + 2.0), 1e-13);
}

// Best-so-far fitness at generation 29 of the reduced experiment
// (media/experiment/runs.csv and sparse/runs.csv, 10 significant digits), by seed.
const std::vector<double> kFeedForward = {19.85645171, 31.43090585, 17.9361234,  26.29664791, 28.9900784,
                                          19.22450383, 25.93684994, 25.38856277, 29.09277238, 21.2913661};
const std::vector<double> kRecurrent = {17.63035334, 19.47156361, 21.99942461, 33.80974258, 20.44670961,
                                        17.93723543, 20.74533288, 22.11418172, 23.85350344, 18.30391089};
const std::vector<double> kRecurrentSparse = {32.04415125, 23.59926401, 32.7971969, 29.61692114, 21.32281508};

TEST(WelchTTest, UnequalGroupsChangeTheVerdict) {
  // 10 recurrent runs against 5 from the sparse start: Student's p = 0.0355 (df 13) but
  // Welch's p = 0.0545 (df 7.50): the two tests disagree about p < 0.05. mpmath 1.3.0:
  // Student t = -2.34598732138862, p = 0.0354904939181662;
  // Welch t = -2.27599955823331, df = 7.49804882054546, p = 0.0545339656278671.
  const TTestResult s = ttest_ind(kRecurrent, kRecurrentSparse);
  EXPECT_NEAR(s.t, -2.34598732138862, 1e-11);
  EXPECT_EQ(s.df, 13.0);
  EXPECT_NEAR(s.p, 0.0354904939181662, 1e-12);
  const TTestResult w = welch_ttest(kRecurrent, kRecurrentSparse);
  EXPECT_NEAR(w.t, -2.27599955823331, 1e-11);
  EXPECT_NEAR(w.df, 7.49804882054546, 1e-10);
  EXPECT_NEAR(w.p, 0.0545339656278671, 1e-12);
  // 10 against 10 with similar spread: the two agree (t = -1.3830313234682, p = 0.1836, df 17.999).
  const TTestResult s2 = ttest_ind(kRecurrent, kFeedForward), w2 = welch_ttest(kRecurrent, kFeedForward);
  EXPECT_NEAR(s2.p, 0.183572159870649, 1e-12);
  EXPECT_NEAR(w2.df, 17.9989348743087, 1e-10);
  EXPECT_NEAR(w2.p, 0.183573146652102, 1e-12);
}

TEST(WelchTTest, DegenerateSamples) {
  EXPECT_TRUE(std::isnan(welch_ttest({1.0}, {2.0, 3.0}).p));  // a sample of one: no variance
  EXPECT_TRUE(std::isnan(welch_ttest({3, 3}, {3, 3, 3}).t));
  const TTestResult r = welch_ttest({50, 50}, {10, 10});
  EXPECT_TRUE(std::isinf(r.t) && r.t > 0);
  EXPECT_EQ(r.p, 0.0);
  EXPECT_TRUE(std::isnan(r.df));
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
