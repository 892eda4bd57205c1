#pragma once
// Holm's step-down correction for a family of m tests (Holm 1979). With the
// p-values sorted, p_(1) <= ... <= p_(m), the adjusted values are
//   q_(i) = min(1, max_{j <= i} (m - j + 1) p_(j)),
// and the hypotheses with q < alpha are rejected: the family-wise error rate
// stays at most alpha under any dependence between the tests. NaN p-values
// (no test) are not members of the family: they stay NaN and do not count in m.
#include <vector>

namespace robozoo {

/// Holm-adjusted p-values, in the order of `p`.
std::vector<double> holm_adjust(const std::vector<double>& p);

}  // namespace robozoo
