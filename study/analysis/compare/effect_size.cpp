#include "study/analysis/compare/effect_size.hpp"

#include <boost/math/distributions/non_central_t.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "study/analysis/compare/nan.hpp"
#include "study/analysis/compare/ttest.hpp"

namespace robozoo {

namespace {

// P(T'(df, ncp) <= t): decreasing in ncp.
double nct_cdf(double df, double ncp, double t) { return boost::math::cdf(boost::math::non_central_t(df, ncp), t); }

// The ncp with nct_cdf(df, ncp, t) = target, by bisection on a bracket that
// grows until it holds the root (the cdf falls from 1 to 0 as ncp grows).
double solve_ncp(double t, double df, double target) {
  double step = 2.0 + 0.5 * std::fabs(t);
  double lo = t - step, hi = t + step;
  for (int i = 0; i < 60 && nct_cdf(df, lo, t) < target; ++i) lo -= (step *= 2);
  step = 2.0 + 0.5 * std::fabs(t);
  for (int i = 0; i < 60 && nct_cdf(df, hi, t) > target; ++i) hi += (step *= 2);
  for (int i = 0; i < 200 && hi - lo > 1e-12 * (1.0 + std::fabs(lo) + std::fabs(hi)); ++i) {
    const double mid = 0.5 * (lo + hi);
    (nct_cdf(df, mid, t) > target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double hedges_correction(double df) {
  if (!(df > 1)) return kNaN;
  return std::exp(std::lgamma(df / 2) - std::lgamma((df - 1) / 2)) / std::sqrt(df / 2);
}

void noncentral_t_interval(double t, double df, double level, double& low, double& high) {
  if (!(level > 0 && level < 1)) throw std::invalid_argument("noncentral_t_interval: level must be in (0, 1)");
  low = high = kNaN;
  if (!std::isfinite(t) || !(df > 0)) return;
  const double tail = (1 - level) / 2;
  try {
    low = solve_ncp(t, df, 1 - tail);
    high = solve_ncp(t, df, tail);
  } catch (const std::exception&) {
    // Boost could not evaluate the distribution (a t far in the tail): no interval.
    low = high = kNaN;
  }
}

EffectSize effect_size(const std::vector<double>& a, const std::vector<double>& b, double level) {
  EffectSize e;
  e.level = level;
  e.d = e.g = e.d_low = e.d_high = kNaN;
  const size_t n1 = a.size(), n2 = b.size();
  if (n1 < 2 || n2 < 2) return e;
  const TTestResult st = ttest_ind(a, b);
  if (!std::isfinite(st.t)) return e;
  const double k = std::sqrt(1.0 / n1 + 1.0 / n2);
  e.d = st.t * k;
  e.g = hedges_correction(st.df) * e.d;
  noncentral_t_interval(st.t, st.df, level, e.d_low, e.d_high);
  e.d_low *= k;
  e.d_high *= k;
  return e;
}

}  // namespace robozoo
