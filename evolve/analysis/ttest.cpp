#include "evolve/analysis/ttest.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>

namespace robozoo {

TTestResult ttest_ind(const std::vector<double>& a, const std::vector<double>& b) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  TTestResult r;
  const size_t n1 = a.size(), n2 = b.size();
  r.df = static_cast<double>(n1 + n2) - 2.0;
  if (n1 == 0 || n2 == 0 || r.df < 1.0) {
    r.t = r.p = kNaN;
    return r;
  }
  auto mean_ss = [](const std::vector<double>& x, long double& mean, long double& ss) {
    long double sum = 0;
    for (double v : x) sum += v;
    mean = sum / static_cast<long double>(x.size());
    ss = 0;
    for (double v : x) ss += (v - mean) * (v - mean);
  };
  long double m1, ss1, m2, ss2;
  mean_ss(a, m1, ss1);
  mean_ss(b, m2, ss2);
  const long double pooled = (ss1 + ss2) / static_cast<long double>(r.df);
  const long double denom = std::sqrt(pooled * (1.0L / n1 + 1.0L / n2));
  const long double diff = m1 - m2;
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
  if (std::isnan(r.t)) {
    r.p = kNaN;
    return r;
  }
  const boost::math::students_t dist(r.df);
  r.p = 2.0 * boost::math::cdf(dist, -std::fabs(r.t));
  if (r.p > 1.0) r.p = 1.0;
  return r;
}

std::string significance_stars(double p) {
  if (std::isnan(p)) return "";
  if (p < 0.001) return "***";
  if (p < 0.01) return "**";
  if (p < 0.05) return "*";
  return "";
}

}  // namespace robozoo
