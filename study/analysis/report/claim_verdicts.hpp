#pragma once
// Each compared statistic judged against the paper, with the tests fixed before
// the data:
//   - the primary test: best-so-far fitness at the last generation, control
//     against experimental, Student's t at alpha = 0.05, as the paper;
//   - the secondary tests: every other statistic whose samples are runs, as one
//     family under Holm's correction (holm.hpp); their verdicts come from the
//     adjusted p-values;
//   - left out of the family: statistics true by construction for the compared
//     arms (e.g. a feed-forward CPPN has no recurrent link; the 209-link start
//     has more links than the 99-link one), pooled events (descriptive) and the
//     max_spheres indicator (the cap, described).
// The paper's claims (paper_claims.hpp) are about feed-forward against
// recurrent CPPNs: they apply when one arm is feedforward and the other a
// recurrent arm, oriented to the experimental-minus-control direction;
// otherwise the paper did not compare the arms. The power of each test is
// Student's at alpha (unadjusted) against the smallest effect the paper's
// reported p-value implies with 30 runs per regime (power.hpp), where the
// paper's samples are runs.
#include <string>
#include <vector>

#include "study/analysis/compare/experiment_analysis.hpp"

namespace robozoo {

enum class ClaimRole { Primary, Secondary, ByConstruction, Descriptive };

struct ClaimRow {
  Comparison comparison;
  std::string section;  ///< "Figure 1", "Figure 2", "Figure 3", "Section 4"
  ClaimRole role = ClaimRole::Secondary;
  std::string role_note;  ///< why a statistic is true by construction or descriptive
  std::string paper;      ///< the paper's words, "silent", or "not compared by the paper"
  /// The paper's finding in this comparison's direction (experimental minus
  /// control): +1 higher, -1 lower, 0 no significant difference, 2 none.
  int paper_direction = 2;
  bool paper_significant = false;
  double paper_effect = 0;  ///< |d| the paper's result implies (NaN: none)
  double power = 0;         ///< Student's t-test's power at paper_effect (NaN: none)
  double holm_p = 0;        ///< Holm-adjusted Student's p (secondary tests; NaN otherwise)
  std::string direction;    ///< "same as the paper", "opposite to the paper", "" (no direction to compare)
  std::string verdict;      ///< the row's conclusion, from the primary test or Holm's p
};

struct ClaimsAssessment {
  double alpha = 0.05;
  bool paper_compared = false;  ///< the paper compared these two arms (feed-forward against recurrent)
  std::string outcome;          ///< primary: "reproduced", "not reproduced", "inconclusive" (paper_compared), else ""
  std::string headline;         ///< one sentence for the top of the report
  int family_size = 0;          ///< secondary tests with a p-value (Holm's m)
  std::vector<ClaimRow> rows;   ///< primary, then the statistics of Figures 2, 3 and section 4
};

/// +1 when the paper's claims apply as they are (control feedforward,
/// experimental a recurrent arm), -1 when reversed, 0 when the paper did not
/// compare the two arms.
int paper_orientation(const std::string& control_arm, const std::string& experimental_arm);

/// Why statistic `key` differs between the arms by construction, or "".
std::string by_construction(const std::string& key, const std::string& control_arm,
                            const std::string& experimental_arm);

/// Judges every comparison of `a`.
ClaimsAssessment assess_claims(const ExperimentAnalysis& a, double alpha = 0.05);

}  // namespace robozoo
