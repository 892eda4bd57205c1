#pragma once
// Standardised difference of two means, with a 95 % confidence interval.
//
//   Cohen's d  = (mean(a) - mean(b)) / s_p,  s_p the pooled standard deviation
//                of Student's t-test (n1 + n2 - 2 in the denominator), so that
//                d = t sqrt(1/n1 + 1/n2) with Student's t.
//   Hedges' g  = J d,  J = Gamma(df/2) / (sqrt(df/2) Gamma((df-1)/2)), df = n1 + n2 - 2
//                (the exact small-sample correction; J ~ 1 - 3 / (4 df - 1)).
//   CI of d    : inversion of the noncentral t (Steiger & Fouladi 1997): with
//                t the observed Student's t, the bounds are the noncentrality
//                parameters L, U with P(T'(df, L) <= t) = 1 - (1 - level)/2 and
//                P(T'(df, U) <= t) = (1 - level)/2, times sqrt(1/n1 + 1/n2).
//                Exact under normality and equal variances. The CI of g is J times it.
// Undefined (NaN): a sample with fewer than two values, or s_p = 0.
#include <vector>

namespace robozoo {

struct EffectSize {
  double d = 0;         ///< Cohen's d, positive when mean(a) > mean(b)
  double g = 0;         ///< Hedges' g
  double d_low = 0;     ///< lower bound of d's confidence interval
  double d_high = 0;    ///< upper bound
  double level = 0.95;  ///< the interval's confidence level
};

/// The effect size of `a` against `b` with a `level` confidence interval (0 < level < 1).
EffectSize effect_size(const std::vector<double>& a, const std::vector<double>& b, double level = 0.95);

/// The interval [L, U] of the noncentrality parameter given an observed t with
/// `df` degrees of freedom (see above); NaN bounds for a non-finite t or df <= 0.
void noncentral_t_interval(double t, double df, double level, double& low, double& high);

/// Hedges' exact correction J(df) (NaN for df <= 1).
double hedges_correction(double df);

}  // namespace robozoo
