#include "study/analysis/compare/ttest.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>

#include "study/analysis/compare/nan.hpp"

namespace robozoo {

namespace {

void mean_ss(const std::vector<double>& x, long double& mean, long double& ss) {
  long double sum = 0;
  for (double v : x) sum += v;
  mean = sum / static_cast<long double>(x.size());
  ss = 0;
  for (double v : x) ss += (v - mean) * (v - mean);
}

// t = diff / denom, with SciPy's answers for a zero denominator.
TTestResult finish(long double diff, long double denom, double df) {
  TTestResult r;
  r.df = df;
  if (denom == 0) {
    if (diff == 0) {
      r.t = r.p = kNaN;
    } else {
      r.t = diff > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
      r.p = 0.0;
    }
    return r;
  }
  r.t = static_cast<double>(diff / denom);
  r.p = two_sided_p(r.t, r.df);
  return r;
}

}  // namespace

double two_sided_p(double t, double df) {
  if (std::isnan(t) || std::isnan(df) || !(df > 0)) return kNaN;
  if (std::isinf(t)) return 0.0;
  const boost::math::students_t dist(df);
  const double p = 2.0 * boost::math::cdf(dist, -std::fabs(t));
  return p > 1.0 ? 1.0 : p;
}

TTestResult ttest_ind(const std::vector<double>& a, const std::vector<double>& b) {
  const size_t n1 = a.size(), n2 = b.size();
  const double df = static_cast<double>(n1 + n2) - 2.0;
  if (n1 == 0 || n2 == 0 || df < 1.0) return {kNaN, df, kNaN};
  long double m1, ss1, m2, ss2;
  mean_ss(a, m1, ss1);
  mean_ss(b, m2, ss2);
  const long double pooled = (ss1 + ss2) / static_cast<long double>(df);
  return finish(m1 - m2, std::sqrt(pooled * (1.0L / n1 + 1.0L / n2)), df);
}

TTestResult welch_ttest(const std::vector<double>& a, const std::vector<double>& b) {
  const size_t n1 = a.size(), n2 = b.size();
  if (n1 < 2 || n2 < 2) return {kNaN, kNaN, kNaN};
  long double m1, ss1, m2, ss2;
  mean_ss(a, m1, ss1);
  mean_ss(b, m2, ss2);
  const long double v1 = ss1 / (n1 - 1) / n1, v2 = ss2 / (n2 - 1) / n2;
  const long double den = v1 * v1 / (n1 - 1) + v2 * v2 / (n2 - 1);
  const double df = den > 0 ? static_cast<double>((v1 + v2) * (v1 + v2) / den) : kNaN;
  return finish(m1 - m2, std::sqrt(v1 + v2), df);
}

std::string significance_stars(double p) {
  if (std::isnan(p)) return "";
  if (p < 0.001) return "***";
  if (p < 0.01) return "**";
  if (p < 0.05) return "*";
  return "";
}

}  // namespace robozoo
