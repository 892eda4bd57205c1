#include "study/analysis/compare/mean_gap.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <stdexcept>

#include "study/analysis/compare/sample_stats.hpp"
#include "study/analysis/compare/ttest.hpp"

namespace robozoo {

namespace {

void check_level(double level) {
  if (!(level > 0 && level < 1)) throw std::invalid_argument("a confidence level must lie strictly between 0 and 1");
}

// The interval and p of g.gap, g.se and g.df, when they allow one.
void finish(MeanGap& g) {
  if (!(g.df >= 1) || !(g.se > 0) || !std::isfinite(g.se)) return;
  const double q = boost::math::quantile(boost::math::students_t(g.df), (1 + g.level) / 2);
  g.low = g.gap - q * g.se;
  g.high = g.gap + q * g.se;
  g.p = two_sided_p(g.gap / g.se, g.df);
}

}  // namespace

MeanGap student_gap(const std::vector<double>& a, const std::vector<double>& b, double level) {
  check_level(level);
  MeanGap g;
  g.level = level;
  g.n_a = a.size();
  g.n_b = b.size();
  if (a.empty() || b.empty()) return g;
  const SampleStats sa = describe(a), sb = describe(b);
  g.mean_a = sa.mean;
  g.mean_b = sb.mean;
  g.gap = sa.mean - sb.mean;
  if (a.size() + b.size() < 3) return g;
  g.df = static_cast<double>(a.size() + b.size()) - 2.0;
  const double pooled = ((sa.n - 1.0) * sa.sd * sa.sd + (sb.n - 1.0) * sb.sd * sb.sd) / g.df;
  g.se = std::sqrt(pooled * (1.0 / static_cast<double>(sa.n) + 1.0 / static_cast<double>(sb.n)));
  finish(g);
  if (std::isfinite(g.low)) g.p = ttest_ind(a, b).p;  // the same test, to the bit
  return g;
}

MeanGap gap_difference(const MeanGap& x, const MeanGap& y, double level) {
  check_level(level);
  MeanGap g;
  g.level = level;
  g.mean_a = x.gap;
  g.mean_b = y.gap;
  g.gap = x.gap - y.gap;
  const double vx = x.se * x.se, vy = y.se * y.se;
  if (!(x.df >= 1) || !(y.df >= 1) || !(vx + vy > 0)) return g;
  g.se = std::sqrt(vx + vy);
  g.df = (vx + vy) * (vx + vy) / (vx * vx / x.df + vy * vy / y.df);
  finish(g);
  return g;
}

}  // namespace robozoo
