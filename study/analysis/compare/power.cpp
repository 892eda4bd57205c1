#include "study/analysis/compare/power.hpp"

#include <boost/math/distributions/non_central_t.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace robozoo {

double t_test_power(double d, int n1, int n2, double alpha) {
  if (!(alpha > 0 && alpha < 1)) throw std::invalid_argument("t_test_power: alpha must be in (0, 1)");
  if (n1 < 1 || n2 < 1 || n1 + n2 < 3 || std::isnan(d)) return std::numeric_limits<double>::quiet_NaN();
  const double df = n1 + n2 - 2.0;
  const double c = boost::math::quantile(boost::math::students_t(df), 1 - alpha / 2);
  const double ncp = d * std::sqrt(static_cast<double>(n1) * n2 / (n1 + n2));
  const boost::math::non_central_t t(df, ncp);
  return boost::math::cdf(boost::math::complement(t, c)) + boost::math::cdf(t, -c);
}

double smallest_effect_for_p(double p0, int n1, int n2) {
  if (!(p0 > 0 && p0 < 1)) throw std::invalid_argument("smallest_effect_for_p: p0 must be in (0, 1)");
  if (n1 < 1 || n2 < 1 || n1 + n2 < 3) return std::numeric_limits<double>::quiet_NaN();
  const double c = boost::math::quantile(boost::math::students_t(n1 + n2 - 2.0), 1 - p0 / 2);
  return c * std::sqrt(1.0 / n1 + 1.0 / n2);
}

}  // namespace robozoo
