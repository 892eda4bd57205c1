#pragma once
// The difference of two means in the units of the data, with a confidence
// interval: what the sensitivity study reports (a fitness gap), where Cohen's d
// (effect_size) would hide the scale.
//
//   student_gap(a, b):  gap = mean(a) - mean(b), se = sqrt(s_p^2 (1/n1 + 1/n2)),
//                       df = n1 + n2 - 2 (Student's pooled variance, as ttest_ind),
//                       interval gap -+ q se with q the (1 + level)/2 quantile of
//                       Student's t(df); p is Student's two-sided p (ttest_ind's).
//   gap_difference(x, y): x.gap - y.gap of two gaps from independent samples,
//                       se = sqrt(se_x^2 + se_y^2), df by Welch-Satterthwaite
//                       (se_x^2 + se_y^2)^2 / (se_x^4 / df_x + se_y^4 / df_y).
// Undefined (NaN interval and p): a sample of fewer than two values (fewer than
// one degree of freedom), or a zero standard error.
#include <cstddef>
#include <limits>
#include <vector>

namespace robozoo {

struct MeanGap {
  size_t n_a = 0;  ///< size of the first sample (count; for a difference of gaps: 0)
  size_t n_b = 0;  ///< size of the second sample (count; for a difference of gaps: 0)
  double mean_a = std::numeric_limits<double>::quiet_NaN();  ///< mean of the first sample (data units)
  double mean_b = std::numeric_limits<double>::quiet_NaN();  ///< mean of the second sample (data units)
  double gap = std::numeric_limits<double>::quiet_NaN();     ///< mean_a - mean_b (data units)
  double se = std::numeric_limits<double>::quiet_NaN();      ///< standard error of the gap (data units)
  double df = std::numeric_limits<double>::quiet_NaN();      ///< degrees of freedom
  double low = std::numeric_limits<double>::quiet_NaN();     ///< lower bound of the interval (data units)
  double high = std::numeric_limits<double>::quiet_NaN();    ///< upper bound (data units)
  double p = std::numeric_limits<double>::quiet_NaN();       ///< two-sided p of gap = 0
  double level = 0.95;                                       ///< the interval's confidence level
  /// The interval exists and holds `value`.
  bool covers(double value) const { return low <= value && value <= high; }
};

/// mean(a) - mean(b) with Student's pooled-variance interval (0 < level < 1).
MeanGap student_gap(const std::vector<double>& a, const std::vector<double>& b, double level = 0.95);

/// x.gap - y.gap for gaps of independent samples, with a Welch-Satterthwaite interval.
MeanGap gap_difference(const MeanGap& x, const MeanGap& y, double level = 0.95);

}  // namespace robozoo
