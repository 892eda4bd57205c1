// Cohen's d, Hedges' g and the noncentral-t confidence interval of d. SciPy is
// not on this machine: the references are worked out by hand or computed with
// mpmath 1.3.0 at 30 digits, the noncentral t's cdf as the integral
// P(T' <= t) = int_0^inf Phi(t sqrt(x / df) - ncp) f_chi2(df)(x) dx and its
// roots with mpmath.findroot (independent of Boost.Math).
#include "study/analysis/compare/effect_size.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "study/analysis/compare/ttest.hpp"

namespace robozoo {
namespace {

const std::vector<double> kSleep1 = {0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
const std::vector<double> kSleep2 = {1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};

TEST(EffectSize, CohensDByHand) {
  // {3, 5} against {0, 2}: means 4 and 1, s_p^2 = (2 + 2) / 2 = 2, d = 3 / sqrt(2).
  const EffectSize e = effect_size({3, 5}, {0, 2});
  EXPECT_NEAR(e.d, 3.0 / std::sqrt(2.0), 1e-14);
  // J(2) = Gamma(1) / (sqrt(1) Gamma(1/2)) = 1 / sqrt(pi).
  EXPECT_NEAR(hedges_correction(2), 1.0 / std::sqrt(3.14159265358979323846), 1e-14);
  EXPECT_NEAR(e.g, e.d / std::sqrt(3.14159265358979323846), 1e-14);
  // Swapping the samples flips d and its interval.
  const EffectSize s = effect_size({0, 2}, {3, 5});
  EXPECT_DOUBLE_EQ(s.d, -e.d);
  EXPECT_NEAR(s.d_low, -e.d_high, 1e-9);
  EXPECT_NEAR(s.d_high, -e.d_low, 1e-9);
}

TEST(EffectSize, SleepDataIntervalMatchesMpmath) {
  // d = t sqrt(1/10 + 1/10) with t = -1.86081346748685 (R's -1.8608):
  // d = -0.832181081349540. The ncp bounds (mpmath): P(T'(18, L) <= t) = 0.975 at
  // L = -3.88811278682805, = 0.025 at U = 0.213433578880150; times sqrt(0.2):
  // [-1.73881689910673, 0.0954503982114156]. J(18) = 0.957646427023718,
  // g = -0.796935239191121.
  const EffectSize e = effect_size(kSleep1, kSleep2);
  EXPECT_NEAR(e.d, -0.832181081349540, 1e-12);
  EXPECT_NEAR(e.d_low, -1.73881689910673, 1e-8);
  EXPECT_NEAR(e.d_high, 0.0954503982114156, 1e-8);
  EXPECT_NEAR(hedges_correction(18), 0.957646427023718, 1e-13);
  EXPECT_NEAR(e.g, -0.796935239191121, 1e-12);
  // Hedges' approximation 1 - 3 / (4 df - 1) is within 1e-3 of the exact J.
  EXPECT_NEAR(hedges_correction(18), 1 - 3.0 / 71, 1e-3);
  // The interval holds 0 exactly when Student's p is above 0.05 (here p = 0.079).
  EXPECT_GT(ttest_ind(kSleep1, kSleep2).p, 0.05);
  EXPECT_LT(e.d_low, 0.0);
  EXPECT_GT(e.d_high, 0.0);
}

TEST(EffectSize, TheReducedExperimentsFitness) {
  // Best-so-far fitness at generation 29 of the reduced experiment, recurrent
  // against feed-forward (media/experiment/runs.csv): d = -0.618510410857269;
  // mpmath: ncp bounds -3.37553092083543 and 0.645739919252187, times sqrt(0.2):
  // [-1.50958331982810, 0.288783671046623]. The paper's d = 0.895 lies outside.
  const std::vector<double> ff = {19.85645171, 31.43090585, 17.9361234,  26.29664791, 28.9900784,
                                  19.22450383, 25.93684994, 25.38856277, 29.09277238, 21.2913661};
  const std::vector<double> rec = {17.63035334, 19.47156361, 21.99942461, 33.80974258, 20.44670961,
                                   17.93723543, 20.74533288, 22.11418172, 23.85350344, 18.30391089};
  const EffectSize e = effect_size(rec, ff);
  EXPECT_NEAR(e.d, -0.618510410857269, 1e-12);
  EXPECT_NEAR(e.d_low, -1.50958331982810, 1e-8);
  EXPECT_NEAR(e.d_high, 0.288783671046623, 1e-8);
  EXPECT_LT(e.d_high, 0.895);
}

TEST(EffectSize, LargeSamplesApproachTheNormalApproximation) {
  // For large n the interval tends to d +- 1.96 sqrt((n1 + n2) / (n1 n2) + d^2 / (2 (n1 + n2))).
  std::vector<double> a, b;
  for (int i = 0; i < 2000; ++i) {
    const double e = (i % 4) - 1.5;  // spread -1.5 .. 1.5, mean 0, s^2 = 1.25 * 2000/1999
    a.push_back(e + 0.5);
    b.push_back(e);
  }
  const EffectSize r = effect_size(a, b);
  const double se = std::sqrt(2.0 / 2000 + r.d * r.d / (2 * 4000.0));
  EXPECT_NEAR(r.d, 0.5 / std::sqrt(1.25 * 2000 / 1999), 1e-12);
  EXPECT_NEAR(r.d_low, r.d - 1.959964 * se, 2e-3);
  EXPECT_NEAR(r.d_high, r.d + 1.959964 * se, 2e-3);
  EXPECT_LT(r.d_low, r.d);
  EXPECT_GT(r.d_high, r.d);
}

TEST(EffectSize, ZeroEffectGivesASymmetricInterval) {
  const EffectSize z = effect_size({1, 2, 3}, {3, 2, 1});
  EXPECT_EQ(z.d, 0.0);
  EXPECT_NEAR(z.d_low, -z.d_high, 1e-9);
  EXPECT_GT(z.d_high, 0.5);
}

TEST(EffectSize, HugeEffectsStillGetAnInterval) {
  // The recurrent start's 110 extra links: t in the hundreds. d = 110.6 / 0.6 with
  // samples {110, 111, 110, 111, ...} +- 0.5 around their means: the interval holds d.
  std::vector<double> a, b;
  for (int i = 0; i < 10; ++i) {
    a.push_back(213 + (i % 2) - 0.5);
    b.push_back(103 + (i % 2) - 0.5);
  }
  const EffectSize e = effect_size(a, b);
  EXPECT_GT(e.d, 100);
  EXPECT_LT(e.d_low, e.d);
  EXPECT_GT(e.d_high, e.d);
}

TEST(EffectSize, UndefinedWithoutSpread) {
  EXPECT_TRUE(std::isnan(effect_size({1}, {2, 3}).d));
  EXPECT_TRUE(std::isnan(effect_size({3, 3}, {4, 4}).d));  // s_p = 0
  EXPECT_TRUE(std::isnan(effect_size({3, 3}, {4, 4}).d_low));
  double lo = 0, hi = 0;
  noncentral_t_interval(std::nan(""), 10, 0.95, lo, hi);
  EXPECT_TRUE(std::isnan(lo) && std::isnan(hi));
  EXPECT_THROW(noncentral_t_interval(1, 10, 1.0, lo, hi), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
