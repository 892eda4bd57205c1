#include "evolve/neat/species/compatibility.hpp"

#include <cmath>

namespace robozoo {

double compatibility_distance(const Genome& a, const Genome& b, const NeatParams& p) {
  // Links are sorted by innovation (validate_genome's invariant): one merge pass.
  const auto& la = a.links;
  const auto& lb = b.links;
  size_t i = 0, j = 0;
  int disjoint = 0, excess = 0, matching = 0;
  double weight_diff = 0.0;
  while (i < la.size() && j < lb.size()) {
    if (la[i].innovation == lb[j].innovation) {
      weight_diff += std::fabs(la[i].weight - lb[j].weight);
      ++matching;
      ++i;
      ++j;
    } else if (la[i].innovation < lb[j].innovation) {
      ++disjoint;
      ++i;
    } else {
      ++disjoint;
      ++j;
    }
  }
  if (p.compatibility == CompatibilityRule::HyperNeat) {
    // HyperNEAT counts the difference in gene counts as excess, whatever the innovations.
    excess = static_cast<int>(la.size() > lb.size() ? la.size() - lb.size() : lb.size() - la.size());
  } else {
    // What is left of one genome lies beyond the other's last innovation.
    excess = static_cast<int>((la.size() - i) + (lb.size() - j));
  }
  const double n = 1.0;  // N = 1 (HyperNEAT): no normalisation by genome size
  const double wbar = matching > 0 ? weight_diff / matching : 0.0;
  return p.disjoint_coefficient * disjoint / n + p.excess_coefficient * excess / n + p.weight_coefficient * wbar;
}

}  // namespace robozoo
