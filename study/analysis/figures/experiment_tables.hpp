#pragma once
// The experiment's CSV tables, built from its analysis.
#include <array>
#include "study/analysis/report/claim_verdicts.hpp"
#include "study/analysis/figures/csv_writer.hpp"
#include "study/analysis/compare/experiment_analysis.hpp"

namespace robozoo {

/// generation, n, mean and standard error of the best-so-far fitness of each
/// arm, and that generation's Student's t (experimental against control; Figure 1).
CsvWriter fitness_curve_table(const ExperimentAnalysis& a);
/// One row per comparison: what the samples are (runs, pooled events), both
/// samples (n, mean, sd, se), Student's and Welch's t, df, p (experimental
/// against control), Cohen's d, Hedges' g and d's 95 % CI, stars, and for
/// censored counts the best-of-run robots of each arm at max_spheres.
/// Columns named after the arms (`control` and `experimental` as arm_column prefixes).
CsvWriter comparison_table(const std::vector<Comparison>& list, const std::string& control = "feedforward",
                           const std::string& experimental = "recurrent");
/// One row per compared statistic: its role (primary, secondary, by
/// construction, descriptive), the paper's claim, Student's and Holm's p, the
/// paper's effect and the power at it, direction and verdict.
CsvWriter claims_table(const ClaimsAssessment& claims);
/// Per generation, the mean share of each outcome over the runs of each arm
/// (the runs that reached that generation): arm, generation, runs, then one
/// column per outcome (generation_t's order).
CsvWriter outcome_shares_table(const ExperimentAnalysis& a);
/// Per generation, the mean share of each outcome over `runs`.
std::vector<std::array<double, 6>> mean_outcome_shares(const std::vector<RunAnalysis>& runs);
/// One row per run: identity, sizes, best-of-run fitness, morphology and genotype statistics, champion changes.
CsvWriter runs_table(const ExperimentAnalysis& a);
/// One row per new champion of every run (section 4's raw data).
CsvWriter champion_change_table(const ExperimentAnalysis& a);

}  // namespace robozoo
