#include "study/analysis/compare/sample_stats.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace robozoo {

SampleStats describe(const std::vector<double>& x) {
  SampleStats s;
  s.n = x.size();
  if (x.empty()) {
    s.mean = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  // Long double sums: the means of the report should not depend on order.
  long double sum = 0;
  for (double v : x) {
    if (std::isnan(v)) throw std::invalid_argument("describe: the sample holds a NaN");
    sum += v;
  }
  const long double mean = sum / static_cast<long double>(x.size());
  s.mean = static_cast<double>(mean);
  if (x.size() < 2) return s;
  long double ss = 0;
  for (double v : x) ss += (v - mean) * (v - mean);
  s.sd = static_cast<double>(std::sqrt(ss / static_cast<long double>(x.size() - 1)));
  s.se = s.sd / std::sqrt(static_cast<double>(x.size()));
  return s;
}

}  // namespace robozoo
