#pragma once
// Power of the two-sided two-sample Student's t-test, and the effect a reported
// p-value implies.
//
// With true standardised difference d, the test's statistic follows the
// noncentral t with df = n1 + n2 - 2 and noncentrality ncp = d sqrt(n1 n2 / (n1 + n2)):
//   power = P(T' > c) + P(T' < -c),  c = quantile_t(df)(1 - alpha / 2)
// (Boost.Math's non_central_t and students_t).
//
// A result "p < p0 with n1 against n2" needs |t| >= quantile_t(df)(1 - p0/2), i.e.
//   |d| >= quantile_t(df)(1 - p0/2) sqrt(1/n1 + 1/n2):
// the smallest effect the reported p-value implies (the paper's fitness:
// p < 0.001 with 30 against 30 gives d >= 3.466 sqrt(2/30) = 0.895).
namespace robozoo {

/// Power of the two-sided Student's t-test at level `alpha` for effect `d`
/// (Cohen's d) with samples of n1 and n2 (NaN when n1 + n2 < 3 or n1, n2 < 1).
double t_test_power(double d, int n1, int n2, double alpha = 0.05);

/// The smallest |d| with which Student's t-test of n1 against n2 reaches two-sided p < p0.
double smallest_effect_for_p(double p0, int n1, int n2);

}  // namespace robozoo
