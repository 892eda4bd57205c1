#pragma once
// The sensitivity study: one factor at a time changed from a reference
// configuration (M3's), each factor run for both arms on some of the
// reference's seeds, and for each factor the gap between the arms' best-so-far
// fitness at one generation set beside the reference's own gap on the same
// seeds at the same generation (docs/experiment.md, the pre-registration).
//
// Per factor:
//   gap            control mean - experimental mean (feed-forward minus recurrent),
//                  Student's pooled interval and p (mean_gap.hpp);
//   reference_gap  the same of the reference's runs with the factor's seeds, read
//                  at the same generation (the reference, not a member of the family);
//   difference     gap - reference_gap, Welch-Satterthwaite interval (descriptive,
//                  not tested: the two share seeds, so they are not independent);
//   holm_p         Student's p under Holm's correction across the factors;
//   outcomes       per arm, the generation's evaluations by outcome, pooled over runs.
// Every run is checked first: its arm is one of the two, its seed is run once per
// arm, the reference holds the same seed and software version, it reached the
// generation, and its configuration differs from the reference run's in the same
// keys as every other run of the factor, and in at least one (config_difference;
// the generations asked for do not count).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "study/analysis/compare/mean_gap.hpp"
#include "evolve/record/run_summary.hpp"
#include "study/analysis/sensitivity/config_difference.hpp"

namespace robozoo {

struct SensitivityParams {
  int32_t generation = 0;  ///< generations run when read (count): record generation - 1 (0-based)
  double alpha = 0.05;     ///< significance level of Holm's family
  double level = 0.95;     ///< confidence level of every interval
  std::string control_arm = "feedforward";
  std::string experimental_arm = "recurrent";
};

struct SensitivityFactor {
  std::string name;              ///< e.g. "bias-1.0" (its folder)
  std::vector<RunSummary> runs;  ///< both arms, any order
};

/// One arm's evaluations in one generation by outcome (counts pooled over runs), in the
/// order of GenerationRecord::outcomes.
struct ArmOutcomes {
  size_t runs = 0;                  ///< runs pooled (count)
  std::array<int64_t, 6> counts{};  ///< evaluations per outcome (count)
  int64_t total() const;            ///< evaluations (count)
  int64_t simulated() const;        ///< completed or stopped early (count)
};

struct FactorResult {
  std::string name;
  std::vector<ConfigChange> changes;   ///< the factor's configuration against the reference's
  std::vector<int64_t> control_seeds;  ///< sorted
  std::vector<int64_t> experimental_seeds;
  MeanGap gap;            ///< control - experimental, best-so-far fitness at the generation
  MeanGap reference_gap;  ///< the same of the reference on these seeds
  MeanGap difference;     ///< gap - reference_gap
  double holm_p = std::numeric_limits<double>::quiet_NaN();  ///< Holm-adjusted p of gap = 0
  bool significant = false;                                  ///< holm_p < alpha
  std::string reading;                                       ///< the verdict in words
  ArmOutcomes control_outcomes, experimental_outcomes;
  ArmOutcomes reference_control_outcomes, reference_experimental_outcomes;
};

struct SensitivityAnalysis {
  SensitivityParams params;
  std::string software_version;       ///< the reference's (every run's)
  std::vector<FactorResult> factors;  ///< in the order given
};

/// Throws std::invalid_argument naming the run and what is wrong (see above).
SensitivityAnalysis analyze_sensitivity(const std::vector<RunSummary>& reference,
                                        const std::vector<SensitivityFactor>& factors, const SensitivityParams& params);

/// The factors with fewer runs in an arm than the most any factor has there (a factor still
/// running, or trials missing), each in words: "cap-100 (6 feedforward and 6 recurrent runs,
/// against 10 and 10)". Empty when every factor has as many runs as the others.
std::vector<std::string> factors_with_fewer_runs(const SensitivityAnalysis& a);

}  // namespace robozoo
