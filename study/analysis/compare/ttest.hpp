#pragma once
// Two-sample t-tests, two-sided, as SciPy's scipy.stats.ttest_ind(a, b)
// computes them: Student's (equal_var=True, the default; the paper's footnote 4
// says every p-value was computed so) and Welch's (equal_var=False).
//
// Student:  s_p^2 = ((n1 - 1) s1^2 + (n2 - 1) s2^2) / (n1 + n2 - 2)
//           t = (mean1 - mean2) / sqrt(s_p^2 (1/n1 + 1/n2)),  df = n1 + n2 - 2
// Welch:    v_i = s_i^2 / n_i,  t = (mean1 - mean2) / sqrt(v1 + v2)
//           df = (v1 + v2)^2 / (v1^2 / (n1 - 1) + v2^2 / (n2 - 1))  (Welch-Satterthwaite)
// Both:     p = 2 * cdf_t(df)(-|t|)   (Boost.Math's students_t distribution)
//
// Degenerate samples follow SciPy: with fewer than two degrees of freedom
// (Student) or a sample of fewer than two values (Welch), or two constant
// samples with equal means, t and p are NaN; two constant samples with
// different means give t = +-inf and p = 0 (Welch's df is then NaN).
#include <limits>
#include <string>
#include <vector>

namespace robozoo {

struct TTestResult {
  /// t statistic, positive when mean(a) > mean(b) (NaN: no test)
  double t = std::numeric_limits<double>::quiet_NaN();
  /// degrees of freedom (Student: n1 + n2 - 2; Welch: Welch-Satterthwaite)
  double df = std::numeric_limits<double>::quiet_NaN();
  /// two-sided p-value (NaN when undefined)
  double p = std::numeric_limits<double>::quiet_NaN();
};

/// Student's equal-variance two-sample t-test of `a` against `b`.
TTestResult ttest_ind(const std::vector<double>& a, const std::vector<double>& b);

/// Welch's unequal-variance two-sample t-test of `a` against `b`.
TTestResult welch_ttest(const std::vector<double>& a, const std::vector<double>& b);

/// Two-sided p-value of a t statistic with `df` degrees of freedom (NaN for NaN t or df).
double two_sided_p(double t, double df);

/// The paper's marks: "***" p < 0.001, "**" p < 0.01, "*" p < 0.05, "" otherwise or NaN.
std::string significance_stars(double p);

}  // namespace robozoo
