#include "study/analysis/compare/holm.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace robozoo {

std::vector<double> holm_adjust(const std::vector<double>& p) {
  std::vector<double> q(p.size(), std::nan(""));
  std::vector<size_t> order;
  for (size_t i = 0; i < p.size(); ++i)
    if (!std::isnan(p[i])) order.push_back(i);
  // Stable: equal p-values keep their order, so the result does not depend on the sort.
  std::stable_sort(order.begin(), order.end(), [&p](size_t a, size_t b) { return p[a] < p[b]; });
  const size_t m = order.size();
  double running = 0;
  for (size_t j = 0; j < m; ++j) {
    running = std::max(running, std::min(1.0, static_cast<double>(m - j) * p[order[j]]));
    q[order[j]] = running;
  }
  return q;
}

}  // namespace robozoo
