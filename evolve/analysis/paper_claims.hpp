#pragma once
// What Auerbach & Bongard report for each statistic robozoo compares (paper
// sections 3 and 4, Figures 1-3), so the report can put robozoo's figure
// beside each claim.
#include <string>
#include <vector>

namespace robozoo {

enum class ClaimGroup { Fitness, Morphology, Genotype, Champion };

struct PaperClaim {
  ClaimGroup group;        ///< which list of comparisons holds the statistic
  std::string key;         ///< Comparison::key
  std::string paper;       ///< the paper's words or figures
  /// +1: the paper finds the experimental (recurrent) regime higher, -1 lower,
  /// 0: no (significant) difference, 2: the paper gives no direction.
  int direction = 2;
  bool significant = false;  ///< the paper reports p < 0.05
};

/// The paper's claims, in the order of the report.
const std::vector<PaperClaim>& paper_claims();

}  // namespace robozoo
