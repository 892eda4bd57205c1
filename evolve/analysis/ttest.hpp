#pragma once
// Student's two-sample t-test with equal variances, as SciPy's
// scipy.stats.ttest_ind(a, b) computes it by default (equal_var=True,
// two-sided): the paper's footnote 4 says every p-value was computed so.
//
//   pooled variance  s_p^2 = ((n1 - 1) s1^2 + (n2 - 1) s2^2) / (n1 + n2 - 2)
//   t = (mean1 - mean2) / sqrt(s_p^2 (1/n1 + 1/n2)),  df = n1 + n2 - 2
//   p = 2 * cdf_t(df)(-|t|)      (Boost.Math's students_t distribution)
//
// Degenerate samples follow SciPy: with fewer than two degrees of freedom, or
// two constant samples with equal means, t and p are NaN; two constant samples
// with different means give t = +-inf and p = 0.
#include <string>
#include <vector>

namespace robozoo {

struct TTestResult {
  double t = 0.0;   ///< t statistic, positive when mean(a) > mean(b)
  double df = 0.0;  ///< degrees of freedom, n1 + n2 - 2
  double p = 0.0;   ///< two-sided p-value (NaN when undefined)
};

/// The equal-variance two-sample t-test of `a` against `b`.
TTestResult ttest_ind(const std::vector<double>& a, const std::vector<double>& b);

/// The paper's marks: "***" p < 0.001, "**" p < 0.01, "*" p < 0.05, "" otherwise or NaN.
std::string significance_stars(double p);

}  // namespace robozoo
