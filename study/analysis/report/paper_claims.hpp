#pragma once
// What Auerbach & Bongard report for each statistic robozoo compares (paper
// sections 3 and 4, Figures 1-3), feed-forward (control) against recurrent
// (experimental) CPPNs, so the report can put robozoo's figure beside each
// claim. A statistic without an entry is one the paper is silent on.
#include <string>
#include <vector>

namespace robozoo {

struct PaperClaim {
  std::string key;    ///< Comparison::key
  std::string paper;  ///< the paper's words or figures
  /// +1: the paper finds the recurrent regime higher, -1 lower,
  /// 0: no significant difference.
  int direction = 0;
  bool significant = false;  ///< the paper reports the difference as significant
  /// The p-value the paper reports (an upper bound: "p < 0.001"); for a
  /// difference called significant without a figure, 0.05. NaN: none.
  double p_bound = 0;
  /// The paper's samples are its 30 runs per regime (false: the paper's samples
  /// are pooled events of an unreported number, so no effect size follows).
  bool run_samples = true;
};

/// The paper's runs per regime.
constexpr int kPaperRunsPerRegime = 30;

/// The paper's claims, in the order of the report.
const std::vector<PaperClaim>& paper_claims();

/// The claim about statistic `key`, or nullptr when the paper is silent on it.
const PaperClaim* paper_claim(const std::string& key);

}  // namespace robozoo
